"""IFC003: a field type of an interface definition that names no type (``float``, ``Header``)."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.interfaces import KINDS, close_interfaces, kind_in, packages_with
from pkgtool.model.interface_file import Member
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.records import record
from pkgtool.rules.interface_types import interfaces_for
from pkgtool.rules.interfaces._files import (LOWER_NAME, MESSAGE_NAME, PRIMITIVES,
                                             built_interface_files, split_type)
from pkgtool.rules.registry import rule

_OTHER_LANGUAGES = {"float": "float64", "double": "float64", "int": "int32", "integer": "int32",
                    "uint": "uint32", "long": "int64", "short": "int16", "str": "string",
                    "boolean": "bool", "uchar": "uint8", "unsigned": "uint32"}
"""Type names of other languages -> the ``.msg`` type meant (Python's float is a float64)."""


@record
class TypeProblem:
    """Why a written type names no type, the type meant when that is clear, and whether
    writing it needs nothing else (``lint --fix``)."""

    why: str
    meant: str | None = None
    fixable: bool = True


@rule("IFC003", "unknown-field-type", Severity.ERROR,
      fix="Use a basic type (`float64`, `string`) or a message as `package/Message`")
def unknown_field_type(package: Package) -> Iterator[Hit]:
    """A field of an interface definition has a type that does not exist.

    ## What it does
    Checks the type of every field of the `.msg`, `.srv` and `.action` files of a ROS 2
    package. A type is a basic type (`bool`, `byte`, `char`, `float32`, `float64`, `int8` to
    `uint64`, `string`, `wstring`), a message of the package itself (`Status`), or another
    package's message written `package/Message`. Reports type names of other languages
    (`float`, `int`, `double`, `str`), basic types in other letter cases (`String`,
    `Float64`: a name starting in upper case is a message of the package itself), ROS 1's
    habit of a bare `Header` (`std_msgs/Header` in ROS 2), `pkg/msg/Name` (written without
    `msg/` in these files), and `package/Message` where the package is known (the
    workspace's, or a Jazzy package pkgtool's tables list) and has no such message. A message
    of an unknown package is not judged. Only the files the CMakeLists.txt passes to
    `rosidl_generate_interfaces` are read; ROS 1 (catkin) packages are left alone.

    ## Why is this bad?
    `colcon build` fails in `rosidl_generate_interfaces` (an invalid name, or no `.idl` file
    for the type), so no interface of the package is generated and every node importing one
    fails.

    ## Example
    ```text
    Header header
    String label
    float speed
    geometry_msgs/msg/Point target
    ```

    ## Use instead
    ```text
    std_msgs/Header header
    string label
    float64 speed
    geometry_msgs/Point target
    ```
    """
    for found in built_interface_files(package):
        for member in found.members:
            problem = type_problem(package, member) if member.type and member.name else None
            if problem is not None:
                yield Hit(Span(found.path, member.line, member.column), problem.why,
                          f"Write `{problem.meant}`" if problem.meant else None)


def type_problem(package: Package, member: Member) -> TypeProblem | None:
    """Why ``member``'s type names no type (with the type meant, array part kept), or None
    when it does or nothing is known."""
    written, array = split_type(member.type)
    base = written.split("<=", 1)[0]
    if base in PRIMITIVES:
        return None
    if member.constant:
        return None  # IFC002: constants take basic types only
    found = _problem(package, written)
    if found is None or found.meant is None:
        return found
    return TypeProblem(found.why, found.meant + array, found.fixable)


def _problem(package: Package, written: str) -> TypeProblem | None:
    """Why the type ``written`` (no array part) names nothing, or None."""
    parts = written.split("/")
    if len(parts) == 3 and parts[1] in KINDS:
        return TypeProblem(f"`{written}`: interface files name another package's message "
                           f"`{parts[0]}/{parts[2]}`, without `/{parts[1]}/`",
                           f"{parts[0]}/{parts[2]}")
    if len(parts) > 2:
        return TypeProblem(f"`{written}` is no type: write `package/Message`")
    if len(parts) == 1:
        return _bare(package, written)
    owner, name = parts
    if not LOWER_NAME.fullmatch(owner):
        lower = interfaces_for(package, owner.lower())
        return TypeProblem(f"`{written}`: `{owner}` is no valid package name",
                           f"{owner.lower()}/{name}" if lower is not None and
                           name in lower.get("msg", ()) else None)
    known = interfaces_for(package, owner)
    if known is None or name in known.get("msg", ()):
        return None
    other = kind_in(known, name)
    if other is not None:
        return TypeProblem(f"`{written}` is a {'service' if other == 'srv' else 'action'}, "
                           "not a message: a field holds messages only")
    close = close_interfaces(known, name, "msg")
    return TypeProblem(f"`{owner}` has no message `{name}`",
                       f"{owner}/{close[0]}" if close else None)


def _bare(package: Package, name: str) -> TypeProblem | None:
    """Why ``name``, written without a package, names nothing, or None."""
    lower = name.lower()
    if not MESSAGE_NAME.fullmatch(name):
        meant = _OTHER_LANGUAGES.get(lower) or (lower if lower in PRIMITIVES else None)
        return TypeProblem(f"`{name}` is not a type of ROS interfaces", meant)
    own = interfaces_for(package, package.name)
    if own is None or name in own.get("msg", ()):
        return None
    if lower in PRIMITIVES:
        return TypeProblem(f"`{name}` names a message of this package, which has none: the "
                           f"basic type is `{lower}`", lower)
    where = _preferred(package, packages_with("msg", name, package.context.distro))
    return TypeProblem(f"`{name}` names a message of this package (`{package.name}/{name}`), "
                       "which has none" + (f"; `{where}/{name}` exists" if where else ""),
                       f"{where}/{name}" if where else None, where in _declared(package))


def _preferred(package: Package, owners: list[str]) -> str | None:
    """The package of ``owners`` a field most likely means: one the package depends on, else
    a ``*_msgs`` package, else the first."""
    declared = _declared(package)
    ranked = sorted(owners, key=lambda o: (o not in declared, not o.endswith("_msgs"), o))
    return ranked[0] if ranked else None


def _declared(package: Package) -> frozenset[str]:
    """The names package.xml declares as dependencies of any kind."""
    return frozenset(d.name for d in package.manifest.dependencies) if package.manifest \
        else frozenset()
