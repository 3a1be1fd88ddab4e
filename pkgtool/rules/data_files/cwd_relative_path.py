"""DAT017: code or a Python launch file opens a file of its package by a path relative to the
folder it is started in."""

from __future__ import annotations

import ast
import posixpath
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity, shortened
from pkgtool.lazy_regex import lazy_pattern
from pkgtool.model.ast_nodes import opens_to_write
from pkgtool.model.installed import installed_data
from pkgtool.model.launch import EXISTENCE_CHECKS
from pkgtool.model.modules import PythonModule
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.existence_checks import checks_files
from pkgtool.rules.imports import console_script_files, run_as_a_script, script_helpers
from pkgtool.rules.registry import rule
from pkgtool.rules.relative_paths import assigned_value, package_file_named
from pkgtool.rules.syntax_trees import Index, installed_trees, launch_indexes

READERS = frozenset({
    "io.open", "codecs.open", "cv2.imread",
    "cv2.VideoCapture", "cv2.CascadeClassifier", "cv2.dnn.readNet", "cv2.dnn.readNetFromONNX",
    "cv2.dnn.readNetFromCaffe", "cv2.dnn.readNetFromTensorflow", "cv2.dnn.readNetFromDarknet",
    "numpy.load", "numpy.loadtxt", "numpy.genfromtxt", "pandas.read_csv", "pandas.read_excel",
    "pandas.read_json", "torch.load", "torch.jit.load", "PIL.Image.open", "joblib.load",
    "ultralytics.YOLO", "onnxruntime.InferenceSession", "xml.etree.ElementTree.parse",
    "lxml.etree.parse", "xacro.process_file", "tensorflow.keras.models.load_model",
    "keras.models.load_model", "playsound.playsound", "pygame.mixer.Sound",
    "pygame.image.load", "sqlite3.connect", "scipy.io.loadmat",
    "open3d.io.read_point_cloud", "open3d.io.read_triangle_mesh", "trimesh.load"})
"""Functions and classes (by qualified name) whose first argument is a file they read."""
_PATHS = frozenset({"pathlib.Path", "pathlib.PurePath"})
_PATH_READS = frozenset({"read_text", "read_bytes", "open"})
"""Methods of a ``Path`` that read its file (a ``Path`` alone may be resolved elsewhere)."""
_SAME_PATH = frozenset({"os.path.abspath", "os.path.realpath", "os.path.normpath", *_PATHS})
"""Calls whose one argument is the path they give (``open(Path('x'))``; ``str()`` too)."""
_SETS_THE_FOLDER = EXISTENCE_CHECKS | {"chdir"}
"""Calls after which a relative path may well be right: the module asks whether the file is
there (and falls back), or changes the working folder first (``os.chdir(share)``)."""
_WRITES = frozenset("wax")
"""Characters of an ``open()`` mode that write (a file made where the node runs is its own)."""


@rule("DAT017", "cwd-relative-path", Severity.ERROR,
      fix="Install the file with data_files and open it from "
          "`get_package_share_directory('<package>')`")
def cwd_relative_path(package: Package) -> Iterator[Hit]:
    """Code or a Python launch file opens a file of its package by a path relative to the
    folder the process is started in.

    ## What it does
    Reports calls in installed modules and Python launch files that read a file (`open()` for
    reading, `Path(...).read_text()`, `cv2.imread`, `numpy.load`, `torch.load`, `ultralytics.YOLO`,
    `xacro.process_file`, `PIL.Image.open`, `yaml`'s stream from `open()`, ...) named by a
    relative path that is a file of the package's source folder: written from the
    package's folder (`'config/params.yaml'`) or from a workspace's
    (`'src/my_pkg/models/best.pt'`, a file the package has or not: a model kept out of
    git), from the module's own folder (`'colors.yaml'` for the `my_pkg/colors.yaml` beside
    `my_pkg/node.py`), or the path below `share/<package>` data_files installs a file as
    (`'map.json'` for `my_pkg/map.json` installed into `share/my_pkg`). The path is a
    string literal, or a name or `self.x` assigned that literal and nothing else. A module
    that asks whether files exist (`os.path.exists()` and the like) or changes the working
    folder (`os.chdir()`) is left alone: it may fall back when the file is not there, or
    open it from the right folder. Nor is a script kept in the package folder and run by hand
    from there (it runs code at its top, and no console script runs it, no module imports
    it: `python3 converter.py`), nor a helper only such scripts of its folder import (by its
    bare name: `from utils import load`): both run from that folder. Nor is a path a module
    of the package also opens to write (`open('data.json', 'w')`): a file nodes exchange
    where they run, of which the package's copy is a sample; nor an official Ultralytics
    model given to `YOLO()` (`'yolov8n.pt'`, `'yolo11s-seg.pt'`): Ultralytics downloads a
    missing one. Tests are not checked (pytest runs them from a known folder).

    ## Why is this bad?
    A relative path is resolved against the working folder of the process, not against the
    package: `python3 my_node.py` run from the package's folder finds the file, but `ros2
    run` and `ros2 launch` start the node wherever the user is, and the installed package
    has no source folder at all. The node (or the launch) then fails with
    `FileNotFoundError` on every machine but the author's habit.

    ## Example
    ```python
    with open('config/waypoints.yaml') as stream:
        waypoints = yaml.safe_load(stream)
    ```

    ## Use instead
    ```python
    share = get_package_share_directory('my_pkg')
    with open(os.path.join(share, 'config', 'waypoints.yaml')) as stream:
        waypoints = yaml.safe_load(stream)
    ```
    """
    scripts = console_script_files(package)
    helpers: dict[str, frozenset[str]] = {}  # by folder, worked out when first needed
    indexes = [(module.path, index) for module, _, index in installed_trees(package)
               if not _run_by_hand(package, module, scripts, helpers)]
    shares = _share_paths(package)
    installed_as = {below: source for source, below in shares.items()}
    written = {posixpath.normpath(text) for _, index in indexes for call in index.calls
               for text in _written_texts(call, index)}
    for path, index in [*indexes, *launch_indexes(package)]:
        if checks_files(index, _SETS_THE_FOLDER):
            continue
        for call in index.calls:
            read = _file_read(call, index)
            for text in _path_texts(read, index) if read is not None else ():
                if posixpath.normpath(text) in written:
                    continue  # a file the nodes exchange where they run: the copy a sample
                if index.qualified(call.func) == "ultralytics.YOLO" and \
                        _YOLO_ASSET.fullmatch(posixpath.basename(text)):
                    continue  # an official model: Ultralytics downloads it when it is missing
                named = _named(text.removeprefix("./"), package, installed_as) or \
                    _beside(path, text, package)
                if named is not None:
                    yield _hit(Span(path, call.lineno, call.col_offset + 1), call, text,
                               named, package.name, shares.get(named[0]),
                               _WHEN_MISSING.get(index.qualified(call.func) or ""))
                    break


def _named(text: str, package: Package, installed_as: dict[str, str]) -> tuple[str, str] | None:
    """The file of the package a relative path names (:func:`package_file_named`), or the one
    data_files installs as ``share/<package>/<path>`` (``open('map.json')`` for
    ``my_pkg/map.json``), with the folder the process must start in to find it."""
    named = package_file_named(text, package, absent=True)
    if named is not None:
        return named[0], "a workspace's folder" if named[1] else "the package's source folder"
    source = installed_as.get(posixpath.normpath(text)) if text else None
    if source is None or posixpath.isabs(text):
        return None
    below = posixpath.normpath(text)
    if source == below:
        return source, "the package's source folder"
    if source.endswith("/" + below):
        return source, f"`{source[:-len(below)]}` of the package's source folder"
    return source, f"`share/{package.name}` of the install folder"


def _beside(path: str, text: str, package: Package) -> tuple[str, str] | None:
    """The file beside the module at ``path`` a bare relative path names (``open('hsv.db')``
    in ``my_pkg/node.py`` for ``my_pkg/hsv.db``), with the folder the process must start in."""
    folder = posixpath.dirname(path)
    if not folder or not text or posixpath.isabs(text) or text.startswith(".."):
        return None
    beside = posixpath.normpath(posixpath.join(folder, text))
    return (beside, f"`{folder}/` of the package's source folder") \
        if package.has_file(beside) else None


def _file_read(call: ast.Call, index: Index) -> ast.expr | None:
    """The path argument of a call that reads a file: ``open()`` not given a mode that
    writes, one of :data:`READERS`, a ``Path(...)`` whose file is read at once
    (``Path('x').read_text()``); seen through ``str()``, ``Path()`` and ``os.path.abspath()``
    around it."""
    func = call.func
    if not call.args or not isinstance(func, (ast.Name, ast.Attribute)):
        return None
    if isinstance(func, ast.Name) and func.id == "open" and "open" not in index.bound:
        mode = call.args[1] if len(call.args) > 1 else \
            next((k.value for k in call.keywords if k.arg == "mode"), None)
        if mode is not None and not (isinstance(mode, ast.Constant) and
                                     isinstance(mode.value, str) and
                                     not _WRITES & set(mode.value)):
            return None
    elif index.qualified(func) in _PATHS:
        method = index.parents.get(id(call))
        if not (isinstance(method, ast.Attribute) and method.attr in _PATH_READS and
                isinstance(index.parents.get(id(method)), ast.Call)):
            return None
    elif index.qualified(func) not in READERS:
        return None
    argument = call.args[0]
    while isinstance(argument, ast.Call) and len(argument.args) == 1 and \
            isinstance(argument.func, (ast.Name, ast.Attribute)) and \
            (index.qualified(argument.func) in _SAME_PATH or
             isinstance(argument.func, ast.Name) and argument.func.id == "str"):
        argument = argument.args[0]
    return argument


def _written_texts(call: ast.Call, index: Index) -> list[str]:
    """The relative path an ``open()`` call writes (a mode with ``w``, ``a`` or ``x``)."""
    func = call.func
    if not (isinstance(func, ast.Name) and func.id == "open" and "open" not in index.bound and
            call.args and opens_to_write(call)):
        return []
    return [text for text in _path_texts(call.args[0], index) if not posixpath.isabs(text)]


def _path_texts(value: ast.expr, index: Index) -> list[str]:
    """The text ``value`` certainly holds (:func:`assigned_value`): a string literal."""
    value = assigned_value(value, index)
    return [value.value] if isinstance(value, ast.Constant) and isinstance(value.value, str) \
        else []


def _share_paths(package: Package) -> dict[str, str]:
    """Source file -> its path below ``share/<package>/``, for the files data_files
    installs there."""
    prefix = f"share/{package.name}/"
    return {source: installed.removeprefix(prefix)
            for installed, source in (installed_data(package) or {}).items()
            if installed.startswith(prefix)}


_YOLO_ASSET = lazy_pattern(
    r"yolo(?:v3(?:-tiny|-spp)?u|v5[nsmlx]6?u"
    r"|v8[nsmlx](?:-(?:seg|pose|obb|cls|oiv7|world|worldv2))?|v9[tsmce](?:-seg)?|v10[nsmblx]"
    r"|1[12][nsmlx](?:-(?:seg|pose|obb|cls))?)\.pt")
"""The names of the official Ultralytics models (``yolov8n.pt``, ``yolo11s-seg.pt``):
``YOLO(name)`` downloads a missing one into the path given, where the process runs."""
_WHEN_MISSING = {"sqlite3.connect": "sqlite3 makes a new, empty database there instead",
                 "cv2.imread": "cv2.imread returns None"}
"""Readers that do not raise FileNotFoundError for a missing file, with what they do."""


def _hit(span: Span, call: ast.Call, text: str, named: tuple[str, str], name: str,
         shared: str | None, missing: str | None) -> Hit:
    inside, folder = named
    message = (f"`{shortened(ast.unparse(call))}` opens `{text}` relative to the folder the "
               f"process starts in, not to the package: it finds the package's `{inside}` "
               f"only when started from {folder} (`ros2 run` and `ros2 launch` start it "
               "anywhere, and an installed package has no source folder: "
               f"{missing or 'FileNotFoundError'})")
    if shared is not None:
        parts = ", ".join(f"'{part}'" for part in shared.split("/"))
        return Hit(span, message, f"Open `os.path.join(get_package_share_directory('{name}'), "
                   f"{parts})`: data_files installs `{inside}` there")
    return Hit(span, message, f"Install `{inside}` with data_files into `share/{name}` and open "
               f"it from `get_package_share_directory('{name}')`")


def _run_by_hand(package: Package, module: PythonModule, scripts: frozenset[str],
                 helpers: dict[str, frozenset[str]]) -> bool:
    """True for a script kept in the package folder and run by hand from there, and for a
    helper only such scripts import (``helpers``: by folder, filled as asked)."""
    if run_as_a_script(package, module, scripts):
        return True
    folder = posixpath.dirname(module.path)
    if folder not in helpers:
        helpers[folder] = script_helpers(package, folder, scripts)
    return module.path in helpers[folder]
