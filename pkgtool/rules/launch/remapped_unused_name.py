"""LCH014: a launch file remaps a name the node never uses, a typo away from one it does."""

from __future__ import annotations

import ast
from collections.abc import Iterator
from difflib import get_close_matches

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.memo import per_tree
from pkgtool.model.package import Package
from pkgtool.rules.endpoints import endpoints
from pkgtool.rules.node_parameters import node_class
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import installed_trees


def _bare(name: str) -> str:
    """A topic name without its leading ``/`` or ``~/``."""
    return name.lstrip("/").removeprefix("~/")


@per_tree
def _texts(tree: ast.Module) -> frozenset[str]:
    """Every string literal of a module, :func:`_bare`."""
    return frozenset(_bare(n.value) for n in nodes_of_class(tree, ast.Constant)
                     if isinstance(n, ast.Constant) and isinstance(n.value, str))


@rule("LCH014", "remapped-unused-name", Severity.WARNING,
      fix="Remap the name the node uses (see the message)")
def remapped_unused_name(package: Package) -> Iterator[Hit]:
    """A launch file remaps a topic name the node never uses, spelled like one it does.

    ## What it does
    For a Python launch file's `Node()` of this package with `remappings=[(from, to), ...]`,
    finds the node class its executable runs (as DAT010 does) and reports a literal `from`
    name that appears in no string of that class's module but is a typo away from a topic
    the node publishes or subscribes to (`('cmd_vell', 'turtle1/cmd_vel')` for a node on
    `cmd_vel`). Node, namespace and other special remappings (`__node`, `__ns`) are not
    looked at.

    ## Why is this bad?
    A remapping of a name the node does not use changes nothing and raises no error: the
    node keeps talking on its own topic, and nothing on the intended topic ever hears it.

    ## Example
    ```python
    Node(package='my_robot', executable='talker', remappings=[('cmd_vell', 'turtle1/cmd_vel')])
    ```

    ## Use instead
    ```python
    Node(package='my_robot', executable='talker', remappings=[('cmd_vel', 'turtle1/cmd_vel')])
    ```
    """
    trees = {module.path: tree for module, tree, _ in installed_trees(package)}
    for launch in package.launch_files:
        for node in launch.nodes:
            cls = node_class(package, node) if node.remapped and not node.unused else None
            tree = trees.get(cls.path) if cls is not None else None
            if cls is None or tree is None:
                continue
            topics = sorted({_bare(e.topic) for e in endpoints(package)
                             if e.topic_span.path == cls.path})
            for name, span in node.remapped:
                if name.startswith("__") or _bare(name) in _texts(tree):
                    continue
                close = get_close_matches(_bare(name), topics, n=1, cutoff=0.8)
                if close:
                    yield Hit(span, f"`{name}` is remapped, but `{node.executable}` uses no such "
                                    f"name: did you mean `{close[0]}`? The remapping changes "
                                    "nothing", f"Write `{close[0]}`")
