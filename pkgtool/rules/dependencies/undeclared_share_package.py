"""DEP011: installed code looks up a package (its share folder, its prefix) that package.xml
does not declare, or that no package has as its name."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.launch_python import read_python_launch
from pkgtool.model.package import Package
from pkgtool.rules.imports import RUNTIME, console_script_files, declared
from pkgtool.rules.package_lookups import unlisted_packages
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees


@rule("DEP011", "undeclared-share-package", Severity.ERROR,
      fix="Add an `<exec_depend>` for the package to package.xml, or fix its name")
def undeclared_share_package(package: Package) -> Iterator[Hit]:
    """Installed code looks up another package that package.xml does not declare.

    ## What it does
    Collects the packages installed modules (not tests, not launch files: LCH002 checks
    those) name in `get_package_share_directory('pkg')`, `get_package_prefix('pkg')`,
    `get_package_share_path('pkg')` or `FindPackageShare('pkg')` with a literal name, and
    reports each one other than this package that is no `<exec_depend>` or `<depend>` (nor
    brought in by a declared metapackage); a name that is no package of the target's release
    nor of the packages linted with it is said so, with the package it is a typo of, if any
    (a node copied from another package, still looking up that package's name). A lookup in
    a `try` that catches `PackageNotFoundError` (or `KeyError`, `Exception`, anything), or
    after checking that the package is installed, is optional and left alone, and so is a
    workspace package that depends on this one (declaring it would make a cycle). Modules
    importing `launch` that no console script runs and that define no
    `generate_launch_description` are libraries of launch helpers (a
    `DeclareLaunchArgument` subclass finding each robot's description package): the launch
    files using them look the packages up, and their packages declare them.

    ## Why is this bad?
    The lookup raises `PackageNotFoundError` when the node starts on a machine where the
    package is not installed: rosdep installs only what package.xml declares, and a name no
    package has fails everywhere.

    ## Example
    ```python
    # in package `yolo`, copied from `perception`
    weights = os.path.join(get_package_share_directory('perception'), 'weights.pt')
    ```

    ## Use instead
    ```python
    weights = os.path.join(get_package_share_directory('yolo'), 'weights.pt')
    ```
    """
    if package.manifest is None:
        return
    available = declared(package, RUNTIME)
    scripts = console_script_files(package)
    for module, tree, index in installed_trees(package):
        if not (index.imports_from("ament_index_python") or index.imports_from("launch_ros")) \
                or _launch_helpers(module.path, index, scripts):
            continue
        lookups = read_python_launch(module.path, tree)[1]
        used = [(p.package, p.span) for p in lookups if not p.optional and not p.unused]
        yield from unlisted_packages(package, used, available, "the package's code")


def _launch_helpers(path: str, index: Index, scripts: frozenset[str]) -> bool:
    """True for a library of launch helpers: a module importing ``launch`` that is no launch
    file itself (no ``generate_launch_description``) and that no console script runs; the
    launch files of its users look the packages up (each declares those of its robot)."""
    return index.imports_from("launch") and path not in scripts and \
        not index.defines_function("generate_launch_description")
