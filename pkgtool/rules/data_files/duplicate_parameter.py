"""DAT013: a parameter given twice in the same block of a ROS parameter file."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.launch_reader import yaml_problem
from pkgtool.model.package import Package, is_test_yaml
from pkgtool.rules.node_parameters import span_of
from pkgtool.rules.registry import rule

PARAMS_KEY = "ros__parameters"


def _mapping(node: object) -> bool:
    return getattr(node, "id", None) == "mapping"


def _key(node: object) -> str | None:
    return str(getattr(node, "value")) if getattr(node, "id", None) == "scalar" else None


def _parameter_blocks(node: object, seen: set[int], above: str = ""
                      ) -> Iterator[tuple[str, object]]:
    """The mappings held by a ``ros__parameters`` key anywhere under ``node`` (each once),
    each with the node key above it (namespaces joined with ``/``)."""
    if not _mapping(node) or id(node) in seen:
        return
    seen.add(id(node))
    for key, value in getattr(node, "value"):
        if _key(key) == PARAMS_KEY and _mapping(value):
            yield above, value
        else:
            yield from _parameter_blocks(value, seen, f"{above}/{_key(key)}")


def _repeated(path: str, node: str, block: object, prefix: str, first: dict[str, object]
              ) -> Iterator[Hit]:
    """A hit for each parameter of ``block`` (a mapping; groups flattened to ``group.name``
    as rcl names them) that ``first`` or ``block`` already gave a value."""
    for key, value in getattr(block, "value"):
        name = _key(key)
        if name is None or name == "<<":
            continue
        if _mapping(value):  # a group: rcl merges a group written twice
            yield from _repeated(path, node, value, f"{prefix}{name}.", first)
        elif f"{prefix}{name}" in first:
            earlier = span_of(path, first[f"{prefix}{name}"])
            yield Hit(span_of(path, key), f"`{prefix}{name}` is given twice for the node "
                      f"`{node}` (first on line {earlier.line}): ROS keeps only the last value",
                      related=(earlier,))
        else:
            first[f"{prefix}{name}"] = key


@rule("DAT013", "duplicate-parameter", Severity.WARNING,
      fix="Keep one entry for the parameter, with the value meant")
def duplicate_parameter(package: Package) -> Iterator[Hit]:
    """A parameter file gives the same parameter twice in one `ros__parameters` block.

    ## What it does
    In the package's YAML files (not under `test/`), reports a parameter given a value twice
    under one `ros__parameters`, at the second occurrence, with groups named as rcl names
    them (`pid.p` in `pid: {p: ..., p: ...}`). A group written twice (`axis_linear: {x: 1}`
    then `axis_linear: {y: 0}`) is one group to rcl's parser, which merges it: only a
    parameter repeated inside counts. A node block written twice in one file is merged by rcl
    too: a parameter both give counts. Merge keys (`<<:`) are left alone.

    ## Why is this bad?
    YAML gives a key one value: ROS and every YAML loader keep the last one and drop the
    other without a word. Usually one of the two was meant to be another parameter (copied
    and not renamed), or an old value was left in: the node runs with a value nobody chose.

    ## Example
    ```yaml
    controller:
      ros__parameters:
        max_speed: 0.5
        max_speed: 2.0
    ```

    ## Use instead
    ```yaml
    controller:
      ros__parameters:
        max_speed: 0.5
        max_turn_rate: 2.0
    ```
    """
    for path, text in sorted(package.texts.items()):
        if not path.endswith((".yaml", ".yml")) or is_test_yaml(path) or \
                PARAMS_KEY not in text:
            continue
        documents = yaml_problem(path, text)
        if not isinstance(documents, list):
            continue  # SYN001
        seen: set[int] = set()
        given: dict[str, dict[str, object]] = {}  # by node key: rcl merges a node written twice
        for root in documents:
            for node, block in _parameter_blocks(root, seen):
                yield from _repeated(path, node.strip("/") or "/", block, "",
                                     given.setdefault(node, {}))
