"""Render a :class:`Plan` into the package's files (path -> text) with the jinja2 templates.

Pure and deterministic: the same plan gives the same bytes. Nothing is written here.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from pkgtool.create.headers import header
from pkgtool.create.licenses import license_text
from pkgtool.create.pysource import import_block, py_str, py_value, yaml_value
from pkgtool.safe_xml import xml_text

if TYPE_CHECKING:
    from jinja2 import Environment

    from pkgtool.create.nodes import NodeSpec
    from pkgtool.create.options import Plan

Imports = list[tuple[str, "str | None"]]

_ACTION_IMPORTS: dict[str, Imports] = {
    "action-server": [("rclpy.action", "ActionServer"), ("rclpy.action", "CancelResponse"),
                      ("rclpy.callback_groups", "ReentrantCallbackGroup"), ("time", None)],
    "action-client": [("rclpy.action", "ActionClient")]}
# The test of a node uses the other end of the node's action.
_ACTION_TEST_IMPORTS = {"action-server": ("rclpy.action", "ActionClient"),
                        "action-client": ("rclpy.action", "ActionServer")}
_TESTS_WITH_OVERRIDES = frozenset({"publisher", "timer", "client", "action-server"})
_CONFTEST: Imports = [("os", None), ("threading", None), ("time", None), ("pytest", None),
                      ("rclpy", None), ("rclpy.context", "Context"),
                      ("rclpy.executors", "MultiThreadedExecutor"),
                      ("rclpy.executors", "SingleThreadedExecutor")]
_LINTER_TESTS: dict[str, Imports] = {
    name: [("pathlib", "Path"), ("pytest", None)]
    for name in ("test_copyright", "test_flake8", "test_pep257")
}


def environment() -> Environment:
    """The jinja2 environment over ``templates/`` (strict: an unknown variable is an error).

    Compiled templates are cached in jinja2's per-user temporary folder (keyed by each
    template's checksum): compiling them all takes longer than the rest of ``create``.
    """
    from jinja2 import Environment, FileSystemBytecodeCache, FileSystemLoader, StrictUndefined

    from pkgtool.resources import resource_dir

    try:
        cache: FileSystemBytecodeCache | None = FileSystemBytecodeCache()
    except (OSError, RuntimeError):  # no usable temporary folder: compile every time
        cache = None
    env = Environment(loader=FileSystemLoader(str(resource_dir("templates"))),
                      undefined=StrictUndefined, autoescape=False, keep_trailing_newline=True,
                      trim_blocks=True, lstrip_blocks=True, bytecode_cache=cache)
    env.filters.update(py_str=py_str, py_value=py_value, yaml_value=yaml_value, xml=xml_text)
    return env


def node_imports(node: NodeSpec) -> Imports:
    """What the module of ``node`` imports."""
    found: Imports = [("signal", None), ("rclpy", None),
                      ("rclpy.executors", "ExternalShutdownException"),
                      ("rclpy.executors", node.executor), ("rclpy.node", "Node")]
    if node.interface:
        found.append((node.interface.module, node.interface.name))
    return found + _ACTION_IMPORTS.get(node.kind.name, [])


def test_imports(package: str, node: NodeSpec) -> Imports:
    """What the test of ``node`` imports."""
    found: Imports = [(f"{package}.{node.name}", node.class_name)]
    if node.interface:
        found.append((node.interface.module, node.interface.name))
    if node.kind.name in _TESTS_WITH_OVERRIDES:
        found.append(("rclpy.parameter", "Parameter"))
    if node.kind.name in _ACTION_TEST_IMPORTS:
        found += [_ACTION_TEST_IMPORTS[node.kind.name], ("action_msgs.msg", "GoalStatus")]
    return found


def _launch_imports(plan: Plan) -> Imports:
    found: Imports = [("launch", "LaunchDescription"), ("launch_ros.actions", "Node")]
    if plan.config:
        found += [("launch.substitutions", "PathJoinSubstitution"),
                  ("launch_ros.substitutions", "FindPackageShare")]
    return found


def _init_docstring(plan: Plan) -> str:
    if not plan.nodes:
        return f"The {plan.name} package."
    names = ", ".join(node.name for node in plan.nodes)
    text = f"The {plan.name} package: nodes {names}."
    return text if len(text) <= 90 else f"The {plan.name} package and its nodes."


def _renderer(plan: Plan, env: Environment, files: dict[str, str]) -> Callable[..., None]:
    """``put(path, template, **context)``: render a template of ``plan`` into ``files``."""
    head = header(year=plan.year, holder=plan.maintainer_name, license_=plan.license,
                  expression=plan.license_expression, spdx_line=plan.spdx_header)

    def put(path: str, template: str, **context: object) -> None:
        text = env.get_template(template).render(plan=plan, header=head, **context)
        files[path] = text.rstrip("\n") + "\n"

    return put


def node_files(plan: Plan, env: Environment | None = None) -> dict[str, str]:
    """The module and the test of each node of ``plan``, and the tests' ``conftest.py``."""
    files: dict[str, str] = {}
    put = _renderer(plan, env or environment(), files)
    for node in plan.nodes:
        put(f"{plan.name}/{node.name}.py", node.kind.template, node=node,
            imports=import_block(node_imports(node)))
        put(f"test/test_{node.name}.py", node.kind.template.replace("nodes/", "tests/"),
            node=node, imports=import_block(test_imports(plan.name, node)))
    if plan.nodes:
        put("test/conftest.py", "tests/conftest.py.jinja", imports=import_block(_CONFTEST))
    return files


def launch_file(plan: Plan, env: Environment | None = None) -> str:
    """The launch file starting the nodes of ``plan`` (with config/params.yaml if ``config``)."""
    files: dict[str, str] = {}
    _renderer(plan, env or environment(), files)("launch", "launch.py.jinja",
                                                 imports=import_block(_launch_imports(plan)))
    return files["launch"]


def params_file(plan: Plan, env: Environment | None = None) -> str:
    """config/params.yaml with the parameters of the nodes of ``plan``."""
    files: dict[str, str] = {}
    _renderer(plan, env or environment(), files)("params", "params.yaml.jinja")
    return files["params"]


def render(plan: Plan, env: Environment | None = None) -> dict[str, str]:
    """Every file of the package, by POSIX path relative to the package folder."""
    env = env or environment()
    files: dict[str, str] = {}
    put = _renderer(plan, env, files)
    put("package.xml", "package.xml.jinja")
    put("setup.py", "setup.py.jinja")
    put("setup.cfg", "setup.cfg.jinja")
    files[f"resource/{plan.name}"] = ""
    if plan.license_shipped:
        files["LICENSE"] = license_text(plan.license, year=plan.year,
                                        holder=plan.maintainer_name)
    put(f"{plan.name}/__init__.py", "__init__.py.jinja", docstring=_init_docstring(plan))
    if plan.library_name:
        put(f"{plan.name}/{plan.library_name}/__init__.py", "__init__.py.jinja",
            docstring=f"The {plan.library_name} library of the {plan.name} package.")
    files.update(node_files(plan, env))
    for name, imports in _LINTER_TESTS.items():
        put(f"test/{name}.py", f"tests/{name}.py.jinja", imports=import_block(imports))
    if plan.launch:
        files[f"launch/{plan.name}.launch.py"] = launch_file(plan, env)
    if plan.config:
        files["config/params.yaml"] = params_file(plan, env)
    return dict(sorted(files.items()))
