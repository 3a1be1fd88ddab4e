"""Generate ``data/rclpy_signatures.txt``: the keywords rclpy's most used calls take.

Run ``python -m pkgtool.knowledge.generate_rclpy_signatures --rclpy-git DIR`` in pkgtool's
locked environment, ``DIR`` a clone of ros2/rclpy: the functions are read from its ``humble``,
``jazzy`` and ``rolling`` branches with ``git show`` and from the installed Jazzy wheel's files,
nothing checked out or imported. Each entry is ``<call> <parameter>...``, the union over the
branches (a keyword any of them takes is known); a function taking ``**kwargs`` gets ``**``.
Methods are keyed by their name (``create_timer``: lint finds them by name on any receiver
that may be a node, a client or an action client), functions and constructors by the dotted
name code imports them by (``rclpy.spin_once``, ``rclpy.action.ActionServer``).
"""

from __future__ import annotations

import ast
import subprocess
from pathlib import Path

from pkgtool.knowledge.generate_rclpy_classes import (BRANCHES, INSTALLED, source,
                                                      write_rclpy_table)

METHODS = {
    "rclpy.node.Node": ("create_publisher", "create_subscription", "create_client",
                        "create_service", "create_timer", "create_rate", "declare_parameter",
                        "declare_parameters", "get_parameter_or"),
    "rclpy.client.Client": ("call_async", "wait_for_service"),
    "rclpy.action.client.ActionClient": ("send_goal_async", "wait_for_server"),
}
"""Methods whose names no other common library uses for something else, by class."""
FUNCTIONS = {
    "rclpy.init": "rclpy.init", "rclpy.spin": "rclpy.spin", "rclpy.spin_once": "rclpy.spin_once",
    "rclpy.spin_until_future_complete": "rclpy.spin_until_future_complete",
    "rclpy.create_node": "rclpy.create_node",
    "rclpy.node.Node": "rclpy.node.Node.__init__",
    "rclpy.action.ActionServer": "rclpy.action.server.ActionServer.__init__",
    "rclpy.action.ActionClient": "rclpy.action.client.ActionClient.__init__",
    "rclpy.executors.SingleThreadedExecutor":
        "rclpy.executors.SingleThreadedExecutor.__init__",
    "rclpy.executors.MultiThreadedExecutor": "rclpy.executors.MultiThreadedExecutor.__init__",
}
"""Functions and constructors: the name code calls them by -> where they are defined."""


def _function(git: Path, branch: str, dotted: str) -> ast.FunctionDef | None:
    """The ``def`` of ``module.function`` or ``module.Class.method`` on ``branch``."""
    parts = dotted.split(".")
    for split in range(len(parts) - 1, 0, -1):
        tree = _module(git, branch, ".".join(parts[:split]))
        if tree is None:
            continue
        body: list[ast.stmt] = tree.body
        for name in parts[split:-1]:
            body = next((c.body for c in body if isinstance(c, ast.ClassDef) and c.name == name),
                        [])
        return next((f for f in body if isinstance(f, ast.FunctionDef) and
                     f.name == parts[-1]), None)
    return None


def _module(git: Path, branch: str, module: str) -> ast.Module | None:
    """The syntax tree of ``module`` (a file or a package's ``__init__``), None if absent."""
    for name in (module, f"{module}.__init__"):
        try:
            return ast.parse(source(git, branch, name))
        except (OSError, subprocess.CalledProcessError):
            continue
    return None


def _parameters(function: ast.FunctionDef) -> set[str]:
    arguments = function.args
    found = {a.arg for a in (*arguments.posonlyargs, *arguments.args, *arguments.kwonlyargs)}
    return found | ({"**"} if arguments.kwarg else set())


def table(git: Path) -> dict[str, set[str]]:
    """Call -> the union of its parameters over :data:`BRANCHES` and the installed wheel."""
    wanted = {name: f"{cls}.{name}" for cls, names in METHODS.items() for name in names}
    wanted.update(FUNCTIONS)
    found: dict[str, set[str]] = {}
    for call, where in wanted.items():
        union: set[str] = set()
        for branch in (*BRANCHES, INSTALLED):
            function = _function(git, branch, where)
            union |= _parameters(function) if function else set()
        if not union:
            raise SystemExit(f"{where} is on no branch")
        found[call] = union - {"self"}
    return found


def main() -> None:
    write_rclpy_table("rclpy_signatures", "The parameters of rclpy's most used calls.", table,
                      __doc__.splitlines()[0])


if __name__ == "__main__":
    main()
