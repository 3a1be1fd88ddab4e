"""Edits of a ROS parameter file (``config/params.yaml``): one more node's block at the end."""

from __future__ import annotations

from pkgtool.edit.core import Edit, EditError
from pkgtool.edit.source import Source


def add_block(source: Source, node: str, block: str) -> list[Edit]:
    """Append ``block`` (YAML text starting with ``node:``) unless ``node`` has a block."""
    from pkgtool.model.launch_reader import yaml_problem

    import yaml

    root = yaml_problem(source.path, source.text, documents=False)
    if root is None:
        keys: list[str] = []
    elif isinstance(root, yaml.MappingNode) and not root.flow_style:
        keys = [getattr(key, "value", None) for key, _ in root.value]
    else:
        raise EditError(f"`{source.path}` is not a block mapping of node names: add the "
                        f"parameters of `{node}` by hand.")
    if node in keys or f"/{node}" in keys:
        return []
    newline = source.newline
    text = newline.join(block.strip("\n").splitlines()) + newline
    end = len(source.text)
    lead = newline if source.text and not source.text.endswith(("\n", "\r")) else ""
    return [Edit(source.path, end, end, lead + text)]
