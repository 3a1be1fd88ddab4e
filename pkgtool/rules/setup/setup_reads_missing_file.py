"""SET018: setup.py reads a file the package does not have."""

from __future__ import annotations

import ast
import posixpath
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.python_visitor import parse_tree
from pkgtool.model.span import Span
from pkgtool.model.submodules import ignored
from pkgtool.rules.existence_checks import checks_files
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import catches_everything
from pkgtool.rules.sys_path import file_relative_paths
from pkgtool.rules.syntax_trees import Index, index_of

_OPENERS = frozenset({"open", "io.open", "codecs.open"})
_PATH_READS = frozenset({"read_text", "read_bytes", "open"})
_PATHS = frozenset({"pathlib.Path", "Path"})
_LISTERS = frozenset({"os.listdir", "os.scandir"})
"""Calls listing a folder's entries, which raise FileNotFoundError for a missing folder
(``os.walk`` yields nothing instead)."""
_MISSING_FILE_ERRORS = frozenset({"OSError", "IOError", "FileNotFoundError", "EnvironmentError"})


def _literal(node: ast.expr | None) -> str | None:
    return node.value if isinstance(node, ast.Constant) and isinstance(node.value, str) \
        else None


def _read_paths(tree: ast.Module, index: Index) -> Iterator[tuple[ast.Call, str, bool]]:
    """Each call reading a file or listing a folder, with the package-relative path it names
    (a literal: setup.py runs in the package's folder, or a path built from ``__file__``) and
    whether it is a folder's."""
    built = {id(node): path for node, path in file_relative_paths(tree, "setup.py")}
    for call in index.calls:
        func = call.func
        target: ast.expr | None = None
        name = index.qualified(func) if isinstance(func, (ast.Name, ast.Attribute)) else None
        folder = name in _LISTERS or isinstance(func, ast.Attribute) and func.attr == "iterdir"
        if name in _LISTERS and call.args:
            target = call.args[0]
        elif (name in _OPENERS or isinstance(func, ast.Name) and func.id == "open") and \
                call.args and _reads(call):
            target = call.args[0]
        elif isinstance(func, ast.Attribute) and func.attr in _PATH_READS | {"iterdir"} and \
                isinstance(func.value, ast.Call) and func.value.args and \
                (index.qualified(func.value.func) or "") in _PATHS | {"pathlib.Path"}:
            target = func.value.args[0] if len(func.value.args) == 1 else None
        path = built.get(id(target)) if target is not None else None
        path = path or _literal(target)
        if path and not posixpath.isabs(path) and not path.startswith(("~", "$")):
            yield call, posixpath.normpath(path), folder


def _reads(call: ast.Call) -> bool:
    """True unless ``open()`` is given a mode that writes or creates."""
    mode = call.args[1] if len(call.args) > 1 else next(
        (k.value for k in call.keywords if k.arg == "mode"), None)
    text = _literal(mode) if mode is not None else "r"
    return text is not None and not set(text) & set("wax+")


def _tolerated(call: ast.Call, index: Index) -> bool:
    """True inside a ``try`` whose handler catches a missing file."""
    parent = index.parents.get(id(call))
    child: ast.AST = call
    while parent is not None:
        if isinstance(parent, ast.Try) and any(child is s for s in parent.body) and any(
                catches_everything(h) or _catches_missing(h) for h in parent.handlers):
            return True
        child, parent = parent, index.parents.get(id(parent))
    return False


def _catches_missing(handler: ast.ExceptHandler) -> bool:
    kinds = handler.type.elts if isinstance(handler.type, ast.Tuple) else [handler.type]
    return any(isinstance(k, ast.Name) and k.id in _MISSING_FILE_ERRORS or
               isinstance(k, ast.Attribute) and k.attr in _MISSING_FILE_ERRORS for k in kinds)


@rule("SET018", "setup-reads-missing-file", Severity.ERROR,
      fix="Add the file to the package, or stop reading it in setup.py")
def setup_reads_missing_file(package: Package) -> Iterator[Hit]:
    """setup.py reads a file that the package does not have.

    ## What it does
    Reports a file setup.py opens for reading (`open()`, `io.open()`, `codecs.open()`,
    `Path(...).read_text()`, `.read_bytes()`, `.open()`) by a literal path (relative to
    the package's folder, where colcon runs setup.py) or a path built from `__file__`
    (`os.path.join(os.path.dirname(__file__), 'README.md')`), when the package has no such
    file, and a folder it lists (`os.listdir('maps')`, `os.scandir()`, `Path(...).iterdir()`)
    when the package has no file in it: `install_requires=open('requirements.txt').read()
    .splitlines()` in a package without `requirements.txt`, a `long_description` read from a
    README never committed, data_files made from `os.listdir('maps')` with no map committed.
    Reads inside a `try` that catches a missing file (`OSError`, `FileNotFoundError`, or
    anything) and setup.py files asking whether files exist (`os.path.exists`) are left
    alone; so are files a `.gitignore` leaves out (made before the build).

    ## Why is this bad?
    colcon runs setup.py to build the package: it raises `FileNotFoundError` at once, and
    `colcon build` fails for the package (and every package that depends on it) on any
    machine but the author's.

    ## Example
    ```python
    setup(
        name=package_name,
        install_requires=open('requirements.txt').read().splitlines(),
    )
    ```

    ## Use instead
    ```python
    setup(
        name=package_name,
        install_requires=['setuptools'],
    )
    ```
    """
    text = package.texts.get("setup.py")
    tree = parse_tree("setup.py", text) if text else None
    if not isinstance(tree, ast.Module):
        return
    index = index_of(tree)
    if checks_files(index):
        return
    for call, path, folder in _read_paths(tree, index):
        if path.startswith("..") or ignored(path, package.ignores) or _tolerated(call, index) or \
                (path == "." or package.has_folder(path) if folder else package.has_file(path)):
            continue
        what = "lists the folder" if folder else "reads"
        yield Hit(Span("setup.py", call.lineno, call.col_offset + 1),
                  f"setup.py {what} `{path}`, which the package does not have: colcon runs "
                  "setup.py to build the package, and it raises FileNotFoundError")
