"""DAT023: code hands a path starting with ``~`` to a function that never expands it."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity, shortened
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.relative_paths import assigned_value
from pkgtool.rules.syntax_trees import Index, installed_trees, launch_indexes

TAKE_PATHS = frozenset({
    "io.open", "codecs.open", "os.open", "os.makedirs", "os.mkdir", "os.listdir", "os.scandir",
    "os.remove", "os.unlink", "os.rmdir", "os.rename", "os.replace", "os.chdir", "os.stat",
    "os.access", "os.path.exists", "os.path.isfile", "os.path.isdir", "os.path.getsize",
    "os.path.getmtime", "shutil.copy", "shutil.copy2", "shutil.copyfile", "shutil.copytree",
    "shutil.move", "shutil.rmtree", "glob.glob", "glob.iglob", "cv2.imread", "cv2.imwrite",
    "cv2.VideoCapture", "cv2.VideoWriter", "numpy.load", "numpy.save", "numpy.savez",
    "torch.load", "torch.save", "sqlite3.connect", "logging.FileHandler",
    "PIL.Image.open"})
"""Functions (by qualified name) whose first argument is a path they use as it is: none
expands ``~`` (pandas' readers, which do, are not here)."""
_PATH_METHODS = frozenset({"open", "read_text", "read_bytes", "write_text", "write_bytes",
                           "mkdir", "touch", "exists", "is_file", "is_dir", "iterdir", "glob",
                           "rglob", "unlink", "rmdir", "stat"})
"""Methods of a ``pathlib.Path`` that use its path as it is (``expanduser`` is not one)."""
_JOINS = frozenset({"os.path.join", "os.path.abspath", "os.path.normpath", "pathlib.Path",
                    "pathlib.PurePath"})
"""Calls whose first argument starts the path they give."""


@rule("DAT023", "unexpanded-home-path", Severity.ERROR,
      fix="Expand the path first: `os.path.expanduser('~/...')` or `Path('~/...').expanduser()`")
def unexpanded_home_path(package: Package) -> Iterator[Hit]:
    """Code hands a path starting with `~` to a function that does not expand it.

    ## What it does
    Reports calls in installed modules and Python launch files that open, create, list, test
    or remove a file or folder (`open()`, `os.makedirs()`, `os.path.exists()`, `shutil.*`,
    `glob.glob()`, `cv2.imwrite()`, `numpy.save()`, `torch.load()`, `sqlite3.connect()`, a
    `pathlib.Path`'s `mkdir()`, `open()`, `write_text()`, ...) whose path starts with `~/` (or
    is `~`): a string literal, an f-string or a `+` that starts with one, an `os.path.join()`
    or `Path()` whose first part is one (also through `/`), or a name or `self.x` assigned
    such a value and nothing else; the path given as the first argument or by keyword
    (`filename=`), or as the `Path` whose method is called (`self.folder.mkdir()`).

    ## Why is this bad?
    Only a shell expands `~`: Python, OpenCV and NumPy take `~/captures/run1` as a relative
    path into a folder literally named `~` in the folder the node was started in. Reading
    fails with `FileNotFoundError` (or `os.path.exists()` is always False); writing quietly
    creates `./~/captures/run1` wherever `ros2 run` or `ros2 launch` happened to start the
    node, and the home folder never gets the files.

    ## Example
    ```python
    self.out_dir = '~/captures'
    os.makedirs(self.out_dir, exist_ok=True)
    ```

    ## Use instead
    ```python
    self.out_dir = os.path.expanduser('~/captures')
    os.makedirs(self.out_dir, exist_ok=True)
    ```
    """
    indexes = [(module.path, index) for module, _, index in installed_trees(package)
               if "~" in package.texts.get(module.path, "~")]
    for path, index in [*indexes, *launch_indexes(package)]:
        for call in index.calls:
            argument = _path_argument(call, index)
            start = _home_start(argument, index, 4) if argument is not None else None
            if start is not None:
                yield Hit(Span(path, call.lineno, call.col_offset + 1),
                          f"`{shortened(ast.unparse(call))}` uses `{start}` as it is: Python "
                          "never expands `~`, so the path is a folder named `~` in the folder "
                          "the node is started in, not the home folder")


def _path_argument(call: ast.Call, index: Index) -> ast.expr | None:
    """The path a call of :data:`TAKE_PATHS` (or of the built-in ``open``) uses (its first
    argument, or a path keyword), or the path of a ``Path`` whose method uses it at once
    (``Path(p).mkdir()``, ``self.folder.mkdir()`` for ``self.folder = Path(p)``)."""
    func = call.func
    if isinstance(func, ast.Name) and func.id == "open" and "open" not in index.bound or \
            isinstance(func, (ast.Name, ast.Attribute)) and index.qualified(func) in TAKE_PATHS:
        return call.args[0] if call.args else \
            next((k.value for k in call.keywords if k.arg in _PATH_KEYWORDS), None)
    if isinstance(func, ast.Attribute) and func.attr in _PATH_METHODS:
        return _path_of(func.value, index, 4)
    return None


_PATH_KEYWORDS = frozenset({"file", "filename", "fname", "name", "path", "src", "database"})
"""Keywords that name the path of a :data:`TAKE_PATHS` call given no positional argument."""


def _path_of(value: ast.expr, index: Index, depth: int) -> ast.expr | None:
    """The first part of the path a ``pathlib.Path`` value is made of: the argument of
    ``Path(...)``, also through a name or ``self.x`` given it and through ``/``."""
    value = assigned_value(value, index)
    if depth == 0:
        return None
    if isinstance(value, ast.BinOp) and isinstance(value.op, ast.Div):
        return _path_of(value.left, index, depth - 1)
    if isinstance(value, ast.Call) and value.args and \
            isinstance(value.func, (ast.Name, ast.Attribute)) and \
            index.qualified(value.func) in ("pathlib.Path", "pathlib.PurePath"):
        return value.args[0]
    return None


def _home_start(value: ast.expr, index: Index, depth: int) -> str | None:
    """The text starting with ``~`` the path ``value`` certainly begins with, or None."""
    value = assigned_value(value, index)
    if depth == 0:
        return None
    if isinstance(value, ast.Constant) and isinstance(value.value, str):
        text = value.value
        return text if text == "~" or text.startswith("~/") else None
    if isinstance(value, ast.JoinedStr) and value.values:
        return _home_start(value.values[0], index, depth - 1)
    if isinstance(value, ast.BinOp) and isinstance(value.op, ast.Add):
        return _home_start(value.left, index, depth - 1)
    if isinstance(value, ast.BinOp) and isinstance(value.op, ast.Div):
        first = _path_of(value, index, depth - 1)
        return _home_start(first, index, depth - 1) if first is not None else None
    if isinstance(value, ast.Call) and value.args and \
            isinstance(value.func, (ast.Name, ast.Attribute)) and \
            (index.qualified(value.func) in _JOINS or
             isinstance(value.func, ast.Name) and value.func.id == "str"):
        return _home_start(value.args[0], index, depth - 1)
    return None
