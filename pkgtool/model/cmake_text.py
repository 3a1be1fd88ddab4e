"""Reading a CMake file's text as CMake would, as far as that is static: its commands and
their arguments, the variables it sets (``set``, ``list``, ``file(GLOB ...)``, ``foreach``,
``project``), what an argument expands to, and the package's ``.cmake`` files it includes
(by path, or by module name from a folder ``CMAKE_MODULE_PATH`` lists)."""

from __future__ import annotations

import posixpath
import re
from collections.abc import Callable
from fnmatch import fnmatchcase

from pkgtool.lazy_regex import lazy_pattern

_CALL = lazy_pattern(r"\b([A-Za-z_]\w*)\s*\(([^()]*(?:\([^()]*\)[^()]*)*)\)", re.S)


_COMMENT = lazy_pattern(r"#[^\n]*")


_TOKEN = lazy_pattern(r'"([^"]*)"|(\S+)')


VARIABLE = lazy_pattern(r"\$\{(\w+)\}")


_SOURCE_DIRS = frozenset({"CMAKE_CURRENT_SOURCE_DIR", "PROJECT_SOURCE_DIR", "CMAKE_SOURCE_DIR",
                          "CMAKE_CURRENT_LIST_DIR"})
"""Variables holding the package's own folder: a path under them is a path in the package."""


DEPTH = 8


_GLOB_OPTIONS = {"RELATIVE": 1, "LIST_DIRECTORIES": 1, "CONFIGURE_DEPENDS": 0,
                 "FOLLOW_SYMLINKS": 0}
"""``file(GLOB ...)`` options, with how many values each takes: the rest are patterns."""


FOUND = "<find_package>"
"""Where :func:`set_variables` keeps the names of the packages the file finds."""


def with_included(text: str, read: Callable[[str], str | None]) -> str:
    """``text`` (a CMakeLists.txt) followed by the package's CMake files it ``include()``s,
    literally or through its variables (theirs too), as ``read`` (a package-relative path ->
    the text, or None) gives them; ``${CMAKE_CURRENT_LIST_DIR}`` in each stands for its folder.
    """
    seen: set[str] = set()
    parts = [text]
    for part in parts:
        for path in included_files(part):
            included = read(path) if path not in seen else None
            seen.add(path)
            if included is not None and len(seen) <= DEPTH:
                folder = posixpath.dirname(path)
                parts.append(included.replace("${CMAKE_CURRENT_LIST_DIR}", folder or "."))
    return "\n".join(parts)


_MODULE_NAME = lazy_pattern(r"[A-Za-z_][\w-]*")


def included_files(text: str) -> list[str]:
    """The package-relative paths of the ``.cmake`` files ``text`` includes: by path, or by
    module name from a folder of the package ``CMAKE_MODULE_PATH`` lists (other modules, such
    as ``include(GNUInstallDirs)``, are CMake's own)."""
    calls = commands(text)
    variables = set_variables(calls, frozenset())
    folders = dict.fromkeys(posixpath.normpath(folder.lstrip("/")) for value in
                            variables.get("CMAKE_MODULE_PATH") or () if value
                            for folder in expand(value, variables, DEPTH)
                            if folder and "${" not in folder)
    found = []
    for name, args in calls:
        for value in expand(args[0], variables, DEPTH) if name == "include" and args else ():
            if value and value.endswith(".cmake") and "${" not in value:
                found.append(posixpath.normpath(value.lstrip("/")))
            elif value and _MODULE_NAME.fullmatch(value):  # a module of CMAKE_MODULE_PATH
                found.extend(f"{folder}/{value}.cmake" for folder in folders)
    return [path for path in found if not path.startswith("..")]


def commands(text: str) -> list[tuple[str, list[str]]]:
    """The commands of a CMake file, names in lower case, with their arguments."""
    return [(name.lower(), _tokens(args)) for name, args in _CALL.findall(_COMMENT.sub("", text))]


def _tokens(args: str) -> list[str]:
    return [bare or quoted for quoted, bare in _TOKEN.findall(args)]


def set_variables(calls: list[tuple[str, list[str]]], files: frozenset[str]
                  ) -> dict[str, list[str] | None]:
    """Variables the file sets: their values (a glob's: the ``files`` it matches), or None
    for values only a build knows (a ``foreach(... RANGE ...)``)."""
    found: dict[str, list[str] | None] = {}
    for name, args in calls:
        if name == "set" and args:
            found.setdefault(args[0], []).extend(a for a in args[1:] if a != "PARENT_SCOPE")
        elif name == "list" and len(args) > 1 and args[0] in ("APPEND", "PREPEND"):
            found.setdefault(args[1], []).extend(args[2:])
        elif name == "list" and len(args) > 2 and args[0] == "INSERT":
            found.setdefault(args[1], []).extend(args[3:])
        elif name == "file" and len(args) > 1 and args[0] in ("GLOB", "GLOB_RECURSE"):
            found[args[1]] = _globbed(args[2:], files, args[0] == "GLOB_RECURSE")
        elif name == "foreach" and args:
            found[args[0]] = _loop_values(args[1:])
        elif name == "project" and args:
            found["PROJECT_NAME"] = [args[0]]
        elif name == "find_package" and args:
            found.setdefault(FOUND, []).append(args[0])
    return found


def _globbed(args: list[str], files: frozenset[str], recurse: bool) -> list[str]:
    """The package files the patterns of a ``file(GLOB ...)`` match, package-relative (a
    pattern with a variable other than the package's folder matches nothing known)."""
    patterns: list[str] = []
    skip = 0
    for arg in args:
        if skip:
            skip -= 1
        elif arg in _GLOB_OPTIONS:
            skip = _GLOB_OPTIONS[arg]
        else:
            for name in _SOURCE_DIRS:
                arg = arg.replace(f"${{{name}}}", "")
            if "${" not in arg:
                patterns.append(posixpath.normpath(arg.lstrip("/")))
    return [path for path in sorted(files)
            if any(_matches(path, pattern, recurse) for pattern in patterns)]


def _matches(path: str, pattern: str, recurse: bool) -> bool:
    """True when ``pattern`` matches ``path``; with ``recurse`` (``GLOB_RECURSE``) its folder
    part matches the file's folder or one above it."""
    folder, name = posixpath.split(path)
    where, what = posixpath.split(pattern)
    if not fnmatchcase(name, what):
        return False
    while not fnmatchcase(folder, where):
        if not recurse or not folder:
            return False
        folder = posixpath.dirname(folder)
    return True


def _loop_values(args: list[str]) -> list[str] | None:
    """The values a ``foreach`` variable takes (``IN LISTS`` names lists); None for a range."""
    if args[:1] == ["RANGE"]:
        return None
    if args[:2] == ["IN", "LISTS"]:
        return [f"${{{name}}}" for name in args[2:] if name != "ITEMS"]
    return [arg for arg in args if arg not in ("IN", "ITEMS")]


def _found_by_package(name: str, variables: dict[str, list[str] | None]) -> bool:
    """True for a variable a ``find_package``'d package sets (``<Package>_MSG_FILES``)."""
    return any(name.startswith(package + "_") for package in variables.get(FOUND) or ())


def expand(arg: str, variables: dict[str, list[str] | None], depth: int
           ) -> list[str | None]:
    """The values ``arg`` stands for; None for one that comes from outside the file.

    A variable nobody sets is empty, unless its name is that of a package the file finds
    (``find_package(Pkg)`` sets ``Pkg_...``). A path built from variables of one value each
    (``${PROJECT_NAME}/node.py``, ``${scripts}/x.py``) is joined; the source folder
    (``${CMAKE_CURRENT_SOURCE_DIR}/``) is the package's root.
    """
    for name in _SOURCE_DIRS:
        arg = arg.replace(f"${{{name}}}/", "").replace(f"${{{name}}}", "")
    names = VARIABLE.findall(arg)
    if not names:
        return [arg]
    if any(name not in variables and _found_by_package(name, variables) for name in names):
        return [None]
    if any(name not in variables for name in names):
        return []  # never set: empty
    if depth == 0:
        return []
    if arg == f"${{{names[0]}}}":
        result: list[str | None] = []
        for value in variables[names[0]] or ():
            result.extend(expand(value, variables, depth - 1))
        return result
    return [_joined(arg, variables, depth)]


def _joined(arg: str, variables: dict[str, list[str] | None], depth: int) -> str | None:
    """``arg`` (``${PROJECT_NAME}/node.py``) with each variable replaced by its one value; None
    when one has no single known value (a list, or a value from outside the file)."""
    values: dict[str, str] = {}
    for name in set(VARIABLE.findall(arg)):
        found = [v for value in variables[name] or () for v in expand(value, variables, depth - 1)]
        if len(found) != 1 or found[0] is None:
            return None
        values[name] = found[0]
    return VARIABLE.sub(lambda match: values[match.group(1)], arg)
