"""The lines of a ``.msg``, ``.srv`` or ``.action`` file, split as rosidl's adapter splits them.

rosidl (``rosidl_adapter.parser``) finds the sections of a service or an action at lines that
are exactly ``---``, drops everything from the first ``#`` of a line, and reads each remaining
line as ``<type> <name>[ <default>]`` (a field) or, when the rest holds ``=``, as ``<type>
<NAME>=<value>`` (a constant). This module only splits; what rosidl would refuse is the rules'
business (:mod:`pkgtool.rules.interfaces`).
"""

from __future__ import annotations

from pkgtool.records import record

SEPARATOR = "---"
SECTIONS = {"msg": 1, "srv": 2, "action": 3}
"""How many sections (parts between ``---`` lines) a file of each kind has."""


@record
class Member:
    """One field or constant line: where it is, what it declares.

    ``type`` is the first word (empty when the line starts with a space, which rosidl cannot
    read), ``name`` the word after it (empty when there is none), ``value`` a field's default
    or a constant's value (None when absent), ``section`` the 0-based section it is in.
    """

    line: int
    column: int
    type: str
    name: str
    value: str | None
    constant: bool
    section: int


@record
class InterfaceFile:
    """A package's interface definition: its kind and name (from the file name), its fields
    and constants in order, the lines of its ``---`` separators, and the lines rosidl takes
    for no separator though they look like one (spaces or a comment beside ``---``; any
    in a message)."""

    path: str
    kind: str
    name: str
    members: tuple[Member, ...]
    separators: tuple[int, ...]
    near_separators: tuple[int, ...]


def read_interface(path: str, kind: str, name: str, text: str) -> InterfaceFile:
    """The :class:`InterfaceFile` of ``text``, the content of ``path`` (``kind`` and ``name``
    as rosidl takes them from the path)."""
    members: list[Member] = []
    separators: list[int] = []
    near: list[int] = []
    section = 0
    for number, raw in enumerate(text.splitlines(), 1):
        if raw == SEPARATOR and kind != "msg":
            separators.append(number)
            section += 1
            continue
        if raw.split("#", 1)[0].strip() == SEPARATOR:  # ``--- # response``, `` ---``
            near.append(number)
            continue
        member = _member(raw, number, section)
        if member is not None:
            members.append(member)
    return InterfaceFile(path, kind, name, tuple(members), tuple(separators), tuple(near))


def _member(raw: str, number: int, section: int) -> Member | None:
    """The field or constant ``raw`` declares, or None for a blank or comment line."""
    line = raw.replace("\t", " ").rstrip()
    comment = line.find("#")
    if comment >= 0:
        line = line[:comment]
        if not line.strip():
            return None
        line = line.rstrip()
    if not line:
        return None
    type_, _, rest = line.partition(" ")
    rest = rest.lstrip()
    column = len(line) - len(line.lstrip()) + 1
    equals = rest.find("=")
    if equals >= 0:
        return Member(number, column, type_, rest[:equals].rstrip(),
                      rest[equals + 1:].lstrip(), True, section)
    name, _, default = rest.partition(" ")
    return Member(number, column, type_, name, default.lstrip() or None, False, section)
