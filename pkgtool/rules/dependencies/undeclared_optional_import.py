"""DEP005: a guarded (optional) import that package.xml does not declare."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.python2_modules import PYTHON2_MODULES
from pkgtool.knowledge.rosdep import ROS1_PACKAGES
from pkgtool.model.package import Package
from pkgtool.rules.imports import ANY, all_python, declared, needs
from pkgtool.rules.registry import rule


@rule("DEP005", "undeclared-optional-import", Severity.INFO,
      fix="Declare the package if the feature that needs it matters on the robot")
def undeclared_optional_import(package: Package) -> Iterator[Hit]:
    """An optional import (`try/except ImportError`, `suppress(ImportError)`, `TYPE_CHECKING`,
    `find_spec`) is undeclared.

    ## What it does
    Reports guarded imports whose package or rosdep key package.xml does not declare in any
    dependency tag. The code is written to survive without the module, so this is
    information, not an error. An import in a function (or a class's `__init__`) that the
    module only calls (constructs) under `try/except Exception` with a fallback counts as
    guarded too, and so do the imports of an own module that the package only ever
    imports under such a guard (an optional back-end, like rqt_py_console's spyder
    console; not one the guard imports by its bare name and its handler by its package's,
    `from target_types import X` then `from my_pkg.target_types import X`: one of the
    two always runs), and so do an import inside a function of a distribution that
    `extras_require` of setup.py or setup.cfg lists (`def to_html(): import jinja2` with
    `extras_require={'html': ['Jinja2']}`: an optional feature's requirement), and
    imports under `if probe():`, where `probe` is a module function
    that tries an import and returns when it fails (`if in_notebook(): from
    IPython.display import display`). ROS 1 modules (`rospy`) guarded in a ROS 2 package
    are its ROS 1 code path (`if ROS_VERSION == 1:`, `except ImportError:`), and Python 2
    standard modules (`import Queue` beside `import queue`) its Python 2 one: there is
    nothing to declare.

    ## Why is this bad?
    Without a declaration the optional feature is silently off on every machine set up with
    rosdep, which is rarely what the author tested.

    ## Example
    ```python
    try:
        import cv2
    except ImportError:
        cv2 = None
    ```

    ## Use instead
    ```xml
    <exec_depend>python3-opencv</exec_depend>
    ```
    """
    available = declared(package, ANY)
    ros2 = package.manifest is not None and not package.manifest.is_ros1
    for module in all_python(package) if package.manifest else ():
        required = {need.top for need in needs(package, module)}
        for need in needs(package, module, guarded=True):
            if ros2 and need.top in ROS1_PACKAGES or need.top in PYTHON2_MODULES:
                continue  # a fallback for ROS 1, or for Python 2
            if need.top not in required and not any(k in available for k in need.keys):
                guess = " (a guess from the name)" if need.kind == "unknown" else ""
                yield Hit(need.imported.span,
                          f"Optional import `{need.top}` is not declared; its key is "
                          f"`{need.key}`{guess}",
                          f"Add `<exec_depend>{need.key}</exec_depend>` if the feature is needed")
