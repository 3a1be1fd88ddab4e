"""DEP008: a message, service or action imported that its package does not define."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.interfaces import (KINDS, WORDS, Interfaces, Mismatch, generated_module,
                                          kind_in, meant_kind, mismatch)
from pkgtool.knowledge.ros_names import ROS_SUFFIXES
from pkgtool.model.modules import Import
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.imports import all_python, dependency_cause
from pkgtool.rules.interface_types import interfaces_for, patched_interfaces
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import index_of, python_files, resolved_attributes
from pkgtool.lazy_regex import lazy_pattern


@rule("DEP008", "unknown-interface-import", Severity.ERROR,
      fix="Import an interface the package defines, from the module of its kind")
def unknown_interface_import(package: Package) -> Iterator[Hit]:
    """``from pkg.msg import Name`` names no message of ``pkg``, or ``pkg.msgs`` no module.

    ## What it does
    Checks the names of unguarded `from <pkg>.msg|srv|action import ...` imports in every
    Python file against the interfaces of `<pkg>` when they are known: the package's own
    `msg/`, `srv/` and `action/` folders (their subfolders too: rosidl flattens
    `msg/motion/Twist.msg` into `msg/Twist`) and the other files its CMakeLists.txt passes to
    `rosidl_generate_interfaces` (none are known when it passes a list that a package it
    finds sets, such as `${pkg_MSG_FILES}`), those of the other packages of the workspace, and
    pkgtool's table of the interface packages of ROS 2 Jazzy that are installable as wheels
    (for a jazzy target only: other distributions have other interfaces)
    (`std_msgs`, `geometry_msgs`, `sensor_msgs`, `std_srvs`, ...). Packages that are not
    known (`nav2_msgs`) are never reported. The types generated with each service `X`
    (`X_Request`, `X_Response`, `X_Event`) and action `A` (`A_SendGoal_Request`,
    `A_GetResult_Response`, ...) exist where the target distribution's modules export them:
    since Iron; on humble they are reported with the attribute to use (`X.Request`). The
    submodule rosidl writes each interface to (`from pkg.action import _fibonacci`) is no
    mistake. A ROS 1 (catkin) package is checked against its own interfaces only, where an
    action `A` is the messages `AAction`, `AGoal`, `AResult`, ... of `pkg.msg` and a service
    `X` also gives `XRequest` and `XResponse` in `pkg.srv`. A name the
    package's installed code assigns onto the module (`rosgraph_msgs.msg.Log =
    rcl_interfaces.msg.Log`, as ROS 1 compatibility shims do) exists.

    The same goes for a name read on the module (`std_msgs.msg.Strng()` after `import
    std_msgs.msg`). Also reports a misspelled module of an interface package (`std_msgs.msgs`,
    `geometry_msgs.message`, `example_interfaces.srvs`, `from std_msgs import Msg`; a word
    too short to tell, `from my_interfaces.src import AddTwo`, when every name imported is an
    interface of one kind of the package), an
    interface package written in other letter cases (`from Robot_interfaces.srv import
    Home` for the workspace's `robot_interfaces`), and an interface imported from the package
    itself (`from std_msgs import String`): the
    Python module of a ROS 2 interface package holds only `msg`, `srv` and `action`. An
    interface package is one whose interfaces are known as above, or one named like an
    interface package (`*_msgs`, `*_srvs`, `*_interfaces`); a workspace package that has a
    Python package of its own, and the linted package's own modules (`pkg/messages.py`), may
    define any submodule and are not reported.

    ## Why is this bad?
    The node dies at start-up with `ImportError: cannot import name ...` (or
    `ModuleNotFoundError: No module named 'std_msgs.msgs'`); a service imported from `.msg`
    fails the same way, and only on the robot.

    ## Example
    ```python
    from std_msgs.msg import Strin
    from std_srvs.msg import Trigger
    from example_interfaces.srvs import AddTwoInts
    ```

    ## Use instead
    ```python
    from std_msgs.msg import String
    from std_srvs.srv import Trigger
    from example_interfaces.srv import AddTwoInts
    ```
    """
    for module in all_python(package):
        for imported in module.imports:
            parts = imported.module.split(".")
            if imported.level or imported.guarded:
                continue
            yield from _misspelled_module(package, imported)
            yield from _interface_without_module(package, imported)
            if len(parts) != 2 or parts[1] not in KINDS:
                continue
            known = interfaces_for(package, parts[0])
            if known is None:
                yield from _miscased_package(package, imported, parts[0], parts[1])
                continue
            patched = patched_interfaces(package)
            modules = {generated_module(name) for name in known.get(parts[1], ())} \
                if any(name.startswith("_") for name in imported.names) else set()
            for name in imported.names:
                if (parts[0], parts[1], name) in patched:
                    continue
                found = None if name == "*" or name in modules else mismatch(
                    parts[0], parts[1], name, known, package.context.distro)
                if found:
                    yield Hit(imported.span, _message(found), _fix(found))
    yield from _attribute_reads(package)


def _attribute_reads(package: Package) -> Iterator[Hit]:
    """``std_msgs.msg.Strng`` read through ``import std_msgs.msg``: a name the interface
    module lacks."""
    for path, _, tree in python_files(package, (".msg.", ".srv.", ".action.")):
        index = index_of(tree)
        for node, owner, name in resolved_attributes(index):
            parts = owner.split(".")
            known = interfaces_for(package, parts[0]) \
                if len(parts) == 2 and parts[1] in KINDS and not name.startswith("_") else None
            found = mismatch(parts[0], parts[1], name, known, package.context.distro) \
                if known is not None and (parts[0], parts[1], name) not in \
                patched_interfaces(package) else None
            if found:
                kind, meant = (found.actual, found.name) if found.actual else \
                    found.close or (None, None)
                yield Hit(Span(path, node.end_lineno or node.lineno,
                               (node.end_col_offset or 0) - len(name) + 1), _message(found),
                          f"Write `{found.package}.{kind}.{meant}`" if kind else None)


def _misspelled_module(package: Package, imported: Import) -> Iterator[Hit]:
    """``pkg.msgs`` imported (``import pkg.msgs``, ``from pkg.msgs import X``, ``from pkg
    import msgs``) where ``pkg`` is an interface package: the module meant, as a hit."""
    name, _, rest = imported.module.partition(".")
    words = [rest.split(".")[0]] if rest else list(imported.names)
    for word in words:
        known = interfaces_for(package, name) or {}
        kind = meant_kind(word) or (_kind_of_all(known, imported.names) if rest and
                                    word not in KINDS else None)
        if kind is None or not _interface_package(package, name, word):
            continue
        kind = next(filter(None, (kind_in(known, n) for n in imported.names)), kind)
        right = f"{name}.{kind}"
        written = f"{name}.{word}"
        if not rest:
            fix = f"Write `from {name} import {kind}`"
        elif imported.names:
            fix = f"Write `from {right}{imported.module[len(written):]} import " \
                f"{', '.join(imported.names)}`"
        else:
            fix = f"Write `import {right}{imported.module[len(written):]}`"
        yield Hit(imported.span, f"`{written}` does not exist: the {WORDS[kind]}s of `{name}` "
                  f"are in `{right}`", fix)


def _interface_without_module(package: Package, imported: Import) -> Iterator[Hit]:
    """``from pkg import Name`` where ``Name`` is an interface of the interface package
    ``pkg`` (it lives in ``pkg.msg``, ``pkg.srv`` or ``pkg.action``), as a hit."""
    if "." in imported.module:
        return
    known = interfaces_for(package, imported.module) or {}
    for name in imported.names:
        kind = kind_in(known, name)
        if kind is not None and _interface_package(package, imported.module, name):
            right = f"{imported.module}.{kind}"
            yield Hit(imported.span, f"`{imported.module}` has no `{name}`: the "
                      f"{WORDS[kind]} `{name}` is in `{right}`",
                      f"Write `from {right} import {name}`")
            return


def _miscased_package(package: Package, imported: Import, name: str, kind: str
                      ) -> Iterator[Hit]:
    """``from Robot_interface.srv import X`` where no package is ``Robot_interface`` but one
    interface package (of the workspace, or of pkgtool's table) is ``robot_interface``: Python
    imports are case-sensitive, so this one fails, as a hit."""
    if name in package.context.workspace or name == package.name:
        return
    lowered = name.lower()
    meant = {other for other in (*package.context.workspace, package.name, lowered)
             if other.lower() == lowered and other != name and interfaces_for(package, other)}
    if len(meant) == 1:
        right = meant.pop()
        names = ", ".join(imported.names)
        yield Hit(imported.span, f"There is no package `{name}`: the interface package is "
                  f"`{right}`, and Python imports are case-sensitive",
                  f"Write `from {right}.{kind} import {names}`" if names else None,
                  cause=dependency_cause(name))


def _kind_of_all(known: Interfaces, names: tuple[str, ...] | list[str]) -> str | None:
    """The one kind every name of ``names`` is of among ``known`` (``src`` written for
    ``srv`` is too short to tell by itself, but ``AddTwoInts`` is a service), or None."""
    kinds = {kind_in(known, name) for name in names}
    return kinds.pop() if len(kinds) == 1 and None not in kinds else None


def _interface_package(package: Package, name: str, word: str) -> bool:
    """True when the Python module of the package ``name`` certainly has no submodule
    ``word``: an interface package (interfaces known, or named like one) without Python code
    of its own that could define it."""
    if name == package.name:
        if any(f"/{path}".endswith((f"/{name}/{word}.py", f"/{name}/{word}/__init__.py"))
               for path in package.files):
            return False
    else:
        neighbour = package.context.workspace.get(name)
        if neighbour is not None:
            return bool(neighbour.interfaces) and name not in neighbour.modules
    return interfaces_for(package, name) is not None or name.endswith(ROS_SUFFIXES)


def _message(found: Mismatch) -> str:
    module = f"{found.package}.{found.kind}"
    if found.companion:
        return (f"`{module}` exports `{found.name}` only since Iron, not on {found.distro}: "
                f"use `{found.companion}`")
    if found.actual:
        return (f"`{found.name}` is a {WORDS[found.actual]} of `{found.package}`, not a "
                f"{WORDS[str(found.kind)]}: `{module}` has no `{found.name}`")
    text = f"`{module}` has no {WORDS[str(found.kind)]} `{found.name}`"
    if found.close:
        kind, name = found.close
        text += f" (did you mean `{name}`?)" if kind == found.kind else (
            f" (did you mean the {WORDS[kind]} `{name}` of `{found.package}.{kind}`?)")
    return text


def _fix(found: Mismatch) -> str | None:
    if found.companion:
        return f"Import `{found.companion.split('.', 1)[0]}` and use `{found.companion}`"
    kind, name = (found.actual, found.name) if found.actual else found.close or (None, None)
    return f"Write `from {found.package}.{kind} import {name}`" if kind else None


_WRITE_FROM = lazy_pattern(r"Write `from ([\w.]+) import ([\w, ]+)`")


def written_import(fix: str | None) -> tuple[str, tuple[str, ...]] | None:
    """(module, names) of a fix that says to write ``from module import names``."""
    found = _WRITE_FROM.fullmatch(fix or "")
    return (found[1], tuple(found[2].split(", "))) if found else None
