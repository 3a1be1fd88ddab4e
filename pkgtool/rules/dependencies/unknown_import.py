"""DEP004: an import that is neither a known ROS package nor a curated Python module."""

from __future__ import annotations

from collections.abc import Iterable, Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.knowledge.ros_names import looks_like_ros
from pkgtool.knowledge.python2_modules import python3_name
from pkgtool.knowledge.rosdep import ROS1_PACKAGES
from pkgtool.knowledge.rosdistro import is_released_package, modules_of_key
from pkgtool.model.installed import installed_modules
from pkgtool.model.modules import Import, PythonModule
from pkgtool.rules.imports import (ANY, also_imported, declared, grouped, installed_code,
                                   needs, released_for, source_path_module)
from pkgtool.rules.registry import rule
from pkgtool.rules.test_modules import test_files
from pkgtool.lazy_regex import lazy_pattern


@rule("DEP004", "unknown-import", Severity.WARNING,
      fix="Declare the rosdep key that installs the module (check it with `rosdep resolve`)")
def unknown_import(package: Package) -> Iterator[Hit]:
    """A module is imported that pkgtool cannot map to a rosdep key.

    ## What it does
    Reports unguarded absolute imports (in installed modules, tests and Python launch files;
    not in files colcon never installs, such as firmware or offline scripts) of names that
    are not standard library (of the target distribution's Python), not the package's own
    (for test code, also a helper module in a folder pytest puts on `sys.path`; for any
    file, a module of a folder of the package that the file, or a `conftest.py` above a
    test, puts on `sys.path` before the import with a path built from `__file__`:
    `sys.path.insert(0, str(Path(__file__).resolve().parents[1] / 'scripts'))`,
    `sys.path.append(os.path.join(os.path.dirname(__file__), '..', 'scripts'))`), not ROS
    (released for the target distribution, or ROS by name), and not a module that rosdep's
    data maps to a key (the pip and Debian names in rosdistro's `python.yaml`), unless a key
    that looks like it (`python3-<name>`, `python3-<name>-pip` or the bare name) is
    declared. The suggested key is a guess from the module name; for a ROS package that
    another distribution releases (`tiago_description` on Jazzy) the finding says so and names
    the package instead. ROS 1 modules (`rospy`,
    `tf`) and Python 2 standard modules (`Queue`, `urllib2`) are reported as such, and so
    is the name of a package of the workspace that installs no Python package (a CMake
    package without `ament_python_install_package`).

    ## Why is this bad?
    An import that package.xml does not cover fails on a clean machine, but pip and rosdep
    names often differ from import names (`cv2` is `python3-opencv`), so pkgtool cannot tell
    which key is missing, only that one probably is.

    A Python package of another package of the same workspace (linted in the same run, or
    under the same colcon `src` folder) maps to that package (DEP001 then wants it declared),
    and so does the Python package rosidl generates for a workspace interface package (its
    name, whatever it looks like).

    A package declaring a ROS package of Python bindings (named `..._python`, `..._py`,
    `python_...`, `...pybind...`) that none of its imports is known to use gets no finding
    for an import named with words of that package's name: such a package's module is often
    named otherwise (`rmf_fleet_adapter_python` installs `rmf_adapter`).

    ## Example
    ```python
    from filterpy.kalman import KalmanFilter  # pkgtool guesses `python3-filterpy`
    ```

    ## Use instead
    The key rosdep really has (`rosdep resolve`, or rosdistro's rosdep/python.yaml):
    ```xml
    <exec_depend>python3-filterpy-pip</exec_depend>
    ```
    """
    if package.manifest is None:
        return
    available = declared(package, ANY)
    bindings = _unused_bindings(package, available)
    for modules in _by_kind(package):
        unknown = (need for module in modules for need in needs(package, module)
                   if need.kind == "unknown" and not any(k in available for k in need.keys)
                   and source_path_module(package, module, need.imported) is None
                   and not any(_words(need.top) <= words for words in bindings))
        for need, others in grouped(unknown):
            related = tuple(other.imported.span for other in others)
            if need.top in package.context.workspace and need.top != package.name:
                yield Hit(need.imported.span,
                          f"`{need.top}` is a package of the workspace, but it installs no "
                          f"Python package of that name{also_imported(others)}: the import "
                          "raises ModuleNotFoundError",
                          f"Install `{need.top}`'s Python code (`ament_python_install_package("
                          f"{need.top})` in a CMake package), or import what it does install",
                          related)
            elif (own := _renamed_own_module(package, need.imported)) is not None:
                yield Hit(need.imported.span,
                          f"`{need.top}` is no known package, but `{need.imported.module}` "
                          f"is this package's `{own}` under another name (the package's "
                          "former name?): the import raises ModuleNotFoundError"
                          f"{also_imported(others)}", f"Import `{own}`", related)
            elif (python3 := python3_name(need.top)) is not None:
                yield Hit(need.imported.span, f"`{need.top}` is a Python 2 standard module: "
                          f"Python 3 has {python3} instead, and the import raises "
                          f"ModuleNotFoundError{also_imported(others)}", f"Import {python3}",
                          related)
            elif need.top in ROS1_PACKAGES:
                yield Hit(need.imported.span, f"`{need.top}` is a ROS 1 module: ROS 2 does not "
                          f"have it{also_imported(others)}",
                          f"Port the code to {ROS1_PACKAGES[need.top]}", related)
            elif elsewhere := released_for(need.top):
                yield Hit(need.imported.span,
                          f"`{need.top}` is a ROS package released for {', '.join(elsewhere)}"
                          f" but not for {package.context.distro}, the target"
                          f"{also_imported(others)}: on {package.context.distro} it must be "
                          "built from source in the workspace",
                          f"Declare `<exec_depend>{need.top}</exec_depend>` and build "
                          f"`{need.top}` from source, or target a distribution that releases "
                          "it (`--rosdistro`)", related)
            else:
                yield Hit(need.imported.span,
                          f"`{need.top}` is not a known ROS package or Python module; its "
                          f"rosdep key might be `{need.key}` (a guess from the name)"
                          f"{also_imported(others)}",
                          f"Declare the key that installs `{need.top}`, e.g. "
                          f"`<exec_depend>{need.key}</exec_depend>` if `rosdep resolve "
                          f"{need.key}` knows it", related)


def _renamed_own_module(package: Package, imported: Import) -> str | None:
    """The module of this package that ``imported`` names under another top-level name
    (``from p3_ekf_adr.motion_models import predict`` in ``ekf_estimator``, which installs
    ``ekf_estimator.motion_models`` defining ``predict``), or None. Not a module that imports
    from that other name itself: it wraps the other project's module of the same name
    (``kompass.actions`` extends ``ros_sugar.actions``)."""
    top, _, rest = imported.module.partition(".")
    installed = installed_modules(package) or {}
    modules = {module.path: module for module in package.modules}
    wanted = set(imported.names) - {"*"}
    return next((name for name in sorted(installed) if rest and name.partition(".")[2] == rest
                 and (module := modules.get(installed[name])) is not None
                 and wanted <= module.top_level_names
                 and not any(i.top_level == top for i in module.imports)), None)


_BINDING = lazy_pattern(r"(?:^|_)py(?:thon)?3?(?:_|$)|pybind")
"""How ROS packages of Python bindings are named (``rmf_fleet_adapter_python``, ``tf2_ros_py``,
``python_qt_binding``): their module is often named otherwise (``rmf_adapter``)."""


def _unused_bindings(package: Package, available: Iterable[str]) -> list[frozenset[str]]:
    """The words of each declared ROS package named as a Python binding, whose modules pkgtool
    does not know, that no import it knows uses: an unknown import named with some of those
    words (``rmf_adapter`` of ``rmf_fleet_adapter_python``) may be its module."""
    bindings = {key for key in available if _BINDING.search(key) and not modules_of_key(key)
                and not key.startswith("ament_")
                and (looks_like_ros(key) or is_released_package(key, package.context.distro))}
    if not bindings:
        return []
    used = {key for module in package.modules for need in needs(package, module)
            for key in need.keys if need.kind != "unknown"}
    return [_words(key) - _BINDING_WORDS for key in bindings - used]


_BINDING_WORDS = frozenset({"py", "python", "python3", "pybind", "pybind11", "binding",
                            "bindings"})


def _words(name: str) -> frozenset[str]:
    """The lower-case words of a snake-case name."""
    return frozenset(word for word in name.lower().split("_") if word)


def _by_kind(package: Package) -> tuple[list[PythonModule], ...]:
    """Installed code, tests and launch files: one finding per unknown name and kind of
    file (code colcon never installs, firmware or an offline script, needs no key)."""
    launch = [f.python for f in package.launch_files if f.python]
    tests = test_files(package)
    return (installed_code(package), [m for m in package.modules if m.path in tests], launch)
