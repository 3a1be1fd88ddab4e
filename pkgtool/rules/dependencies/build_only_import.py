"""DEP002: installed code imports a package declared only as a build dependency."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.imports import BUILD_ONLY, declaration, declared, unmet_runtime_needs
from pkgtool.rules.registry import rule


@rule("DEP002", "import-declared-only-as-build-depend", Severity.ERROR,
      fix="Declare the package with `<depend>` (build and run) or add an `<exec_depend>`")
def import_declared_only_as_build_depend(package: Package) -> Iterator[Hit]:
    """Installed code imports a package that package.xml declares only for the build.

    ## What it does
    Reports imports in installed modules whose package or rosdep key appears only in
    `<build_depend>`, `<build_export_depend>` or `<buildtool_depend>`, never in `<depend>` or
    `<exec_depend>`. A module that only a `pytest11` entry point names is a pytest plugin,
    test code that runs where pytest runs; its imports are checked as test imports (DEP003).
    A key declared as `<buildtool_export_depend>` is right for code that runs while the
    packages depending on this one build (a rosidl generator, a CMake extension's Python
    helpers), and bloom installs it with the binary package: not reported.

    ## Why is this bad?
    Build dependencies are not installed with the binary package: an ament_python package
    imports its dependencies when it runs, not when it is built, so the import fails on
    every machine that installed the package instead of building it. A
    `<build_export_depend>` is installed with it, but not by `rosdep install -t exec`, which
    run-time images use: the import fails there.

    ## Example
    ```xml
    <build_depend>python3-numpy</build_depend>
    ```

    ## Use instead
    ```xml
    <depend>python3-numpy</depend>
    ```
    """
    build_only = declared(package, BUILD_ONLY - {"buildtool_export_depend"})
    for need in unmet_runtime_needs(package):
        key = next((k for k in need.keys if k in build_only), None)
        if key is None:
            continue
        dependency = build_only[key]
        tag, name = dependency.tag, dependency.name
        yield Hit(need.imported.span,
                  f"`{need.top}` is imported at run time but `{key}` is declared only as "
                  f"{declaration(key, dependency)}",
                  f"Change `<{tag}>{name}</{tag}>` to `<depend>{name}</depend>`")
