"""DAT006: a file an installed launch file reads from share/<package> is not installed."""

from __future__ import annotations

import ast
import posixpath
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import is_main_test, nodes_of_class
from pkgtool.model.installed import installed_data, installed_modules
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.data_files.common import uninstalled_launch_resources
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, launch_trees


@rule("DAT006", "uninstalled-launch-resource", Severity.ERROR,
      fix="Install the file with data_files, e.g. `(os.path.join('share', package_name, "
          "'config'), glob('config/*.yaml'))`")
def uninstalled_launch_resource(package: Package) -> Iterator[Hit]:
    """An installed launch file or module uses a file of the package's share it does not install.

    ## What it does
    For each launch file data_files installs, and each installed module that imports
    `ament_index_python`, looks at the paths it builds from this package's share folder
    (`get_package_share_directory('<pkg>')`, `FindPackageShare`, `$(find-pkg-share <pkg>)`
    joined with static parts, e.g. `config/params.yaml`) and reports those that data_files
    does not install (neither the file nor a folder holding it) while the package has them.
    A file the package does not have at all is DAT012's. Paths that are glob patterns
    (`config/*.yaml`) count when installed files match them, and a module that asks whether
    files exist (`os.path.exists`, `Path.exists()`: it handles a missing one) is left alone;
    in a launch file only the paths it asks that of are (all of them when it asks of a path
    pkgtool cannot work out). A folder holding only hidden files (`output/.gitkeep`: where
    the code writes) has nothing to install. An installed Python launch file that puts its
    folder on `sys.path` (it mentions both) and imports a module kept beside it
    (`launch/helpers.py`) is reported when data_files does not install that module beside
    it.

    ## Why is this bad?
    The launch file starts, then fails on the missing parameter file, URDF or RViz config,
    or a node silently runs with default parameters; a node reading the file dies with
    `FileNotFoundError` once installed, though it worked from the source tree.

    ## Example
    ```python
    params = os.path.join(get_package_share_directory('my_pkg'), 'config', 'params.yaml')
    # setup.py installs launch/ but not config/
    ```

    ## Use instead
    ```python
    (os.path.join('share', package_name, 'config'), glob('config/*.yaml')),
    ```
    """
    share = f"share/{package.name}"
    for reader, ref, relative, _ in uninstalled_launch_resources(package):
        if package.has_file(relative) or package.has_folder(relative) and \
                not _placeholder_folder(package, relative):
            yield Hit(ref.span, f"`{relative}` is not installed to `{share}`, but "
                                f"`{reader}` uses it")
    yield from _uninstalled_helpers(package)


def _uninstalled_helpers(package: Package) -> Iterator[Hit]:
    """Modules beside an installed Python launch file that it imports (its folder put on
    ``sys.path``) and that data_files does not install beside it."""
    installed = installed_data(package) or {}
    places = {source: posixpath.dirname(target) for target, source in installed.items()}
    own = {name.split(".")[0] for name in installed_modules(package) or {}}
    for path, tree, index in launch_trees(package):
        folder = posixpath.dirname(path)
        where = places.get(path)
        text = package.texts.get(path) or ""
        if where is None or "__file__" not in text or "sys.path" not in text:
            continue  # not installed (DAT005's), or its folder is not put on sys.path
        first = min((n.lineno for n in nodes_of_class(tree, ast.Attribute)
                     if isinstance(n, ast.Attribute) and n.attr == "path" and
                     isinstance(n.value, ast.Name) and n.value.id == "sys"), default=0)
        for node, name in _top_imports(tree):
            if node.lineno < first or name in own or name in _LOADED or any(
                    isinstance(p, ast.Try) or isinstance(p, ast.If) and is_main_test(p.test)
                    for p in _parents(node, index)):
                continue  # found before sys.path grows; installed code; launch's own (loaded
                # by `ros2 launch`); optional; or run only as a script
            helper = next((f for f in (posixpath.join(folder, f"{name}.py"),
                                       posixpath.join(folder, name, "__init__.py"))
                           if package.has_file(f)), None)
            target = posixpath.join(where, posixpath.relpath(helper, folder)) if helper else ""
            if helper is not None and target not in installed:
                yield Hit(Span(path, node.lineno, node.col_offset + 1),
                          f"`{path}` imports `{name}` from `{helper}`, which data_files does "
                          f"not install beside it in `{where}`: the installed launch file "
                          f"fails with ModuleNotFoundError (it works only with "
                          f"`--symlink-install`)",
                          f"Install `{helper}` into `{where}` too")


_LOADED = frozenset({"launch", "launch_ros", "launch_xml", "launch_yaml", "launch_testing",
                     "launch_testing_ros", "ament_index_python", "rclpy"})
"""Packages `ros2 launch` has imported before it runs a launch file: a module of the same
name beside the file is never the one imported."""


def _parents(node: ast.AST, index: Index) -> Iterator[ast.AST]:
    parent = index.parents.get(id(node))
    while parent is not None:
        yield parent
        parent = index.parents.get(id(parent))


def _top_imports(tree: ast.Module) -> Iterator[tuple[ast.stmt, str]]:
    """The absolute imports of a module with the top-level name each imports."""
    for node in nodes_of_class(tree, ast.Import, ast.ImportFrom):
        if isinstance(node, ast.Import):
            yield from ((node, alias.name.split(".")[0]) for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and not node.level and node.module:
            yield node, node.module.split(".")[0]


def _placeholder_folder(package: Package, path: str) -> bool:
    """True for a folder holding only hidden files (``output/.gitkeep``): kept in git for
    what the code writes there, nothing to install."""
    prefix = path.rstrip("/") + "/"
    return all(f.rpartition("/")[2].startswith(".") for f in package.files
               if f.startswith(prefix))
