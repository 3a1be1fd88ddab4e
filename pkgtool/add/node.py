"""``pkgtool add node``: the module and its test, the console script, dependencies, launch."""

from __future__ import annotations

import ast

from pkgtool.add.depends import declare
from pkgtool.add.target import Target
from pkgtool.create.nodes import NodeSpec
from pkgtool.edit.core import EditError

LAUNCH_DEPENDS = {"py": ("launch", "launch_ros"), "xml": ("launch_ros", "launch_xml"),
                  "yaml": ("launch_ros", "launch_yaml"), "yml": ("launch_ros", "launch_yaml")}
"""What ``ros2 launch`` needs to run a launch file of each kind that starts a node."""


def parse_spec(text: str) -> NodeSpec:
    """``NAME:KIND[:TYPE]`` checked like ``pkgtool create --node``."""
    from pkgtool.create import CreateError
    from pkgtool.create.nodes import parse_node
    from pkgtool.create.options import check_node_name

    try:
        spec = parse_node(text)
        check_node_name(spec.name)
    except CreateError as error:
        raise EditError(str(error).replace("--node ", "")) from None
    return spec


def add_node(target: Target, spec: NodeSpec, *, year: int | None = None,
             launch_file: str | None = None) -> None:
    """Write the node's module and test (if missing), then register the node everywhere."""
    from pkgtool.create.render import node_files

    folder = target.name
    if not target.exists(f"{folder}/__init__.py"):
        raise EditError(f"`{folder}/__init__.py` is missing: pkgtool puts nodes into the Python "
                        f"package named like the ROS package. Create `{folder}/` first.")
    files = node_files(target.plan(year=year, nodes=(spec,)))
    conftest = files.pop("test/conftest.py")
    _check_conftest(target)
    for path, text in files.items():
        target.create(path, text)
    if not target.exists("test/conftest.py"):
        target.create("test/conftest.py", conftest)
    register(target, spec, launch_file=launch_file)


def register(target: Target, spec: NodeSpec, *, launch_file: str | None = None) -> None:
    """Console script, run-time and test dependencies, and the launch file's node."""
    from pkgtool.create.options import node_dependencies

    target.session.apply(target.setup().add_console_script(
        spec.name, f"{target.name}.{spec.name}:main"))
    ros, tests = node_dependencies((spec,))
    declare(target, ros=ros, tests=tests)
    chosen = launch_file or pick_launch_file(target)
    if chosen:
        add_to_launch(target, chosen, spec.name)


def pick_launch_file(target: Target) -> str | None:
    """The package's launch file: the only one, or the one named after the package."""
    paths = sorted({launch.path for launch in target.package.launch_files
                    if not launch.path.startswith("test/")})
    if len(paths) <= 1:
        return paths[0] if paths else None
    for path in paths:
        name = path.rsplit("/", 1)[-1]
        if name.startswith((f"{target.name}.launch.", f"{target.name}_launch.")):
            return path
    target.notes.append(f"Not added to a launch file: the package has {len(paths)} "
                        "(give one with --launch-file).")
    return None


def add_to_launch(target: Target, path: str, executable: str) -> None:
    """Start ``executable`` from the launch file at ``path``; declare what launching needs."""
    from pkgtool.edit import launch

    source = target.session.source(path)
    if source is None:
        raise EditError(f"The launch file `{path}` does not exist.")
    target.session.apply(launch.add_node(source, target.name, executable))
    kind = path.rsplit(".", 1)[-1]
    declare(target, exec_only=LAUNCH_DEPENDS.get(kind, ()))
    _add_parameters(target, path, executable)


def _add_parameters(target: Target, launch_path: str, executable: str) -> None:
    """Give the node a block in config/params.yaml when the launch file passes that file."""
    from pkgtool.add.files import node_parameters, params_block
    from pkgtool.edit.params import add_block

    text = target.source_text(launch_path) or ""
    params = target.session.source("config/params.yaml")
    if params is None or "params.yaml" not in text:
        return
    block = params_block(target, executable, node_parameters(target, executable))
    if block:
        target.session.apply(add_block(params, executable, block))


def _check_conftest(target: Target) -> None:
    """The generated test needs conftest.py's ``ros`` fixture; a foreign conftest lacks it."""
    text = target.source_text("test/conftest.py")
    if text is None:
        return
    try:
        tree = ast.parse(text)
    except SyntaxError:
        raise EditError("test/conftest.py does not parse: fix it first.") from None
    if not any(isinstance(n, ast.FunctionDef) and n.name == "ros" for n in tree.body):
        raise EditError("test/conftest.py has no `ros` fixture, which the generated node test "
                        "uses: move that conftest.py away (pkgtool then writes its own), or "
                        "add the node with `pkgtool create` into a new package.")
