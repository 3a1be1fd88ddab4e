"""Declaring dependencies in package.xml with the tag the package's own style calls for."""

from __future__ import annotations

from collections.abc import Iterable

from pkgtool.add.target import Target
from pkgtool.edit.core import EditError
from pkgtool.edit.manifest import ManifestDoc

RUNTIME = ("depend", "exec_depend", "run_depend")
TEST = (*RUNTIME, "test_depend")


def resolve(names: Iterable[str]) -> tuple[set[str], set[str]]:
    """(ROS packages, rosdep keys of Python modules) for ROS package, module or key names."""
    from pkgtool.create import CreateError
    from pkgtool.create.options import sort_dependencies

    try:
        return sort_dependencies(tuple(names))
    except CreateError as error:
        raise EditError(str(error).replace("--dependencies", "the command line")) from None


def declare(target: Target, *, ros: Iterable[str] = (), exec_only: Iterable[str] = (),
            tests: Iterable[str] = ()) -> None:
    """Add what is not declared yet, as ``ros2 pkg create`` and ``pkgtool create`` would.

    ``ros``: ROS packages the code imports (``<depend>`` when the manifest uses it, else
    ``<exec_depend>``); ``exec_only``: rosdep keys and packages needed only to run
    (``<exec_depend>``, e.g. Python modules and launch); ``tests``: ``<test_depend>``.
    """
    for name in sorted(set(ros)):
        _declare(target, name, RUNTIME, ros=True)
    for name in sorted(set(exec_only)):
        _declare(target, name, RUNTIME, ros=False)
    for name in sorted(set(tests)):
        _declare(target, name, TEST, ros=False, test=True)


def _declare(target: Target, name: str, covered_by: tuple[str, ...], *, ros: bool,
             test: bool = False) -> None:
    if name == target.name:
        raise EditError(f"`{name}` is this package itself: a package does not depend on itself.")
    source = target.session.source("package.xml")
    assert source is not None
    doc = ManifestDoc(source)
    if any(doc.find(tag, name) for tag in covered_by):
        return
    if test:
        tag = "test_depend"
    elif doc.format == 1:
        tag = "run_depend"
    elif ros and doc.find("depend"):
        tag = "depend"
    else:
        tag = "exec_depend"
    target.session.apply(doc.add(tag, name))
