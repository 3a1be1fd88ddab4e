"""DAT014: code, a launch file or a parameter file names a file in one user's home folder."""

from __future__ import annotations

import ast
import re
from collections.abc import Callable, Iterator

from pkgtool.findings import Hit, Severity, shortened
from pkgtool.model.ast_nodes import nodes_of_class, walk_once
from pkgtool.model.description_files import comment_kind, model_texts
from pkgtool.model.installed import installed_data, is_ament_python
from pkgtool.model.launch import EXISTENCE_CHECKS
from pkgtool.model.package import Package, is_test_material
from pkgtool.model.span import Span
from pkgtool.model.text_comments import without_comments
from pkgtool.records import replace
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import single_assignments
from pkgtool.rules.syntax_trees import Index, index_of, installed_trees, python_files
from pkgtool.lazy_regex import lazy_pattern

HOME_PATH = lazy_pattern(r"(?:(?<=file://)|(?<![\w.~$}/-]))"
                         r"(?:/home/(?!\$|\{)[\w.-]+|/Users/[\w.-]+|"
                         r"/root(?=/(?:[\w.-]+/)*?[\w.-]+/(?:src|install)/))/[\w.-]")
"""An absolute path (or a ``file://`` URI's) inside a named user's home folder (not
``/home/$USER/``), or into a colcon workspace's ``src`` or ``install`` folder in root's
(``/root/ros2_ws/src/...``: a container's; root's other files, ``/root/.bashrc``, are left
alone)."""
_PLACEHOLDER_HOME = lazy_pattern(r"(?<![\w.~$}/-])/home/<[\w.-]+>/[\w.-]")
"""A home folder left as a placeholder in code (``'/home/<username>/data'``): in a settings
file it is a template for the user to fill in, in code a path that never exists."""
_HINTS = ("/home/", "/Users/", "/root/")
_MESSAGES = frozenset({"print", "info", "warn", "warning", "error", "debug", "fatal", "log",
                       "exception", "critical", "write", "format", "add_argument"})
"""Calls whose text arguments are messages."""
_PATH_END = lazy_pattern(r"[\s\"'<>,;)\]}]")
_DATA_SUFFIXES = (".yaml", ".yml", ".xml", ".launch")


@rule("DAT014", "home-folder-path", Severity.WARNING,
      fix="Install the file and find it with `get_package_share_directory('<package>')`, or "
          "take the path as a parameter")
def home_folder_path(package: Package) -> Iterator[Hit]:
    """Code, a launch file or a parameter file names a file inside one user's home folder.

    ## What it does
    Reports absolute paths into a named user's home folder (`/home/alice/...`,
    `/Users/alice/...`, and root's into a workspace's `src` or `install` folder:
    `/root/ros2_ws/src/...`): string literals of installed modules and Python launch files (not
    docstrings, nor messages given to `print`, a logger, `argparse`, a launch argument's
    `description` or an exception raised; not a path the file asks exists, given to
    `os.path.exists()` and the like or bound to a name such a check is built from, as code that
    falls back when a machine lacks the file does), and values in XML and YAML launch files and
    in the YAML and XML files, robot descriptions, worlds and RViz settings (`.urdf`,
    `.xacro`, `.sdf`, `.world`, `.wbt`, `.rviz`: a mesh `file:///home/alice/...`) the
    package installs (not comments; in a package whose installed
    files are not known, those outside `doc`, `docs` and `example` folders and hidden ones: CI
    settings such as `.travis.yml` name the CI machine's home). In Python, also a path built
    from the home folder into a colcon workspace's `src` or `install` folder
    (`'~/ros2_ws/src/...'`, `os.path.join(os.getenv('HOME'), 'ws', 'src', ...)`,
    `f"{os.environ['HOME']}/ros2_ws/install/..."`, `Path.home() / 'ros2_ws/src/...'`; the home
    folder also through a name bound once to it, `HOME = os.path.expanduser('~')`). Also an
    absolute path outside home folders into a workspace's `src` folder through a folder named
    like this package or one of its workspace (`/team/ros_ws/src/my_pkg/...`: a lab machine's
    or a container's checkout). Tests and test data are left alone.

    ## Why is this bad?
    The path exists on the author's machine only: on a teammate's, a grader's, the robot's
    or in CI the node or the launch fails to find the file (`FileNotFoundError`, or a
    parameter file that is silently not loaded). Files the package needs belong in it,
    installed by data_files and found through its share folder.

    ## Example
    ```python
    params = '/home/alice/ros2_ws/src/my_robot/config/params.yaml'
    ```

    ## Use instead
    ```python
    params = os.path.join(get_package_share_directory('my_robot'), 'config', 'params.yaml')
    ```
    """
    checked = {module.path for module, _, _ in installed_trees(package)} | \
        {f.path for f in package.launch_files if f.kind == "python"}
    names = frozenset((package.name, *package.context.workspace))
    for path, _, tree in python_files(package, (*_HINTS, *_HOME_HINTS, _SRC)):
        if path in checked:
            index = index_of(tree)
            tested = _tested(tree, index)
            for hit, node in (*_python_paths(path, tree, names),
                              *_workspace_paths(path, tree, index)):
                if not tested(node):
                    yield hit
    shipped = _shipped(package)
    for path, text in sorted(package.texts.items()):
        if path.endswith(_DATA_SUFFIXES) and path != "package.xml" and shipped(path) and \
                not is_test_material(path) and any(h in text for h in (*_HINTS, _SRC)):
            yield from _text_paths(path, text, names)
    for path, text in model_texts(package).items():
        if shipped(path) and not is_test_material(path) and \
                any(h in text for h in (*_HINTS, _SRC)):
            uncommented = without_comments(text, comment_kind(path))
            yield from _first_of(list(_text_paths(path, uncommented, names)))


_ASIDE = frozenset({"doc", "docs", "example", "examples"})


def _shipped(package: Package) -> Callable[[str], bool]:
    """Whether a data file is one the package runs with: a launch file, a file data_files
    installs (in an ament_python package whose data_files evaluated), else any file outside
    documentation, examples and hidden files and folders (CI settings: `.travis.yml`,
    `.github/`)."""
    launch = {f.path for f in package.launch_files}
    installed = installed_data(package) if is_ament_python(package) else None
    if installed is not None:
        sources = launch | set(installed.values())
        return sources.__contains__
    return lambda path: path in launch or not (
        _ASIDE & set(path.split("/")[:-1]) or path.rpartition("/")[2].startswith("example") or
        any(part.startswith(".") for part in path.split("/")))  # CI settings: .travis.yml


def _python_paths(path: str, tree: ast.Module, names: frozenset[str]
                  ) -> Iterator[tuple[Hit, ast.AST]]:
    parents = walk_once(tree).parents
    for node in nodes_of_class(tree, ast.Constant):
        value = getattr(node, "value", None)
        found = (HOME_PATH.search(value) or _PLACEHOLDER_HOME.search(value) or
                 _source_tree(value, names)) if isinstance(value, str) else None
        if found is None or "\n" in value or _docstring(node, parents) or \
                _message(node, parents):
            continue
        yield _hit(Span(path, node.lineno, node.col_offset + 1), found.group(0), value), node


_SRC = "/src/"
_SOURCE_TREE = lazy_pattern(r"(?<![\w.~$}/-])/(?:[\w.-]+/)+?src/((?:[\w.-]+/)+)[\w.-]")
"""An absolute path into the ``src`` folder of a workspace (``/ws/src/my_pkg/map.pgm``)."""


def _source_tree(text: str, names: frozenset[str]) -> re.Match[str] | None:
    """The absolute path into a workspace's ``src`` folder in ``text`` that goes through a
    folder named like this package or one of its workspace (``/team/ws/src/my_pkg/...``,
    outside any home folder: a container's or a lab machine's checkout)."""
    found = _SOURCE_TREE.search(text)
    parts = found.group(0).split("/") if found else []
    return found if found and names & set(found.group(1).split("/")) and \
        not {".", ".."} & set(parts) else None


def _tested(tree: ast.Module, index: Index) -> Callable[[ast.AST], bool]:
    """Whether a path is one the module asks exists (``os.path.exists(path)``,
    ``Path(path).is_file()``), as code falling back when a machine lacks it does: given to
    the check, or bound to a name the check (or a name it is given) is built from, also
    through a list of candidates the check's name loops over."""
    checks = [call for call in index.calls if isinstance(call.func, ast.Attribute) and
              call.func.attr in EXISTENCE_CHECKS]
    if not checks:
        return lambda node: False
    parts = {id(n) for call in checks for given in (*call.args, call.func.value)  # type: ignore
             for n in ast.walk(given)}
    names = {n.id for call in checks for given in (*call.args, call.func.value)  # type: ignore
             for n in ast.walk(given) if isinstance(n, ast.Name)}
    values = list(_flows(tree))
    while True:  # the names a checked name is built from are checked too
        more = {n.id for name, value in values if name in names for n in ast.walk(value)
                if isinstance(n, ast.Name)} - names
        if not more:
            break
        names |= more
    held = {id(n) for name, value in values if name in names for n in ast.walk(value)}
    return lambda node: id(node) in parts or id(node) in held


_ADDING = frozenset({"append", "add", "extend", "insert", "appendleft"})


def _flows(tree: ast.Module) -> Iterator[tuple[str, ast.expr]]:
    """(name, what goes into it): ``name = value``, ``for name in value``, and
    ``name.append(value)`` (a list of candidate paths)."""
    for node in nodes_of_class(tree, ast.Assign, ast.For, ast.comprehension, ast.Call):
        if isinstance(node, ast.Assign):
            yield from ((t.id, node.value) for t in node.targets if isinstance(t, ast.Name))
        elif isinstance(node, (ast.For, ast.comprehension)) and \
                isinstance(node.target, ast.Name):
            yield node.target.id, node.iter
        elif isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and \
                node.func.attr in _ADDING and isinstance(node.func.value, ast.Name):
            yield from ((node.func.value.id, given) for given in node.args)


_HOME_HINTS = ("HOME", "~", "home()")
_HOME_CALLS = frozenset({"os.getenv", "os.environ.get", "os.path.expanduser", "pathlib.Path.home",
                         "os.path.expandvars"})
_WORKSPACE = lazy_pattern(r"^~?/?(?:[\w.-]+/)*?[\w.-]+/(?:src|install)(?:/|$)")
"""A path from the home folder into a colcon workspace's ``src`` or ``install`` folder."""


def _workspace_paths(path: str, tree: ast.Module, index: Index
                     ) -> Iterator[tuple[Hit, ast.AST]]:
    """Paths built from the home folder (``~/ros2_ws/src/...``, ``os.path.join(
    os.getenv('HOME'), 'ws', 'src', ...)``, an f-string starting with ``$HOME``) that go into
    a workspace's ``src`` or ``install`` folder: one user's checkout."""
    parents = walk_once(tree).parents
    homes = frozenset(name for name, value in single_assignments(tree).items()
                      if _is_home(value, index, frozenset()))
    for node in nodes_of_class(tree, ast.Constant, ast.Call, ast.JoinedStr, ast.BinOp):
        if isinstance(node, ast.BinOp) and _is_path_part(parents.get(id(node))):
            continue  # the outermost `/` of `Path.home() / 'ws' / 'src'` tells the whole path
        rest = _after_home(node, index, homes)
        if rest is not None and _WORKSPACE.match(rest) and \
                not _docstring(node, parents) and not _message(node, parents):
            shown = shortened(ast.unparse(node))
            yield Hit(Span(path, node.lineno, node.col_offset + 1),
                      f"`{shown}` is a file of the colcon workspace in one user's home folder "
                      f"(`~/{rest.lstrip('~/')}`): on any other machine, or with the "
                      "workspace elsewhere, the file is not there"), node


def _after_home(node: ast.AST, index: Index, homes: frozenset[str]) -> str | None:
    """What ``node`` adds to the home folder: the text of ``'~/x/y'``, of the parts of
    ``os.path.join(<home>, 'x', 'y')`` or of an f-string ``f'{<home>}/x/y'`` (``homes``: the
    names bound once to the home folder); None for anything else."""
    if isinstance(node, ast.Constant):
        value = node.value
        return value if isinstance(value, str) and value.startswith("~/") else None
    if isinstance(node, ast.Call) and index.qualified(node.func) == "os.path.join" and \
            node.args and _is_home(node.args[0], index, homes) and \
            all(isinstance(a, ast.Constant) and isinstance(a.value, str) for a in node.args[1:]):
        return "/".join(a.value.strip("/") for a in node.args[1:])  # type: ignore[attr-defined]
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Div):
        before = "" if _is_home(node.left, index, homes) else \
            _after_home(node.left, index, homes) if isinstance(node.left, ast.BinOp) else None
        if before is None or not (isinstance(node.right, ast.Constant) and
                                  isinstance(node.right.value, str)):
            return before  # `.../src' / package_name`: what is known of the path
        return f"{before}/{node.right.value.strip('/')}".lstrip("/")
    if isinstance(node, ast.JoinedStr) and len(node.values) >= 2 and \
            isinstance(node.values[0], ast.FormattedValue) and \
            _is_home(node.values[0].value, index, homes) and \
            isinstance(node.values[1], ast.Constant) and isinstance(node.values[1].value, str):
        return node.values[1].value.lstrip("/")
    return None


def _is_path_part(parent: ast.AST | None) -> bool:
    """True for the parent of a path that a longer path extends (``<path> / 'x'``)."""
    return isinstance(parent, ast.BinOp) and isinstance(parent.op, ast.Div)


def _is_home(node: ast.expr, index: Index, homes: frozenset[str]) -> bool:
    """True for ``os.getenv('HOME')``, ``os.environ['HOME']``, ``os.environ.get('HOME')``,
    ``os.path.expanduser('~')`` and ``Path.home()`` (also inside ``str()``), and a name of
    ``homes``."""
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and \
            node.func.id == "str" and len(node.args) == 1:
        node = node.args[0]
    if isinstance(node, ast.Name):
        return node.id in homes
    if isinstance(node, ast.Subscript):
        key = node.slice
        return index.qualified(node.value) == "os.environ" and \
            isinstance(key, ast.Constant) and key.value == "HOME"
    if not isinstance(node, ast.Call) or index.qualified(node.func) not in _HOME_CALLS:
        return False
    first = node.args[0] if node.args else None
    return first is None or isinstance(first, ast.Constant) and first.value in ("HOME", "~",
                                                                                "$HOME")


def _first_of(hits: list[Hit]) -> Iterator[Hit]:
    """The first of a file's hits, saying how many more there are: a world or a model saved
    by a simulator names every mesh by the same folder."""
    if len(hits) > 1:
        yield replace(hits[0], message=f"{hits[0].message} (and {len(hits) - 1} more such "
                                       "paths in the file)")
    else:
        yield from hits


def _text_paths(path: str, text: str, names: frozenset[str]) -> Iterator[Hit]:
    for number, line in enumerate(text.splitlines(), 1):
        stripped = line.strip()
        found = HOME_PATH.search(line) or _source_tree(line, names) \
            if not stripped.startswith(("#", "<!--")) else None
        if found is not None and "#" not in line[:found.start()]:
            end = _PATH_END.search(line, found.end())
            yield _hit(Span(path, number, found.start() + 1), found.group(0),
                       line[found.start():end.start() if end else len(line)])


def _hit(span: Span, start: str, value: str) -> Hit:
    shown = value if len(value) <= 80 else value[:77] + "..."
    if not start.startswith(_HINTS):
        return Hit(span, f"`{shown}` is in the source folder of one machine's workspace "
                   f"(`{start.partition('/src/')[0]}`): on any other machine the file is not "
                   "there")
    user = "root" if start.startswith("/root/") else start.split("/")[2]
    return Hit(span, f"`{shown}` is in the home folder of the user `{user}`: on any other "
               "machine the file is not there")


def _docstring(node: ast.AST, parents: dict[int, ast.AST]) -> bool:
    """True for a string statement (a docstring or a comment written as a string)."""
    return isinstance(parents.get(id(node)), ast.Expr)


def _message(node: ast.AST, parents: dict[int, ast.AST]) -> bool:
    """True for a string (or part of an f-string) given to one of :data:`_MESSAGES`, or to
    the exception a ``raise`` makes (``raise FileNotFoundError(f'tried {path}')``)."""
    parent = parents.get(id(node))
    if isinstance(parent, ast.JoinedStr):
        node, parent = parent, parents.get(id(parent))
    if isinstance(parent, ast.keyword):
        if parent.arg in ("help", "description"):  # argparse's, a launch argument's
            return True
        node, parent = parent, parents.get(id(parent))
    if not isinstance(parent, ast.Call) or node is parent.func:
        return False
    func = parent.func
    name = func.attr if isinstance(func, ast.Attribute) else \
        func.id if isinstance(func, ast.Name) else None
    return name in _MESSAGES or isinstance(parents.get(id(parent)), ast.Raise)
