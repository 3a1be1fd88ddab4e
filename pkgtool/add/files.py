"""``pkgtool add launch`` and ``pkgtool add config``: a launch file or a parameter file for the
package's nodes, installed through data_files."""

from __future__ import annotations

import ast

from pkgtool.add.depends import declare
from pkgtool.add.node import LAUNCH_DEPENDS
from pkgtool.add.target import Target
from pkgtool.create.nodes import Kind, NodeSpec
from pkgtool.edit.core import EditError
from pkgtool.lazy_regex import lazy_pattern

_ROS_NAME = lazy_pattern(r"^[A-Za-z_][A-Za-z0-9_]*$")
_LAUNCH_NAME = lazy_pattern(r"^[A-Za-z0-9_.-]+[._]launch\.py$")
_SCALARS = (str, int, float, bool)


def add_launch(target: Target, *, name: str | None = None, year: int | None = None) -> str:
    """Write ``launch/<name>`` starting every console script; install it; return its path."""
    from pkgtool.create.render import launch_file

    name = name or f"{target.name}.launch.py"
    if not _LAUNCH_NAME.match(name):
        raise EditError(f"Launch file name `{name}` does not end in `.launch.py` or "
                        "`_launch.py`, which ros2 launch and pkgtool expect: rename it.")
    path = f"launch/{name}"
    nodes = tuple(_spec(script) for script, _ in target.setup().console_scripts()
                  if _ROS_NAME.match(script))
    config = target.exists("config/params.yaml")
    plan = target.plan(year=year, nodes=nodes, launch=True, config=config)
    target.create(path, launch_file(plan))
    pattern = "launch/*.launch.py" if name.endswith(".launch.py") else path
    _install(target, "launch", pattern)
    declare(target, exec_only=LAUNCH_DEPENDS["py"])
    return path


def add_config(target: Target, *, year: int | None = None) -> str:
    """Write config/params.yaml with the parameters the nodes declare; install it."""
    from pkgtool.create.render import params_file

    path = "config/params.yaml"
    nodes = tuple(_spec(script, node_parameters(target, script))
                  for script, _ in target.setup().console_scripts() if _ROS_NAME.match(script))
    plan = target.plan(year=year, nodes=tuple(n for n in nodes if n.parameters), config=True)
    target.create(path, params_file(plan))
    _install(target, "config", "config/*.yaml")
    launches = [launch.path for launch in target.package.launch_files]
    if launches and not any("params.yaml" in (target.source_text(p) or "") for p in launches):
        target.notes.append(f"Pass config/params.yaml to the nodes in {launches[0]} "
                            "(`parameters=[...]`): pkgtool does not change existing nodes.")
    return path


def _install(target: Target, folder: str, pattern: str) -> None:
    target.session.apply(target.setup().add_data_files(folder, pattern, target.name))


def _spec(script: str, parameters: tuple[tuple[str, object], ...] = ()) -> NodeSpec:
    return NodeSpec(script, Kind("timer", None, "", parameters), None)


def params_block(target: Target, node: str, parameters: tuple[tuple[str, object], ...]) -> str:
    """The YAML block of ``node`` in config/params.yaml (empty without parameters)."""
    from pkgtool.create.render import params_file

    if not parameters:
        return ""
    text = params_file(target.plan(nodes=(_spec(node, parameters),), config=True))
    return "".join(line for line in text.splitlines(keepends=True) if not line.startswith("#"))


def node_parameters(target: Target, script: str) -> tuple[tuple[str, object], ...]:
    """``declare_parameter('name', literal)`` calls in the module a console script runs."""
    modules = dict(target.setup().console_scripts())
    module = modules.get(script)
    text = target.source_text(module.replace(".", "/") + ".py") if module else None
    if text is None:
        return ()
    try:
        tree = ast.parse(text)
    except SyntaxError:
        return ()
    found: dict[str, object] = {}
    for node in ast.walk(tree):
        if not (isinstance(node, ast.Call) and len(node.args) >= 2
                and getattr(node.func, "attr", "") == "declare_parameter"):
            continue
        if all(isinstance(a, ast.Constant) for a in node.args[:2]):
            key, value = node.args[0].value, node.args[1].value  # type: ignore[attr-defined]
            if isinstance(key, str) and isinstance(value, _SCALARS):
                found.setdefault(key, value)
    return tuple(found.items())
