"""DAT015: installed code reads a data file next to its own source, which setup.py does not
install there."""

from __future__ import annotations

import ast
import posixpath
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.ast_nodes import is_main_test, last_name, nodes_of_class, opens_to_write
from pkgtool.model.installed import installed_data, installed_modules, is_ament_python
from pkgtool.model.package import Package
from pkgtool.model.setup_py import PACKAGE_DATA
from pkgtool.model.span import Span
from pkgtool.rules.existence_checks import checks_files
from pkgtool.rules.imports import run_as_a_script
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import ALWAYS, scope_bindings
from pkgtool.rules.sys_path import file_relative_paths
from pkgtool.rules.syntax_trees import Index, installed_trees

_CODE = (".py", ".pyc", ".so", ".pyd")
"""Suffixes of what setuptools installs with a Python package (or builds into it)."""
_TOLERANT = frozenset({"QIcon", "QPixmap", "QImage", "QMovie", "setWindowIcon", "setPixmap"})
"""Qt calls that take a missing file for an empty image instead of raising."""
_WRITES = frozenset({"savefig", "imwrite", "save", "savez", "savez_compressed", "savetxt",
                     "to_csv", "to_json", "write_image", "write_html", "imsave"})
"""Calls whose path argument is a file they write (a plot, an image, an array, a table)."""
_DEPTH = 6
"""How many names and local functions deep a path is followed to where it is used."""


def _never_read(node: ast.AST, index: Index, depth: int = 0) -> bool:
    """True when the path ``node`` builds is never read as a file: it goes only to
    :data:`_TOLERANT` Qt calls (a missing icon shows nothing), or to calls that write it
    (``plt.savefig(path)``, ``open(path, 'w')``), itself or through a name every read of which
    does (a function's local name nothing reads, a literal list holding it, too), or a
    parameter of a function of the module every read of which does."""
    parent = index.parents.get(id(node))
    if depth > _DEPTH:
        return False  # followed far enough (names may pass the path round in a loop)
    if isinstance(parent, ast.Call) and node in parent.args:
        called = last_name(parent.func)
        return called in _TOLERANT or called in _WRITES or called == "open" and \
            opens_to_write(parent) or _parameter_never_read(
                parent, parent.args.index(node), index, depth + 1)
    if isinstance(parent, (ast.List, ast.Tuple)) and any(node is e for e in parent.elts):
        return _never_read(parent, index, depth + 1)  # read only as the list is
    if not (isinstance(parent, ast.Assign) and len(parent.targets) == 1 and
            isinstance(parent.targets[0], ast.Name)):
        return False
    name = parent.targets[0].id
    function = index.enclosing_function(node)
    local = function is not None and scope_bindings(function)[name] < ALWAYS  # not `global`
    return _reads_never_read(name, index.module_of(node), index, depth + 1, unread=local)


def _parameter_never_read(call: ast.Call, position: int, index: Index, depth: int) -> bool:
    """True when ``call`` calls a function the module defines once, whose parameter at
    ``position`` is only ever used as a path that is never read."""
    if not isinstance(call.func, ast.Name) or \
            any(isinstance(a, ast.Starred) for a in call.args[:position]):
        return False
    defined = [f for f in index.functions if f.name == call.func.id and
               index.enclosing_class(f) is None]
    if len(defined) != 1 or defined[0].args.vararg is not None:
        return False
    function = defined[0]
    parameters = [*function.args.posonlyargs, *function.args.args]
    return position < len(parameters) and _reads_never_read(
        parameters[position].arg, function, index, depth)


def _reads_never_read(name: str, scope: ast.AST, index: Index, depth: int,
                      unread: bool = False) -> bool:
    """True when every read of ``name`` in ``scope`` never reads the path as a file; when
    nothing reads the name, ``unread`` (True for a local name of a function)."""
    reads = [n for n in nodes_of_class(scope, ast.Name)
             if isinstance(n, ast.Name) and n.id == name and isinstance(n.ctx, ast.Load)]
    return (bool(reads) or unread) and all(_never_read(read, index, depth) for read in reads)


def _in_main_block(node: ast.AST, index: Index) -> bool:
    """True for a node inside a module-level ``if __name__ == '__main__':`` block: it runs
    only when the file runs as a script, never when a console script imports its module."""
    child, parent = node, index.parents.get(id(node))
    while parent is not None:
        if isinstance(parent, ast.If) and is_main_test(parent.test) and \
                any(child is statement for statement in parent.body) and \
                isinstance(index.parents.get(id(parent)), ast.Module):
            return True
        child, parent = parent, index.parents.get(id(parent))
    return False


@rule("DAT015", "file-beside-module-not-installed", Severity.ERROR,
      fix="Install the file with data_files into `share/<package>` and find it with "
          "`get_package_share_directory('<package>')`")
def file_beside_module(package: Package) -> Iterator[Hit]:
    """Installed code reads a data file found from its own `__file__` that setup.py does not
    install there.

    ## What it does
    Evaluates the paths installed modules build from `__file__`
    (`os.path.join(os.path.dirname(__file__), 'sounds', 'siren.mp3')`,
    `Path(__file__).parent / 'model.pt'`, also through a name assigned once) and reports one
    that names a file of the package (not Python code) which the install does not put
    there: a file outside the package's Python packages (`<module>/../config/x.yaml`, the
    package root's `config/`), or one inside them when setup.py has no `package_data` nor
    `include_package_data`. Modules that ask whether paths exist (`os.path.exists`) are left
    alone, as are files of a name data_files copies into `site-packages` itself, scripts
    kept in the package folder (code at their top level that no console script runs, no
    module imports and data_files does not copy: run as `python3 path/to/it.py` from the
    sources), and reads in a module's `if __name__ == '__main__':` block (it runs only
    when the file runs as a script, from the sources, unless data_files copies it), paths
    only shown as images by Qt (`QIcon(path)`, `QPixmap(path)`: a missing file makes an
    empty image, no error) and paths only written (`plt.savefig(path)`, `open(path, 'w')`,
    `cv2.imwrite(path, image)`, also through a function of the module taking the path), and
    paths a function keeps in a local name nothing reads, alone or in a list (a candidate
    left over after the code switched to `get_package_share_directory`).

    ## Why is this bad?
    `colcon build --symlink-install` runs the sources in place, so the file is found; a plain
    `colcon build` (a grader's, a robot's, CI's) installs only the `.py` files into
    `site-packages`, and the node fails with `FileNotFoundError` when it reads the file.

    ## Example
    ```python
    sound = os.path.join(os.path.dirname(__file__), 'sounds', 'siren.mp3')
    ```

    ## Use instead
    ```python
    # setup.py: data_files=[('share/' + package_name + '/sounds', ['sounds/siren.mp3'])]
    sound = os.path.join(get_package_share_directory('my_pkg'), 'sounds', 'siren.mp3')
    ```
    """
    setup = package.setup_py
    if setup is None or not is_ament_python(package) or \
            any(keyword in setup.keywords for keyword in PACKAGE_DATA) or \
            setup.is_unresolved("data_files") or setup.is_unresolved("**"):
        return
    into_site = {posixpath.basename(match) for entry in setup.data_files or ()
                 if "site-packages" in entry.destination for source in entry.sources
                 for match in source.matches}  # files data_files copies beside the modules
    folders = {posixpath.dirname(file) for file in (installed_modules(package) or {}).values()}
    files = set(package.files)
    copied = set((installed_data(package) or {}).values())
    for module, tree, index in installed_trees(package):
        if "__file__" not in package.texts.get(module.path, "") or checks_files(index) or \
                run_as_a_script(package, module) and module.path not in copied:
            continue
        seen: set[str] = set()
        for node, path in file_relative_paths(tree, module.path):
            if path in seen or path not in files or path.endswith(_CODE) or \
                    posixpath.basename(path) in into_site or _never_read(node, index) or \
                    module.path not in copied and _in_main_block(node, index):
                continue
            seen.add(path)
            inside = any(path.startswith(f"{folder}/") for folder in folders if folder)
            where = "in the Python package, where setuptools installs only its `.py` files" \
                if inside else "outside the Python packages, which is not installed"
            yield Hit(Span(module.path, node.lineno, node.col_offset + 1),
                      f"`{path}` is read next to the module (from `__file__`), but it is "
                      f"{where}: it works only with `colcon build --symlink-install`, and a "
                      "plain build fails with FileNotFoundError")
