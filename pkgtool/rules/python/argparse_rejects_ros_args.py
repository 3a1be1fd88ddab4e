"""PYC095: a node started by a launch file parses the whole command line with argparse."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.call_graph import module_functions_reached
from pkgtool.rules.console_scripts import scripts_and_modules
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees

_PARSERS = frozenset({"argparse.ArgumentParser"})
_NODE_ACTIONS = frozenset({"Node", "LifecycleNode", "node", "lifecycle_node"})
"""The launch actions that end a node's command line with ``--ros-args``."""
_TOLERANT = ("remove_ros_args", "sys.argv", "REMAINDER", "'...'", '"..."', "--ros-args")
"""Text of a module that may let its parser through ROS's arguments: they are taken out, the
command line is given by hand, or the parser keeps what it does not know."""


@rule("PYC095", "argparse-rejects-ros-args", Severity.ERROR,
      fix="Parse the arguments without ROS's: "
          "`parser.parse_args(rclpy.utilities.remove_ros_args(sys.argv)[1:])`")
def argparse_rejects_ros_args(package: Package) -> Iterator[Hit]:
    """A node a launch file starts parses its command line with `argparse`'s
    `parse_args()`, which rejects the `--ros-args` launch puts on it.

    ## What it does
    For each executable of this package a launch file starts as a node (`Node(...)`,
    `<node>`), follows its console script's function and the module functions it calls, and
    reports `parser.parse_args()` given no argument list (it reads `sys.argv`) on an
    `argparse.ArgumentParser`, outside a `try` catching `SystemExit`. Packages with a module
    that mentions `remove_ros_args`, `sys.argv`, `argparse.REMAINDER` or `--ros-args` are
    left alone (they may take ROS's arguments out or accept them), and so is
    `parse_known_args()`, which keeps what it does not know, and a node started with
    `ros2 run` by an `ExecuteProcess` (only the `Node` action adds `--ros-args`).

    ## Why is this bad?
    launch_ros always ends a node's command line with `--ros-args` (and the node's name,
    parameters and remappings after it). `parse_args()` then exits with "unrecognized
    arguments: --ros-args" before the node starts; `ros2 run` without arguments works,
    so the mistake shows only once the node is launched.

    ## Example
    ```python
    def main():
        parser = argparse.ArgumentParser()
        parser.add_argument('--port', default='/dev/ttyUSB0')
        options = parser.parse_args()
        rclpy.init()
    ```

    ## Use instead
    ```python
    def main():
        parser = argparse.ArgumentParser()
        parser.add_argument('--port', default='/dev/ttyUSB0')
        options = parser.parse_args(remove_ros_args(sys.argv)[1:])
        rclpy.init()
    ```
    """
    launched = _launched(package)
    if not launched:
        return
    entries, modules = scripts_and_modules(package)
    trees = {module.path: (tree, index) for module, tree, index in installed_trees(package)}
    if any(word in (package.texts.get(path) or "") for path in trees for word in _TOLERANT):
        return  # a module of the package may take ROS's arguments out of sys.argv
    done: set[int] = set()
    for entry in entries:
        path = modules.get(entry.module)
        found = trees.get(path or "")
        if entry.name not in launched or found is None or entry.attr is None:
            continue
        tree, index = found
        for function in module_functions_reached(tree, entry.attr.split(".")[0]):
            for call in _argv_parses(function, index):
                if id(call) not in done:
                    done.add(id(call))
                    yield Hit(Span(str(path), call.lineno, call.col_offset + 1),
                              f"`{ast.unparse(call)}` reads the command line, which "
                              f"`{launched[entry.name]}` ends with `--ros-args` when it starts "
                              f"`{entry.name}`: argparse exits with \"unrecognized arguments: "
                              f"--ros-args\" before the node starts")


def _launched(package: Package) -> dict[str, str]:
    """The executables of this package launch files start as nodes, with the first file."""
    found: dict[str, str] = {}
    for launch in package.launch_files:
        for node in launch.nodes:
            if node.package == package.name and node.executable and not node.unused and \
                    node.action in _NODE_ACTIONS:  # not `ros2 run` in an ExecuteProcess
                found.setdefault(node.executable, launch.path)
    return found


def _argv_parses(function: ast.AST, index: Index) -> Iterator[ast.Call]:
    """``x.parse_args()`` calls with no argument list in ``function``, on a name bound to an
    ``argparse.ArgumentParser(...)`` there (or on such a call itself)."""
    parsers = {t.id for n in ast.walk(function) if isinstance(n, ast.Assign) and
               _makes_parser(n.value, index) for t in n.targets if isinstance(t, ast.Name)}
    for call in ast.walk(function):
        if not (isinstance(call, ast.Call) and isinstance(call.func, ast.Attribute) and
                call.func.attr == "parse_args" and not call.args and
                not any(k.arg in ("args", None) for k in call.keywords)):
            continue
        receiver = call.func.value
        if (isinstance(receiver, ast.Name) and receiver.id in parsers or
                _makes_parser(receiver, index)) and not _exit_caught(call, index):
            yield call


def _exit_caught(call: ast.Call, index: Index) -> bool:
    """True when a ``try`` around ``call`` catches ``SystemExit`` (or everything)."""
    child, parent = call, index.parents.get(id(call))
    while parent is not None:
        if isinstance(parent, ast.Try) and any(child is s for s in parent.body) and any(
                h.type is None or any(isinstance(n, ast.Name) and n.id in (
                    "SystemExit", "BaseException") for n in ast.walk(h.type))
                for h in parent.handlers):
            return True
        child, parent = parent, index.parents.get(id(parent))
    return False


def _makes_parser(value: ast.expr, index: Index) -> bool:
    return isinstance(value, ast.Call) and index.qualified(value.func) in _PARSERS
