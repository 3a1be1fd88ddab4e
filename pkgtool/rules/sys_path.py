"""Folders of the package that a module puts on ``sys.path``, read statically from its source.

``sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "scripts"))`` and
``sys.path.append(os.path.join(os.path.dirname(__file__), "..", "scripts"))`` make the modules
of ``scripts/`` importable by their bare names in the rest of the process. Only paths built
from ``__file__`` and string literals are understood: ``os.path`` (``dirname``, ``join``,
``abspath``, ``realpath``, ``normpath``), ``pathlib.Path`` (``parent``, ``parents[n]``, ``/``,
``joinpath``, ``resolve()``, ``absolute()``, ``as_posix()``), ``str()``/``os.fspath()``, a text
starting with ``/`` added to a path (``dirname(__file__) + "/../lib"``, or in an f-string), and
names assigned such a path once in the whole module (at module level or in a function), and
an absolute path into the package's folder of one checkout's sources
(``/home/ubuntu/ws/src/<package>/driver``: the folder it stands for is the package's). The
package's own share folder (``get_package_share_directory('<package>')``) stands for its root:
a launch file putting ``share/<package>/launch`` on the path imports the package's ``launch/``
modules. Nothing is executed; a path leaving the package is ignored.
"""

from __future__ import annotations

import ast
import posixpath
from collections.abc import Iterator
from typing import NamedTuple

from pkgtool.model.ast_nodes import nodes_of
from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.model.python_visitor import parse_tree
from pkgtool.rules.scopes import single_assignments

_ROOT = "/package"
"""Where the package's root stands in the absolute paths worked out here."""
_SAME = frozenset({"os.path.abspath", "os.path.realpath", "os.path.normpath", "os.fspath", "str",
                   "pathlib.Path", "pathlib.PurePath", "pathlib.PosixPath"})
"""Calls whose one argument's path is their result."""
_JOINING = frozenset({"os.path.join", "pathlib.Path", "pathlib.PurePath", "pathlib.PosixPath"})
"""Calls joining their first argument's path with the string literals that follow."""
_FUNCTIONS = _SAME | _JOINING | {"os.path.dirname"}
_EDITS = frozenset({"insert", "append"})
_SHARE_LOOKUPS = frozenset({f"ament_index_python{where}.{function}"
                            for where in ("", ".packages")
                            for function in ("get_package_share_directory",
                                             "get_package_share_path")})
"""The package's share folder, which holds the folders the package installs there under
their source names (``launch/``): read as the package's root."""


def sys_path_edits(package: Package) -> dict[str, tuple[tuple[int, str], ...]]:
    """Module path -> (line, package-relative folder) of each ``sys.path.insert``/``append``
    of a folder of the package the module makes, for the modules that make any."""
    return _package_edits(package)[0]


def outside_edits(package: Package) -> dict[str, int]:
    """Module path -> the line of its first ``sys.path.insert``/``append`` of a folder above
    the package's own (``os.path.join(os.path.dirname(__file__), '..', '..', '..')``): what
    the module imports after it may come from the rest of the checkout."""
    return _package_edits(package)[1]


def vendored_edits(package: Package) -> dict[str, int]:
    """Module path -> the line of its first ``sys.path`` edit of a folder built from another
    module's file (``os.path.dirname(webots_ros2_importer.__file__)``): a folder of another
    installed package, which may hold a copy of any library (it vendors ``urdf2webots``)."""
    return _package_edits(package)[2]


@per_package
def _package_edits(package: Package) -> tuple[dict[str, tuple[tuple[int, str], ...]],
                                              dict[str, int], dict[str, int]]:
    inside: dict[str, tuple[tuple[int, str], ...]] = {}
    outside: dict[str, int] = {}
    vendored: dict[str, int] = {}
    launch = [f.python for f in package.launch_files if f.python is not None]
    for module in (*package.modules, *launch):
        text = package.texts.get(module.path)
        tree = parse_tree(module.path, text) if text and "sys.path" in text else None
        if not isinstance(tree, ast.Module):
            continue
        calls = list(_path_edits(tree))
        edits = list(_edits(tree, calls, module.path, package))
        own = tuple((line, folder) for line, folder in edits if folder is not None)
        if own:
            inside[module.path] = own
        above = [line for line, folder in edits if folder is None]
        if above:
            outside[module.path] = min(above)
        copies = [n.lineno for n in calls if _in_another_module(n.args[-1])]
        if copies:
            vendored[module.path] = min(copies)
    return inside, outside, vendored


def _path_edits(tree: ast.Module) -> Iterator[ast.Call]:
    """The ``sys.path.insert(...)``/``append(...)`` calls of the module."""
    aliases = _aliases(tree)
    for node in nodes_of(tree):
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and \
                node.func.attr in _EDITS and node.args and \
                _dotted(node.func.value, aliases) == "sys.path":
            yield node


def _edits(tree: ast.Module, calls: list[ast.Call], path: str, package: Package
           ) -> Iterator[tuple[int, str | None]]:
    """(line, package-relative folder) of each ``sys.path`` edit (``calls``) of a folder of
    the package, and (line, None) of each of a folder above the package's."""
    aliases = _aliases(tree)
    once = single_assignments(tree)
    for node in calls:
        folder = _path(node.args[-1], _Source(path, package.name), aliases, once, 0)
        relative = _relative(folder) if folder is not None else None
        if relative is not None and (relative == "" or any(
                f.startswith(relative + "/") for f in package.files)):
            yield node.lineno, relative
        elif folder is not None and relative is None:
            yield node.lineno, None


def _in_another_module(path: ast.expr) -> bool:
    """True for a path built from another module's file (``os.path.dirname(
    webots_ros2_importer.__file__)``): a folder of another installed package, which may
    hold any module (a copy of a library it vendors)."""
    return any(isinstance(n, ast.Attribute) and n.attr == "__file__" and
               isinstance(n.value, (ast.Name, ast.Attribute)) for n in ast.walk(path))


def file_relative_paths(tree: ast.Module, path: str) -> Iterator[tuple[ast.expr, str]]:
    """Each call or operation of the module at ``path`` that builds a path from its
    ``__file__`` (``os.path.join(os.path.dirname(__file__), 'sounds', 'x.mp3')``), with the
    package-relative path it evaluates to (none that leaves the package)."""
    aliases, once = _aliases(tree), single_assignments(tree)
    for node in nodes_of(tree):
        if isinstance(node, (ast.Call, ast.BinOp)):  # no package: no share folder stands in
            found = _path(node, _Source(path, ""), aliases, once, 0)
            relative = _relative(found) if found is not None else None
            if relative:
                yield node, relative


def _aliases(tree: ast.Module) -> dict[str, str]:
    """Name -> the dotted module or attribute its imports bind it to (``osp`` -> ``os.path``)."""
    found: dict[str, str] = {}
    for node in nodes_of(tree):
        if isinstance(node, ast.Import):
            for alias in node.names:
                if alias.asname:
                    found[alias.asname] = alias.name
                else:
                    top = alias.name.split(".")[0]
                    found[top] = top
        elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
            for alias in node.names:
                found[alias.asname or alias.name] = f"{node.module}.{alias.name}"
    return found


def _dotted(node: ast.expr, aliases: dict[str, str]) -> str | None:
    """``os.path.join`` for ``osp.join`` when ``import os.path as osp``; None if not a name."""
    parts: list[str] = []
    while isinstance(node, ast.Attribute):
        parts.append(node.attr)
        node = node.value
    if not isinstance(node, ast.Name):
        return None
    return ".".join([aliases.get(node.id, node.id), *reversed(parts)])


def _literal(node: ast.expr) -> str | None:
    """A relative path component written as a string literal (``"scripts"``, ``"../lib"``)."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str) and node.value \
            and not node.value.startswith("/"):
        return node.value
    return None


class _Source(NamedTuple):
    """The module whose ``sys.path`` edits are read, and the name of its package."""

    path: str
    package: str


def _path(node: ast.expr, file: _Source, aliases: dict[str, str], once: dict[str, ast.expr],
          depth: int) -> str | None:
    """The absolute path (under :data:`_ROOT`) ``node`` evaluates to, or None if unknown."""
    if depth > 20:
        return None
    here = (file, aliases, once, depth + 1)
    if isinstance(node, ast.Name):
        if node.id == "__file__":
            return f"{_ROOT}/{file.path}"
        value = once.get(node.id)
        return _path(value, *here) if value is not None else None
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Div):
        base, tail = _path(node.left, *here), _literal(node.right)
        return posixpath.join(base, tail) if base is not None and tail else None
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
        return _appended(_path(node.left, *here), node.right)
    if isinstance(node, ast.JoinedStr) and len(node.values) == 2 and \
            isinstance(node.values[0], ast.FormattedValue) and not node.values[0].format_spec \
            and node.values[0].conversion == -1:
        return _appended(_path(node.values[0].value, *here), node.values[1])
    if isinstance(node, ast.Attribute) and node.attr == "parent":
        base = _path(node.value, *here)
        return posixpath.dirname(posixpath.normpath(base)) if base is not None else None
    if isinstance(node, ast.Subscript) and isinstance(node.value, ast.Attribute) \
            and node.value.attr == "parents" and isinstance(node.slice, ast.Constant) \
            and type(node.slice.value) is int and node.slice.value >= 0:
        base = _path(node.value.value, *here)
        for _ in range((node.slice.value + 1) if base is not None else 0):
            base = posixpath.dirname(posixpath.normpath(base))
        return base
    if isinstance(node, ast.Call) and not node.keywords:
        return _called(node, here)
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return _checkout_path(node.value, file.package)
    return None


def _checkout_path(text: str, package: str) -> str | None:
    """The path under :data:`_ROOT` of an absolute path into the package's folder in a
    workspace's sources (``/home/ubuntu/ws/src/<package>/driver``: one checkout's), or None."""
    parts = posixpath.normpath(text).split("/")
    if not text.startswith("/") or "src" not in parts:
        return None
    below = parts[parts.index("src") + 1:]  # the package's folder: the first of its name
    return posixpath.join(_ROOT, *below[below.index(package) + 1:]) if package in below \
        else None


def _called(node: ast.Call, here: tuple[_Source, dict[str, str], dict[str, ast.expr], int]
            ) -> str | None:
    """The path a call returns: ``os.path`` functions, ``Path(...)``, ``str(...)`` and the
    path methods ``resolve``, ``absolute``, ``as_posix`` and ``joinpath``."""
    func, args = node.func, node.args
    name = _dotted(func, here[1])
    if name in _SHARE_LOOKUPS:  # share/<package> holds the package's folders, as installed
        own = len(args) == 1 and isinstance(args[0], ast.Constant) and \
            args[0].value == here[0].package
        return _ROOT if own else None
    if name in _FUNCTIONS:
        first = _path(args[0], *here) if args else None
        if name == "os.path.dirname":
            return posixpath.dirname(posixpath.normpath(first)) if first and len(args) == 1 \
                else None
        if name not in _SAME or len(args) > 1:
            return _joined(first, args[1:]) if name in _JOINING else None
        return first
    if isinstance(func, ast.Attribute) and \
            func.attr in ("resolve", "absolute", "joinpath", "as_posix"):
        base = _path(func.value, *here)
        return _joined(base, args) if func.attr == "joinpath" else None if args else base
    return None


def _appended(base: str | None, text: ast.expr) -> str | None:
    """``base + "/../lib"``: a path with a literal text starting with ``/`` added to it."""
    if base is None or not isinstance(text, ast.Constant) or not isinstance(text.value, str) \
            or not text.value.startswith("/"):
        return None
    return posixpath.normpath(base + text.value)


def _joined(base: str | None, parts: list[ast.expr]) -> str | None:
    tails = [_literal(part) for part in parts]
    if base is None or any(tail is None for tail in tails):
        return None
    return posixpath.join(base, *(t for t in tails if t))


def _relative(path: str) -> str | None:
    """The package-relative form of an absolute path under :data:`_ROOT` (``""`` for the
    root), None when it leaves the package."""
    normal = posixpath.normpath(path)
    if normal == _ROOT:
        return ""
    return normal[len(_ROOT) + 1:] if normal.startswith(_ROOT + "/") else None
