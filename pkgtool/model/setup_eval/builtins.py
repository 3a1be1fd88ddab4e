"""The allow-list: modules, functions and methods the evaluator computes (all without I/O).

File-system questions (glob, isfile, find_packages) are answered from the package's file list.
"""

from __future__ import annotations

import ast
import glob as globlib
import posixpath
from pathlib import PurePosixPath
from typing import TYPE_CHECKING, Any

from pkgtool.model.setup_eval.bounds import bounded_format, bounded_join, bounded_replace
from pkgtool.model.setup_eval.tree import normalize, spelled_as_written
from pkgtool.model.setup_eval.values import (
    PRIMITIVES, BoundMethod, Builtin, Found, GlobOrigin, PathValue, Str, UserFunc, origins_of,
    tagged_list, tagged_str, tagged_tuple,
)

if TYPE_CHECKING:
    from pkgtool.model.setup_eval.evaluator import Interpreter

SETUP_FUNCTIONS = frozenset({"setuptools.setup", "distutils.core.setup"})
MODULES = frozenset({"os", "os.path", "glob", "pathlib", "setuptools", "distutils",
                     "distutils.core", "sys"})
CONSTANTS = {"os.sep": "/", "os.path.sep": "/", "os.curdir": ".", "os.path.curdir": "."}

_STR_METHODS = frozenset({
    "format", "join", "replace", "strip", "lstrip", "rstrip", "split", "rsplit", "lower",
    "upper", "startswith", "endswith", "removeprefix", "removesuffix", "splitlines",
    "partition", "rpartition", "count", "find", "title", "capitalize",
})
_LIST_METHODS = frozenset({"append", "extend", "insert", "copy", "index", "count", "sort",
                           "reverse"})
_DICT_METHODS = frozenset({"get", "items", "keys", "values", "copy", "update", "setdefault"})
_PATH_METHODS = frozenset({"glob", "rglob", "joinpath", "as_posix", "is_file", "is_dir",
                           "exists", "with_suffix", "with_name", "relative_to"})
_PATH_PROPERTIES = frozenset({"name", "stem", "suffix", "parent", "parts"})


def text(interp: Interpreter, value: Any, node: ast.AST) -> str:
    """A path-like argument as a string (str or pathlib path)."""
    if isinstance(value, (str, PathValue)):
        return str(value)
    raise interp.refuse(node)


def formattable(interp: Interpreter, value: Any, node: ast.AST) -> Any:
    """``value`` as plain scalars/containers for %-formatting and str.format."""
    if isinstance(value, PathValue):
        return str(value)
    if isinstance(value, PRIMITIVES):
        return value
    if isinstance(value, (list, tuple)):
        return tuple(formattable(interp, item, node) for item in value)
    if isinstance(value, dict):
        return {k: formattable(interp, v, node) for k, v in value.items()}
    raise interp.refuse(node)


def join_paths(interp: Interpreter, left: Any, right: Any, node: ast.AST) -> PathValue:
    """``left / right`` with at least one pathlib path."""
    return PathValue(PurePosixPath(text(interp, left, node)) / text(interp, right, node))


def _relative(interp: Interpreter, value: Any, node: ast.AST) -> str:
    path = normalize(text(interp, value, node))
    if path is None:
        raise interp.refuse(node)
    return path


def _glob(interp: Interpreter, pattern: Any, node: ast.AST, *, recursive: bool) -> list[Str]:
    written = text(interp, pattern, node)
    origin = GlobOrigin(_relative(interp, written, node), interp.span(node))
    slash = "/" if written.endswith("/") and origin.pattern else ""
    found = interp.guard(lambda: interp.tree.glob(origin.pattern + slash, recursive=recursive),
                         node)
    spelled = spelled_as_written(written, found)
    if spelled is None or recursive and not found and origin.pattern.endswith("**"):
        # glob('missing/**', recursive=True) is ['missing/'] in CPython, not []
        raise interp.refuse(node)
    items = [tagged_str(path, origin.span, origin) for path in spelled]
    return tagged_list(items, origin.span, (origin,))


def _path_glob(interp: Interpreter, base: PathValue, pattern: Any, node: ast.AST) -> list[Any]:
    joined = posixpath.join(str(base), text(interp, pattern, node))
    origin = GlobOrigin(_relative(interp, joined, node), interp.span(node))
    found = interp.guard(lambda: interp.tree.glob(origin.pattern, recursive=True, hidden=True,
                                                  dirs_only_at_end=True), node)
    items = [PathValue(PurePosixPath(path), origin) for path in found]
    return tagged_list(items, origin.span, (origin,))


def _finder(interp: Interpreter, args: list[Any], kwargs: dict[str, Any], node: ast.Call,
            kind: str) -> Found:
    names = ("where", "exclude", "include")
    if len(args) > 3 or set(kwargs) - set(names):
        raise interp.refuse(node)
    given = dict(zip(names, args)) | kwargs
    where = text(interp, given.get("where", "."), node)
    patterns = {key: tuple(text(interp, p, node) for p in interp.iterate(given[key], node))
                for key in ("exclude", "include") if key in given}
    exclude, include = patterns.get("exclude", ()), patterns.get("include", ("*",))
    found = Found(interp.guard(lambda: interp.tree.find_packages(
        where, include, exclude, namespace=kind == "find_namespace_packages"), node))
    found.span, found.kind, found.where = interp.span(node), kind, where
    found.include, found.exclude = include, exclude
    return found


def _sequence(interp: Interpreter, args: list[Any], node: ast.Call, make: Any) -> Any:
    if len(args) > 1:
        raise interp.refuse(node)
    items = interp.iterate(args[0], node) if args else []
    return make(items, interp.span(node), origins_of(*args))


def _sort_key(value: Any) -> Any:
    return value.pure if isinstance(value, PathValue) else value


def _str(interp: Interpreter, args: list[Any], node: ast.Call) -> str:
    if not args:
        return ""
    value = args[0]
    if len(args) == 1 and isinstance(value, PathValue):
        return tagged_str(str(value), interp.span(node), value.glob)
    if len(args) == 1 and isinstance(value, PRIMITIVES):
        return value if isinstance(value, str) else str(value)
    raise interp.refuse(node)


def _path_call(interp: Interpreter, name: str, args: list[Any], node: ast.Call) -> Any:
    tree, path = interp.tree, normalize(text(interp, args[0], node)) if args else None
    if path is None:
        raise interp.refuse(node)
    return {"isfile": tree.is_file, "isdir": tree.is_dir,
            "exists": lambda p: tree.is_file(p) or tree.is_dir(p)}[name](path)


_PURE_OS_PATH = {"join": posixpath.join, "dirname": posixpath.dirname,
                 "basename": posixpath.basename, "normpath": posixpath.normpath,
                 "splitext": posixpath.splitext, "split": posixpath.split,
                 "isabs": posixpath.isabs}


def call(interp: Interpreter, function: Any, args: list[Any], kwargs: dict[str, Any],
         node: ast.Call) -> Any:
    """Dispatch a call to the allow-list; anything else is refused."""
    if isinstance(function, BoundMethod):
        return _method(interp, function, args, kwargs, node)
    if isinstance(function, UserFunc):
        return interp.call_user(function, args, kwargs, node)  # type: ignore[attr-defined]
    if not isinstance(function, Builtin):
        raise interp.refuse(node)
    name = function.name.removeprefix("setuptools.")
    if name in ("find_packages", "find_namespace_packages"):
        return _finder(interp, args, kwargs, node, name)
    if name in ("glob.glob", "glob.iglob"):
        if len(args) != 1 or set(kwargs) - {"recursive"}:
            raise interp.refuse(node)
        return _glob(interp, args[0], node, recursive=bool(kwargs.get("recursive")))
    if kwargs and name not in ("sorted", "dict", "print"):
        raise interp.refuse(node)
    if name.startswith("os.path.") and name[8:] in _PURE_OS_PATH:
        strings = [text(interp, a, node) for a in args]
        return interp.guard(lambda: _PURE_OS_PATH[name[8:]](*strings), node)
    if name in ("os.path.isfile", "os.path.isdir", "os.path.exists"):
        return _path_call(interp, name[8:], args, node)
    if name == "glob.escape" and len(args) == 1:
        return globlib.escape(text(interp, args[0], node))
    if name == "pathlib.Path" or name == "pathlib.PurePath":
        return PathValue(PurePosixPath(*(text(interp, a, node) for a in args)))
    return _builtin(interp, name, args, kwargs, node)


def _builtin(interp: Interpreter, name: str, args: list[Any], kwargs: dict[str, Any],
             node: ast.Call) -> Any:
    if name == "str":
        return _str(interp, args, node)
    if name in ("list", "sorted"):
        if set(kwargs) - {"reverse"}:
            raise interp.refuse(node)
        result = _sequence(interp, args, node, tagged_list)
        if name == "sorted":
            interp.guard(lambda: interp.budget.charge(len(result) * 17), node)
            interp.guard(lambda: result.sort(key=_sort_key, reverse=bool(kwargs.get("reverse"))),
                         node)
        return result
    if name == "tuple":
        return _sequence(interp, args, node, tagged_tuple)
    if name in ("set", "frozenset"):
        return interp.guard(lambda: set(interp.iterate(args[0], node) if args else ()), node)
    if name == "dict":
        return interp.guard(lambda: dict(*args, **kwargs), node)
    if name == "print":
        return None
    simple = {"len": len, "range": range, "bool": bool, "int": int, "min": min, "max": max,
              "any": any, "all": all, "enumerate": lambda *a: list(enumerate(*a)),
              "zip": lambda *a: list(zip(*a)), "reversed": lambda a: list(reversed(a))}
    if name in simple and all(not isinstance(a, (PathValue, Builtin)) for a in args):
        if name == "range" and interp.guard(lambda: len(range(*args)), node) > 100_000:
            raise interp.refuse(node)
        interp.guard(lambda: interp.budget.charge(sum(len(a) for a in args
                                                      if hasattr(a, "__len__"))), node)
        return interp.guard(lambda: simple[name](*args), node)
    raise interp.refuse(node)


def attribute(interp: Interpreter, base: Any, name: str, node: ast.Attribute) -> Any:
    """``base.name`` for known modules, pathlib paths and methods of evaluated data."""
    if isinstance(base, Builtin) and base.name in MODULES:
        qualified = f"{base.name}.{name}"
        if qualified in CONSTANTS:
            return CONSTANTS[qualified]
        if qualified in MODULES or qualified in SETUP_FUNCTIONS or is_function(qualified):
            return Builtin(qualified)
    elif isinstance(base, PathValue):
        if name in _PATH_PROPERTIES:
            value = getattr(base.pure, name)
            return PathValue(value) if isinstance(value, PurePosixPath) else value
        if name in _PATH_METHODS:
            return BoundMethod(base, name)
    elif (isinstance(base, str) and name in _STR_METHODS or
          isinstance(base, list) and name in _LIST_METHODS or
          isinstance(base, dict) and name in _DICT_METHODS):
        return BoundMethod(base, name)
    raise interp.refuse(node)


def is_function(qualified: str) -> bool:
    """True for module functions on the allow-list (``os.path.join``, ``glob.glob``, ...)."""
    short = qualified.removeprefix("setuptools.")
    return (short in ("find_packages", "find_namespace_packages", "glob.glob", "glob.iglob",
                      "glob.escape", "pathlib.Path", "pathlib.PurePath",
                      "os.path.isfile", "os.path.isdir", "os.path.exists")
            or qualified.startswith("os.path.") and qualified[8:] in _PURE_OS_PATH)


def _method(interp: Interpreter, method: BoundMethod, args: list[Any], kwargs: dict[str, Any],
            node: ast.Call) -> Any:
    value, name = method.value, method.name
    if isinstance(value, PathValue):
        return _path_method(interp, value, name, args, node)
    if isinstance(value, str):
        return _str_method(interp, str(value), name, args, kwargs, node)
    interp.guard(lambda: interp.budget.charge(len(value)), node)
    if isinstance(value, list) and name == "extend" and len(args) == 1:
        items = interp.iterate(args[0], node)
        interp.guard(lambda: interp.budget.size(len(value) + len(items)), node)
        value.extend(items)
        if hasattr(value, "origins"):
            value.origins = origins_of(value, args[0])
        return None
    if name == "sort" and (kwargs or args):
        raise interp.refuse(node)
    if isinstance(value, list) and name in ("append", "insert"):
        interp.guard(lambda: interp.budget.size(len(value) + 1), node)
    result = interp.guard(lambda: getattr(value, name)(*args, **kwargs), node)
    if name in ("items", "keys", "values"):
        return tagged_list(list(result), interp.span(node))
    return result


def _str_method(interp: Interpreter, value: str, name: str, args: list[Any],
                kwargs: dict[str, Any], node: ast.Call) -> Any:
    plain_args = [formattable(interp, a, node) for a in args]
    plain_kwargs = {k: formattable(interp, v, node) for k, v in kwargs.items()}
    budget = interp.budget
    if name == "join":
        if len(args) != 1 or kwargs:
            raise interp.refuse(node)
        raw = interp.iterate(args[0], node)
        sizes = [len(i) if isinstance(i, str) else 4096 for i in raw]
        interp.guard(lambda: bounded_join(budget, value, sizes), node)
        return value.join([text(interp, i, node) for i in raw])
    if name == "format":
        return interp.guard(lambda: bounded_format(budget, value, plain_args, plain_kwargs),
                            node)
    if name == "replace" and not kwargs:
        return interp.guard(lambda: bounded_replace(budget, value, plain_args), node)
    interp.guard(lambda: budget.charge(len(value)), node)
    return interp.guard(lambda: getattr(value, name)(*plain_args, **plain_kwargs), node)


def _path_method(interp: Interpreter, path: PathValue, name: str, args: list[Any],
                 node: ast.Call) -> Any:
    if name in ("glob", "rglob") and len(args) == 1:
        pattern = text(interp, args[0], node)
        return _path_glob(interp, path, pattern if name == "glob" else "**/" + pattern, node)
    if name == "as_posix" and not args:
        return tagged_str(str(path), interp.span(node), path.glob)
    if name in ("is_file", "is_dir", "exists") and not args:
        return _path_call(interp, {"is_file": "isfile", "is_dir": "isdir"}.get(name, name),
                          [path], node)
    strings = [text(interp, a, node) for a in args]
    result = interp.guard(lambda: getattr(path.pure, name)(*strings), node)
    return PathValue(result) if isinstance(result, PurePosixPath) else result
