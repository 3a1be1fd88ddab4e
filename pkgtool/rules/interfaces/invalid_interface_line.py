"""IFC002: a line of a ``.msg``, ``.srv`` or ``.action`` file that rosidl cannot read."""

from __future__ import annotations

import re
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.interface_file import SECTIONS, SEPARATOR, InterfaceFile, Member
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.interfaces._files import (LOWER_NAME, PRIMITIVES, type_base,
                                             built_interface_files, split_type)
from pkgtool.rules.registry import rule
from pkgtool.lazy_regex import lazy_pattern

_CONSTANT_NAME = lazy_pattern(r"[A-Z](?:[A-Z0-9_]?[A-Z0-9]+)*")
"""What rosidl accepts for a constant's name."""
_INTEGERS = {"byte": (0, 255), "char": (0, 255), "int8": (-2 ** 7, 2 ** 7 - 1),
             "uint8": (0, 2 ** 8 - 1), "int16": (-2 ** 15, 2 ** 15 - 1),
             "uint16": (0, 2 ** 16 - 1), "int32": (-2 ** 31, 2 ** 31 - 1),
             "uint32": (0, 2 ** 32 - 1), "int64": (-2 ** 63, 2 ** 63 - 1),
             "uint64": (0, 2 ** 64 - 1)}
_ARRAY = lazy_pattern(r"\[(?:<=)?(\d*)\]")
_KIND_NAMES = {"msg": "a message", "srv": "a service", "action": "an action"}


@rule("IFC002", "invalid-interface-line", Severity.ERROR,
      fix="Write the line as `<type> <name>[ <default>]` or `<type> <NAME>=<value>`")
def invalid_interface_line(package: Package) -> Iterator[Hit]:
    """A line of an interface definition that rosidl refuses.

    ## What it does
    Reads the `.msg`, `.srv` and `.action` files of a ROS 2 package line by line as rosidl's
    adapter does, and reports what it refuses: a service without exactly one `---` line or an
    action without exactly two (a `---` with spaces around it is no separator; a message has
    none); a line starting with a space; a type with no name after it; a field name that is
    not lower case with underscores (`int32 Value`, `float64 linearVelocity`, `x_`); a constant
    name that is not upper case (`int32 max_speed=3`) or a constant of a type that is not
    basic; a default or constant value the type cannot hold (`uint8 X=300`, `bool b yes`), a
    default on a message field; an array size of 0; a field name used twice in one part. The
    types themselves are IFC003's. Only the files the CMakeLists.txt passes to
    `rosidl_generate_interfaces` are read (a course's unlisted template is not); ROS 1
    (catkin) packages, whose rules differ, are left alone.

    ## Why is this bad?
    `colcon build` fails in `rosidl_generate_interfaces` with this line, so no interface of
    the package is generated and every node importing one fails.

    ## Example
    ```text
    # srv/SetSpeed.srv
    float64 linearVelocity
    int32 max_speed=3
    bool ok
    ```

    ## Use instead
    ```text
    float64 linear_velocity
    int32 MAX_SPEED=3
    ---
    bool ok
    ```
    """
    for found in built_interface_files(package):
        yield from _separators(found)
        seen: set[tuple[int, str]] = set()
        for member in found.members:
            problem = _problem(member)
            if problem is None and not member.constant:
                key = (member.section, member.name)
                problem = (f"field `{member.name}` is declared twice", "Rename or remove one") \
                    if key in seen else None
                seen.add(key)
            if problem is not None:
                yield Hit(Span(found.path, member.line, member.column), *problem)


def _separators(found: InterfaceFile) -> Iterator[Hit]:
    """Hits for ``---`` lines that are missing, too many or not exactly ``---``."""
    wanted = SECTIONS[found.kind] - 1
    kind = _KIND_NAMES[found.kind]
    for line in found.near_separators:
        yield Hit(Span(found.path, line, 1),
                  "a message has no `---` line (only services and actions have parts)"
                  if found.kind == "msg" else
                  f"`{SEPARATOR}` with more on its line: rosidl takes only a line of exactly "
                  f"`{SEPARATOR}` for the separator", None if found.kind == "msg"
                  else f"Write the line as `{SEPARATOR}` alone")
    if found.kind == "msg" or len(found.separators) == wanted or found.near_separators:
        return
    if len(found.separators) > wanted:
        yield Hit(Span(found.path, found.separators[wanted], 1),
                  f"{kind} has {wanted + 1} parts, split by {wanted} `{SEPARATOR}` "
                  f"line{'s' if wanted > 1 else ''}: this one is too many")
        return
    parts = "request and response" if found.kind == "srv" else "goal, result and feedback"
    yield Hit(Span(found.path, found.separators[-1] if found.separators else 1, 1),
              f"{kind} needs {wanted} `{SEPARATOR}` line{'s' if wanted > 1 else ''} between "
              f"its {parts}; this file has {len(found.separators)}",
              f"Add the missing `{SEPARATOR}` line (an empty part is allowed)")


def _problem(member: Member) -> tuple[str, str | None] | None:
    """What rosidl refuses in ``member``'s line, and how to fix it; or None."""
    if not member.type:
        return ("the line starts with a space: rosidl reads an empty type and fails",
                "Remove the spaces before the type")
    if not member.name:
        return f"`{member.type}` declares no name", "Write the name after the type"
    found = _written_problem(member)
    return None if found is None else (found, None)


def _written_problem(member: Member) -> str | None:
    """What rosidl refuses in the type, name or value of ``member``, or None."""
    array = split_type(member.type)[1]
    size = _ARRAY.fullmatch(array) if array else None
    if array and (size is None or size.group(1) == "0"):
        return f"`{member.type}`: an array size must be a number above 0 (`[3]`, `[<=3]`)"
    if re.search(r"<=0*(?:\D|$)", split_type(member.type)[0]):
        return f"`{member.type}`: a string bound must be a number above 0 (`string<=10`)"
    if member.constant:
        return _constant_problem(member)
    if not LOWER_NAME.fullmatch(member.name):
        return (f"field name `{member.name}` is not lower case with single underscores "
                f"(`{_snake_case(member.name)}`)")
    if member.value is not None:
        return _value_problem(member.type, member.value, "default")
    return None


def _constant_problem(member: Member) -> str | None:
    """What rosidl refuses in a constant's line, or None."""
    if type_base(member.type) not in PRIMITIVES or split_type(member.type)[1]:
        return f"constant `{member.name}` has type `{member.type}`: constants take basic types"
    if not _CONSTANT_NAME.fullmatch(member.name):
        return (f"constant name `{member.name}` is not upper case with single underscores "
                f"(`{_snake_case(member.name).upper()}`)")
    return _value_problem(member.type, member.value or "", "value")


def _value_problem(written: str, value: str, what: str) -> str | None:
    """Why ``value`` is no value of type ``written``, or None (strings take any text)."""
    base, array = split_type(written)
    base = base.split("<=", 1)[0]
    if base not in PRIMITIVES:
        return f"a field of type `{written}` cannot have a default: only basic types can"
    if array:
        if not (value.startswith("[") and value.endswith("]")):
            return f"the {what} `{value}` of an array must be written `[a, b, ...]`"
        return None if base in ("string", "wstring") else next(
            (problem for element in filter(None, value[1:-1].split(","))
             if (problem := _value_problem(base, element.strip(), what))), None)
    if base == "bool" and value.lower() not in ("true", "false", "1", "0"):
        return f"the {what} `{value}` is no bool: write `true`, `false`, `1` or `0`"
    if base in _INTEGERS:
        low, high = _INTEGERS[base]
        number = _integer(value)
        if number is None or not low <= number <= high:
            return f"the {what} `{value}` is no {base} (an integer from {low} to {high})"
    if base in ("float32", "float64"):
        try:
            float(value)
        except ValueError:
            return f"the {what} `{value}` is no {base}"
    return None


def _integer(value: str) -> int | None:
    """``value`` as rosidl reads an integer (decimal, or with a ``0x``/``0o``/``0b`` prefix)."""
    for base in (10, 0):
        try:
            return int(value, base)
        except ValueError:
            continue
    return None


def _snake_case(name: str) -> str:
    """``name`` in lower case with single underscores (``linearVelocity`` gives
    ``linear_velocity``)."""
    spaced = re.sub(r"(?<=[a-z0-9])(?=[A-Z])", "_", name)
    return re.sub(r"_+", "_", spaced).strip("_").lower() or "name"
