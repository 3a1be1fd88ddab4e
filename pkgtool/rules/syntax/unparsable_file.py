"""SYN001: a package file that does not parse."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.cmake_text import commands
from pkgtool.model.installed import cmake_text, installed_files
from pkgtool.model.manifest import CMAKE_BUILD_TYPES
from pkgtool.model.package import Package
from pkgtool.model.span import ParseProblem
from pkgtool.rules.plain_projects import plain_python_project
from pkgtool.rules.registry import rule
from pkgtool.rules.ros1_platform import is_python2_package, is_ros1_package
from pkgtool.lazy_regex import lazy_pattern
from pkgtool.rules.syntax._newer_syntax import newer_syntax
from pkgtool.rules.syntax._problems import problem_hits, set_aside, stray_yaml

_PARSE_KINDS = {
    "xml-syntax": "XML is not well-formed",
    "python-syntax": "Python syntax error",
    "yaml-syntax": "YAML syntax error",
    "cfg-syntax": "setup.cfg syntax error",
}


@rule("SYN001", "unparsable-file", Severity.ERROR,
      fix="Fix the syntax at the reported line and column")
def unparsable_file(package: Package) -> Iterator[Hit]:
    """A package file (package.xml, setup.py, setup.cfg, a module, a launch file) does not parse.

    ## What it does
    Reports XML that is not well-formed, Python with a syntax error, YAML (launch and
    parameter files) or setup.cfg that does not parse, at the line and column the parser gave.
    A YAML file of an ament_python package that data_files does not install and no other
    file of the package names (a log, a numpy dump saved as `.yaml`, an old copy) is SYN008's
    (a warning): nothing builds, installs or reads it. Test material is left alone where
    tests of error handling keep files broken on purpose:
    Python files under `test/` that pytest does not collect, and YAML under `test/`,
    `test_data/`, `testdata/` and similar folders. Nor are OpenCV's `FileStorage` files
    (starting `%YAML:1.0`), which OpenCV reads and YAML parsers refuse, nor a `.py` file
    whose `#!` line runs another language (a bash script named `start.py`; but one pytest
    collects, `test/test_x.py`, is imported as Python and reported), nor a Python
    file the package does not install in a folder of another project's code (`thirdparty/`,
    `third_party_packages/`, `external/`, `vendor/`: Eigen's Python 2 maintenance scripts) or
    of C and C++ headers (`include/`, where a library's headers come with its scripts:
    Boost.odeint's Python 2 benchmarks), or of a plain Python project kept in the workspace
    (a setup.py and no package.xml: dlib's examples); nor a YAML file that is a Jinja template
    (`{{ ... }}`, `{% ... %}`: a conda recipe's `meta.yaml`), which its tool renders first.
    Python is parsed by the Python running pkgtool: when that is older than the target
    distribution's (3.11 for jazzy's 3.12), a failing line that uses syntax the target's Python
    added is not reported, as the target may well accept it: an f-string that is complete
    under Python 3.12's rules but reuses its quotes, spans lines or holds a backslash or a
    comment in a replacement field (PEP 701), type parameters and `type` aliases, `except*`.
    Run pkgtool on the target's Python for a complete check. Python files of a ROS 1
    package built for Python 2 (one depending on `python-...` keys: Melodic or older) are
    not parsed, nor Python files kept aside (in `backup/`, `old/`, or named as a copy,
    `node_old.py`) that the package neither installs nor has pytest collect, nor those of a
    ROS 1 package whose `#!` line runs `python`, or some file of which runs `python2` (the
    convention before Noetic: its modules are Python 2 as well), nor those whose `#!` line
    runs `python` in a package CMake builds that neither installs them, nor names them or
    their folders in its CMake files, nor runs a Python linter in its tests
    (`ament_lint_auto`, `ament_cmake_flake8`): Python 2 syntax (`print x`, tabs counted as 8
    columns) is not Python 3's.

    ## Why is this bad?
    colcon, rosdep and ``ros2 launch`` stop at the first unparsable file, and an installed
    module with a syntax error fails only when a node imports it, on the robot.

    ## Example
    ```xml
    <name>my_pkg</nam>
    ```

    ## Use instead
    ```xml
    <name>my_pkg</name>
    ```
    """
    yield from problem_hits(package, _PARSE_KINDS, lambda p: not newer_syntax(package, p) and
                            not _vendored_and_unused(package, p) and
                            not _template(package, p) and not _python2(package, p) and
                            not set_aside(package, p.span.path) and not stray_yaml(package, p))


_VENDORED = frozenset({"thirdparty", "third_party", "3rdparty", "external", "extern", "vendor",
                       "vendored", "include"})
"""Folders of code a package keeps from another project (Eigen's maintenance scripts), and of
C and C++ headers (``include``), which hold no Python of the package's own."""


def _vendored_and_unused(package: Package, problem: ParseProblem) -> bool:
    """True for a Python file in a folder of another project's code (or of a plain Python
    project kept in the workspace, with no package.xml: dlib's examples) that the package
    does not install: nothing builds, runs or imports it (a Python 2 maintenance script)."""
    path = problem.span.path
    return problem.kind == "python-syntax" and (
        any(_vendored_folder(part) for part in path.split("/")[:-1]) or
        plain_python_project(package)) and path not in installed_files(package)


_PYTHON2_SHEBANG = lazy_pattern(r"#!.*\bpython(?:2(?:\.\d+)?)?[ \t\r]*(?:\n|$)")
"""A ``#!`` line running ``python``, ``python2`` or ``python2.7``: ROS 1's convention before
Noetic."""


_EXPLICIT_PYTHON2 = lazy_pattern(r"#!.*\bpython2(?:\.\d+)?[ \t\r]*(?:\n|$)")
"""A ``#!`` line running ``python2`` by name (``python`` may be Python 3 on Noetic, with
``python-is-python3``)."""
_PYTHON_LINTERS = frozenset({"ament_lint_auto", "ament_lint_common", "ament_cmake_flake8",
                             "ament_cmake_pyflakes", "ament_cmake_pycodestyle",
                             "ament_cmake_pep257", "ament_flake8"})
"""Test dependencies whose tests parse every Python file of a CMake package."""


def _python2(package: Package, problem: ParseProblem) -> bool:
    """True for Python written for Python 2 that nothing parses as Python 3: in a ROS 1
    package depending on Python 2 keys, or whose ``#!`` line runs ``python`` (Melodic and
    older); or, with such a ``#!`` line, in a package CMake builds that neither installs the
    file nor runs a Python linter in its tests (a vendored library's old test script)."""
    if problem.kind != "python-syntax":
        return False
    path = problem.span.path
    shebang = _PYTHON2_SHEBANG.match(package.texts.get(path, "")) is not None
    if is_ros1_package(package):  # a script's `python2` tells its modules' Python too
        return shebang or is_python2_package(package) or any(
            _EXPLICIT_PYTHON2.match(text) for text in package.texts.values())
    manifest = package.manifest
    return shebang and manifest is not None and manifest.build_type is not None and \
        manifest.build_type.value in CMAKE_BUILD_TYPES and \
        path not in installed_files(package) and not _named_by_cmake(package, path) and \
        not manifest.depends({"test_depend", "build_depend"}) & _PYTHON_LINTERS


def _named_by_cmake(package: Package, path: str) -> bool:
    """True when an argument of a command of the package's CMake files (comments aside) is the
    file's path or one of its folders (``install(DIRECTORY scripts/ ...)``,
    ``ament_add_pytest_test(t test/test_x.py)``, ``add_subdirectory(tests)``)."""
    parts = path.split("/")
    named = {"/".join(parts[:end]) for end in range(1, len(parts) + 1)}
    return any(_SOURCE_DIR.sub("", token).strip("/") in named
               for _, tokens in commands(cmake_text(package) or "") for token in tokens)


_SOURCE_DIR = lazy_pattern(r"^(?:\$\{(?:CMAKE_CURRENT_SOURCE_DIR|PROJECT_SOURCE_DIR)\}/|\./)+")
"""What a CMake path to a file of the package may start with."""


_TEMPLATE = lazy_pattern(r"\{\{.*?\}\}|\{%.*?%\}")
"""Jinja's expressions and statements: a YAML file holding them is a template some tool
renders first (a conda recipe's ``meta.yaml``), not YAML yet."""


def _template(package: Package, problem: ParseProblem) -> bool:
    """True for a YAML file that is a Jinja template (:data:`_TEMPLATE`)."""
    return problem.kind == "yaml-syntax" and \
        _TEMPLATE.search(package.texts.get(problem.span.path, "")) is not None


def _vendored_folder(name: str) -> bool:
    """True for a folder named like :data:`_VENDORED`, also with more words
    (``third_party_packages``, ``vendor_libs``)."""
    words = name.lower().replace("-", "_")
    return words in _VENDORED or any(words.startswith(f"{kind}_") for kind in _VENDORED)
