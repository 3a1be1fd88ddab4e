"""DEP001: installed code imports a package or module that package.xml does not declare."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.manifest import Dependency
from pkgtool.model.package import Package
from pkgtool.rules.dependency_names import names_module, unknown_dependencies
from pkgtool.rules.imports import (BUILD_ONLY, TEST, Need, also_imported, declared,
                                   dependency_cause, grouped, misnamed, misspelt_package,
                                   no_package_named, unmet_runtime_needs)
from pkgtool.rules.package_lookups import depends_on
from pkgtool.rules.registry import rule


@rule("DEP001", "undeclared-import", Severity.ERROR,
      fix="Add an `<exec_depend>` (or `<depend>`) for the imported package to package.xml")
def undeclared_import(package: Package) -> Iterator[Hit]:
    """Installed code imports a package that package.xml does not declare for run time.

    ## What it does
    Checks every absolute, unguarded import in the modules setup.py installs (a module the
    package itself imports only inside `try/except ImportError` is optional, and so is an
    import inside a function of a distribution `extras_require` lists: see DEP005).
    Standard library modules (of the target distribution's Python) and the package's own
    modules are skipped; a ROS import must be covered by `<depend>` or `<exec_depend>` of its
    package (`tf2_ros` by `tf2_ros_py`, not the C++ `tf2_ros`), the Python package of a
    workspace package by that package (also where rosdep has a `python3-x-pip` key for it), and
    a third-party module by one of the rosdep keys that rosdep's data says install it (`cv2` by
    `python3-opencv`, `rosdistro` by `python3-rosdistro-modules`, `pyflakes` by `pyflakes3`,
    ...). A namespace several distributions share is matched by its member: `google.auth` by
    `python3-google-auth`, `google.cloud.storage` by its own key, `google.protobuf` by
    `python3-protobuf`. One finding stands for each missing declaration: modules whose
    suggested key is the same (`matplotlib` and `mpl_toolkits`, both `python3-matplotlib`) are
    reported together at the first import, their other imports listed. A module the package
    declares under a key rosdep does not know but written for it (`python3-torch-pip-shim`
    for `torch`, a key of a private rosdep source) is MAN022's: one mistake, one finding.
    Modules that only a
    `pytest11` entry point names are pytest plugins, checked as test code (DEP003). Without a
    setup.py at the root (ament_cmake) the modules inside Python package folders count as
    installed, only those under what CMakeLists.txt installs when its `install()`,
    `ament_python_install_package` and `ament_auto_package` calls are read statically (a
    generator run at build time or a helper the tests put on `PYTHONPATH` is not installed
    code). A folder below the root with its own setup.py or pyproject.toml is a separate
    Python project (a pip-installable client library): its files are never the package's
    installed code, and its top-level modules count as the package's own. A module of another
    Python project of the workspace without package.xml (a pip project kept in the checkout)
    is named by the name colcon gives it (setup.py's); rosdep knows no such key, so the help
    says so and `--fix` leaves the choice to the user. A workspace package that depends on
    this one (itself or through others) is not reported: declaring it would make a cycle
    colcon cannot order.

    ## Why is this bad?
    `rosdep install` and the binary packages built by the ROS buildfarm install only what
    package.xml declares. The node works on the machine it was written on and fails with
    `ModuleNotFoundError` on a clean robot or in CI.

    ## Example
    ```python
    import tf_transformations  # package.xml declares rclpy and sensor_msgs only
    ```

    ## Use instead
    ```xml
    <exec_depend>tf_transformations</exec_depend>
    ```
    """
    build_only = declared(package, BUILD_ONLY)
    tests = declared(package, TEST)
    unknown = [u.dependency.name for u in unknown_dependencies(package) if not u.close]
    unmet = (need for need in unmet_runtime_needs(package)  # not DEP004's, DEP002's cases
             if need.kind != "unknown" and not any(k in build_only for k in need.keys) and
             not any(names_module(key, need.imported.top_level) for key in unknown) and
             not depends_on(package, need.key))
    for need, others in grouped(unmet, by_key=True):
        meant = misspelt_package(package, need)
        if meant is not None:
            yield Hit(need.imported.span,
                      f"`{need.top}` is imported but {no_package_named(package)} (did you mean "
                      f"`{meant}`?): the import raises ModuleNotFoundError"
                      f"{also_imported(others)}",
                      f"Write `{meant}`", related=tuple(other.imported.span for other in others))
            continue
        tops = _first_per_module((need, *others))
        owner = package.context.workspace.get(need.key)
        yield Hit(need.imported.span,
                  _message(package, tops, tests) + also_imported(others, naming=len(tops) > 1),
                  f"Add `<exec_depend>{need.key}</exec_depend>` to package.xml" if
                  owner is None or owner.manifest else
                  f"Give `{owner.folder.rsplit('/', 1)[-1]}` a package.xml, or add "
                  f"`<exec_depend>{need.key}</exec_depend>` and run rosdep with `--skip-keys "
                  f"{need.key}` (colcon builds that Python project, rosdep knows no such key)",
                  related=tuple(other.imported.span for other in others),
                  cause="" if need.key in tests else dependency_cause(need.key),
                  consequence=True)


def _first_per_module(found: tuple[Need, ...]) -> list[Need]:
    """The first need of each top-level module, in order."""
    firsts: dict[str, Need] = {}
    for need in found:
        firsts.setdefault(need.top, need)
    return list(firsts.values())


def _message(package: Package, tops: list[Need], tests: dict[str, Dependency]) -> str:
    """What ``tops`` (needs of one key, one per module) lack, and why a declared name does not
    provide them."""
    need = tops[0]
    if len(tops) == 1:
        subject, key = f"`{need.top}` is", f"`{need.key}`"
    else:
        names = [f"`{n.top}`" for n in tops]
        subject = f"{', '.join(names[:-1])} and {names[-1]} are"
        key = f"`{need.key}`, which provides them,"
    if need.key in tests:
        return f"{subject} imported by installed code but {key} is only a `test_depend`"
    missing = need.missing if len(tops) == 1 else f"{key} is not declared in package.xml"
    text = f"{subject} imported but {missing}"
    wrong = dict.fromkeys(filter(None, (misnamed(package, n) for n in tops)))
    if wrong:
        text += f" ({'; '.join(wrong)})"
    return text
