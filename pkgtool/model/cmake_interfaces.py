"""The interface files a CMakeLists.txt passes to ``rosidl_generate_interfaces``, as far as known.

Most packages list files of their own ``msg/``, ``srv/`` and ``action/`` folders, literally or
through a variable set in the same file (``set(msg_files "msg/A.msg")``, ``file(GLOB ...)``).
Some list files of other folders (``interfaces/msg/A.msg``: the folder holding a file names
its kind), and some list files a variable from another package holds
(``${test_interface_files_MSG_FILES}`` after ``find_package(test_interface_files)``): then
the package defines interfaces no file of its tree shows, and its set of interfaces is open.

A file may take part of its list from a CMake file of the package it ``include()``s (the
variables are shared; ``${CMAKE_CURRENT_LIST_DIR}`` there is that file's folder), and from
``file(GLOB ...)`` patterns, which match the package's files.

The reading of the text is :mod:`pkgtool.model.cmake_text`'s; what the file installs,
:mod:`pkgtool.model.cmake_install`'s.
"""

from __future__ import annotations

import posixpath
from collections.abc import Iterable

from pkgtool.model.cmake_text import DEPTH, commands, expand, set_variables
from pkgtool.lazy_regex import lazy_pattern
from pkgtool.records import record

_KEYWORDS = frozenset({"DEPENDENCIES", "LIBRARY_NAME", "SKIP_INSTALL", "ADD_LINTER_TESTS",
                       "SKIP_GROUP_MEMBERSHIP_CHECK"})
"""Where the interface files of a ``rosidl_generate_interfaces`` call end."""


_KINDS = ("msg", "srv", "action")


_SUFFIXES = (".msg", ".srv", ".action", ".idl")


@record
class ListedInterfaces:
    """What the ``rosidl_generate_interfaces`` calls of a CMakeLists.txt list.

    ``files`` are the package-relative paths of the files listed literally (or through
    variables set in the file); ``open`` is True when some argument comes from a variable the
    file never sets and a package it finds does (``${Pkg_MSG_FILES}`` after
    ``find_package(Pkg)``), so that the package defines interfaces pkgtool cannot see.
    """

    files: frozenset[str] = frozenset()
    open: bool = False


def listed_interfaces(text: str, files: Iterable[str] = ()) -> ListedInterfaces:
    """The interface files the ``rosidl_generate_interfaces`` calls of ``text`` list, its
    globs matched against ``files`` (the package's)."""
    calls = commands(text)
    variables = set_variables(calls, frozenset(files))
    files: set[str] = set()
    is_open = False
    for name, args in calls:
        if name != "rosidl_generate_interfaces":
            continue
        for arg in _interface_args(args[1:]):
            for value in expand(arg, variables, DEPTH):
                if value is None:
                    is_open = True
                elif value.endswith(_SUFFIXES):
                    files.add(posixpath.normpath(value.rsplit(":", 1)[-1].lstrip("/")))
    return ListedInterfaces(frozenset(files), is_open)


def interfaces_of_files(files: frozenset[str]) -> dict[str, frozenset[str]]:
    """Kind -> interface names of ``files``: the kind of a ``.msg``, ``.srv`` or ``.action``
    file is its suffix, wherever it lies (rosidl_adapter puts ``error_msgs/Error.msg`` into
    ``msg``), that of an ``.idl`` file the folder holding it."""
    found: dict[str, set[str]] = {}
    for path in files:
        folder, name = posixpath.split(path)
        suffix = name.rsplit(".", 1)[-1]
        kind = suffix if suffix in _KINDS else posixpath.basename(folder)
        if kind in _KINDS:
            found.setdefault(kind, set()).add(name.rsplit(".", 1)[0])
    return {kind: frozenset(names) for kind, names in found.items()}


def _interface_args(args: list[str]) -> list[str]:
    """The arguments before the first keyword: the interface files."""
    listed = []
    for arg in args:
        if arg in _KEYWORDS:
            break
        listed.append(arg)
    return listed


def with_listed(found: dict[str, frozenset[str]], cmake: str | None, files: Iterable[str] = ()
                ) -> dict[str, frozenset[str]] | None:
    """What ``cmake`` lists (its globs matched against ``files``, the package's), but files of
    its ``msg``, ``srv`` and ``action`` folders that ``files`` lacks (rosidl stops at a
    missing file: no such interface is ever made); when the CMake code rebuilds lists
    (:func:`rebuilds_list`), also ``found`` (kind -> names of the interface folders).

    None when the list is open: the package defines interfaces no file of its tree shows.
    """
    if cmake is None or "rosidl_generate_interfaces" not in cmake:
        return found
    files = frozenset(files)
    listed = listed_interfaces(cmake, files)
    if listed.open:
        return None
    present = {path for path in listed.files
               if path in files or path.split("/", 1)[0] not in _KINDS}
    made = interfaces_of_files(frozenset(present))
    if not rebuilds_list(cmake):  # the list is all rosidl gets: unlisted files make nothing
        return dict(made)
    merged = dict(found)
    for kind, names in made.items():
        merged[kind] = merged.get(kind, frozenset()) | names
    return merged


_REBUILT_LIST = lazy_pattern(r"(?i)\bforeach\s*\(|\blist\s*\(\s*(?:TRANSFORM|APPEND|INSERT)")
"""CMake that builds a list of files anew (``foreach(f ${MSG_FILES}) list(APPEND ...
"msg/${f}")``): what the first list names are not the paths rosidl gets."""


def rebuilds_list(cmake: str) -> bool:
    """True when CMake code builds a list anew (a loop, ``list(APPEND ...)``): the lists it
    sets are not read whole here."""
    return _REBUILT_LIST.search(cmake) is not None
