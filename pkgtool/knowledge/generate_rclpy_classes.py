"""Generate ``data/rclpy_classes.txt``: the attributes of the rclpy objects a node makes.

Run ``python -m pkgtool.knowledge.generate_rclpy_classes --rclpy-git DIR`` in pkgtool's locked
environment, ``DIR`` a clone of ros2/rclpy (a bare one will do): the classes are read from its
``humble``, ``jazzy`` and ``rolling`` branches with ``git show``, and from the installed Jazzy
wheel's files (a later release than the branch may be), nothing checked out or imported. A
class's attributes are what its body defines (methods, properties, nested classes, class-level
assignments), what its methods assign on ``self`` and, for the QoS policy enums, the deprecated
aliases their decorator adds and what ``int`` and ``Enum`` give their members; with those of
its bases found in rclpy. A class with a base outside rclpy other than ``object``, a
``Protocol``, a ``Generic``, a ``ContextManager``, an ``Enum`` or an ``IntEnum`` would be
open (anything may come from it): none of the chosen ones has one, and the generator refuses
such a class rather than write it.

Each entry is ``<class> <attribute>...``, the union over the branches (an attribute any of them
has is known). The Jazzy wheel's classes are checked against the table by the tests.
"""

from __future__ import annotations

import argparse
import ast
import importlib.metadata
import importlib.util
from collections.abc import Callable, Iterator
from pathlib import Path

from pkgtool.knowledge.generate_rclpy_names import git_text
from pkgtool.knowledge.tables import DATA, render, write

CLASSES = ("rclpy.publisher.Publisher", "rclpy.subscription.Subscription",
           "rclpy.timer.Timer", "rclpy.timer.Rate", "rclpy.client.Client",
           "rclpy.service.Service", "rclpy.clock.ROSClock",
           "rclpy.time.Time", "rclpy.duration.Duration", "rclpy.task.Future",
           "rclpy.qos.ReliabilityPolicy", "rclpy.qos.HistoryPolicy",
           "rclpy.qos.DurabilityPolicy", "rclpy.qos.LivelinessPolicy",
           "rclpy.executors.SingleThreadedExecutor", "rclpy.executors.MultiThreadedExecutor",
           "rclpy.action.client.ActionClient", "rclpy.action.client.ClientGoalHandle",
           "rclpy.parameter.Parameter",
           "rclpy.action.server.ActionServer",
           "rclpy.action.server.GoalResponse", "rclpy.action.server.CancelResponse")
"""The classes whose attributes the table holds."""
INSTALLED = "installed"
"""The rclpy wheel installed here (Jazzy's latest release: newer than the clone's branch)."""
BRANCHES = ("humble", "jazzy", "rolling")
"""The branches of ros2/rclpy read (each has every module of :data:`CLASSES`)."""
_CLOSED_BASES = frozenset({"object", "Protocol", "Generic", "IntEnum", "Enum",
                           "ContextManager"})
"""Bases from outside rclpy that add no attribute a user reads on these objects but, for
``IntEnum``, :data:`_ENUM_ATTRIBUTES` (``ContextManager``, the executors' base from Jazzy on,
adds ``__enter__`` and ``__exit__``)."""
_ENUM_ATTRIBUTES = ("name", "value", *(n for n in dir(int) if not n.startswith("_")))
"""What an ``IntEnum`` member has besides its class's own attributes."""


def source(git: Path, branch: str, module: str) -> str:
    """The text of ``module`` (``rclpy.timer``) on ``branch`` (:data:`INSTALLED`: in the
    installed wheel)."""
    path = f"{module.replace('.', '/')}.py"
    if branch != INSTALLED:
        return git_text(git, "show", f"{branch}:rclpy/{path}")
    spec = importlib.util.find_spec("rclpy")
    assert spec and spec.submodule_search_locations, "rclpy is not installed"
    return (Path(spec.submodule_search_locations[0]).parent / path).read_text(encoding="utf-8")


def _self_stores(function: ast.FunctionDef | ast.AsyncFunctionDef) -> Iterator[str]:
    receiver = function.args.args[0].arg if function.args.args else None
    for node in ast.walk(function):
        if isinstance(node, ast.Attribute) and not isinstance(node.ctx, ast.Load) and \
                isinstance(node.value, ast.Name) and node.value.id == receiver:
            yield node.attr


def _own_attributes(cls: ast.ClassDef) -> Iterator[str]:
    for statement in cls.body:
        if isinstance(statement, ast.ClassDef):
            yield statement.name
        elif isinstance(statement, (ast.FunctionDef, ast.AsyncFunctionDef)):
            yield statement.name
            yield from _self_stores(statement)
        elif isinstance(statement, ast.Assign):
            yield from (t.id for t in statement.targets if isinstance(t, ast.Name))
        elif isinstance(statement, ast.AnnAssign) and isinstance(statement.target, ast.Name):
            yield statement.target.id
    for decorator in cls.decorator_list:  # the QoS enums' deprecated aliases
        yield from (c.value for c in ast.walk(decorator)
                    if isinstance(c, ast.Constant) and isinstance(c.value, str) and
                    c.value.isupper())


def _attributes(git: Path, branch: str, dotted: str, seen: frozenset[str] = frozenset()
                ) -> set[str] | None:
    """Every attribute of class ``dotted`` on ``branch`` (None when its module lacks it)."""
    module, name = dotted.rsplit(".", 1)
    tree = ast.parse(source(git, branch, module))
    found = next((c for c in tree.body if isinstance(c, ast.ClassDef) and c.name == name), None)
    if found is None:
        return None
    attributes = set(_own_attributes(found))
    imported = {alias.asname or alias.name: f"{node.module}.{alias.name}"
                for node in tree.body if isinstance(node, ast.ImportFrom) and node.module
                for alias in node.names}
    for base in found.bases:
        base_name = base.value.id if isinstance(base, ast.Subscript) and \
            isinstance(base.value, ast.Name) else base.id if isinstance(base, ast.Name) else None
        if base_name in _CLOSED_BASES:
            attributes.update(_ENUM_ATTRIBUTES if base_name == "IntEnum" else
                              ("name", "value") if base_name == "Enum" else ())
            continue
        where = f"{module}.{base_name}" if any(
            isinstance(c, ast.ClassDef) and c.name == base_name for c in tree.body) else \
            imported.get(base_name or "", "")
        inherited = _attributes(git, branch, where, seen | {dotted}) \
            if where.startswith("rclpy.") and where not in seen else None
        if inherited is None:
            raise SystemExit(f"{dotted} on {branch}: base {ast.unparse(base)} is not read")
        attributes |= inherited
    return attributes


def table(git: Path) -> dict[str, set[str]]:
    """Class -> the union of its attributes over :data:`BRANCHES` and the installed wheel
    (dunders left out)."""
    found: dict[str, set[str]] = {}
    for dotted in CLASSES:
        union: set[str] = set()
        for branch in (*BRANCHES, INSTALLED):
            union |= _attributes(git, branch, dotted) or set()
        found[dotted] = {name for name in union if not name.startswith("__")}
    return found


def write_rclpy_table(name: str, title: str, make: Callable[[Path], dict[str, set[str]]],
                      description: str) -> None:
    """The command line of a generator of the table ``name`` from a ros2/rclpy clone: each
    entry of ``make(git)`` a line ``<key> <value>...``, under the comment ``title``."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--rclpy-git", type=Path, required=True,
                        help="a clone of ros2/rclpy (its git folder)")
    parser.add_argument("--output", type=Path, default=DATA, help="where to write the table")
    options = parser.parse_args()
    git = options.rclpy_git
    sources = [f"ros-jazzy-rclpy=={importlib.metadata.version('ros-jazzy-rclpy')}",
               *(f"ros2/rclpy@{branch}:{git_text(git, 'rev-parse', '--short', branch).strip()}"
                 for branch in BRANCHES)]
    lines = [f"{key} {' '.join(sorted(values))}" for key, values in make(git).items()]
    write({name: render(f"{title}\nGenerated by `python -m pkgtool.knowledge.generate_{name}`; "
                        "do not edit.", sources, [("-", lines)])}, options.output)


def main() -> None:
    write_rclpy_table("rclpy_classes", "The attributes of the rclpy objects a node makes.",
                      table, __doc__.splitlines()[0])


if __name__ == "__main__":
    main()
