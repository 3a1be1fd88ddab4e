"""DAT020: a CMake ``install()`` names a file or folder the package does not have."""

from __future__ import annotations

import posixpath
import re
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.cmake_install import tolerated_missing_sources
from pkgtool.model.installed import cmake_installed, cmake_text
from pkgtool.model.launch import nested_packages
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.model.submodules import ignored, under
from pkgtool.rules.registry import rule


@rule("DAT020", "missing-cmake-install-source", Severity.ERROR,
      fix="Add the file or folder to the package, or remove it from the `install()` call")
def missing_cmake_install_source(package: Package) -> Iterator[Hit]:
    """A CMake package's `install()` names a file or folder the package does not have.

    ## What it does
    Reads the sources of `install(PROGRAMS|FILES|DIRECTORY ...)` in CMakeLists.txt (and the
    CMake files it includes; `ament_python_install_package` folders too) and reports one that
    is no file or folder of the package, when every source is known statically (no
    variable the file does not set, no `add_subdirectory`, function or macro). Sources a
    `.gitignore` leaves out (made before the build) or inside a git submodule that is not
    checked out are left alone, and so are sources the file copes with missing: those of an
    `install(... OPTIONAL)` and paths it tests with `if(EXISTS ...)` or `if(IS_DIRECTORY
    ...)` (installed only when present), and sources outside the package folder
    (`../dbc/robot.dbc`, an absolute path) or inside a folder holding a package.xml of its
    own (an old package kept inside this one), which pkgtool does not read. An empty folder
    counts as missing: git keeps no empty folders, so a fresh clone lacks it.

    ## Why is this bad?
    `colcon build` stops at the install step ("file INSTALL cannot find ..."): nothing of the
    package is installed, on every machine that builds it from the repository.

    ## Example
    ```cmake
    install(PROGRAMS scripts/teleop.py scripts/internal_test.py  # no internal_test.py
            DESTINATION lib/${PROJECT_NAME})
    ```

    ## Use instead
    ```cmake
    install(PROGRAMS scripts/teleop.py DESTINATION lib/${PROJECT_NAME})
    ```
    """
    sources = cmake_installed(package)
    text = package.texts.get("CMakeLists.txt", "")
    tolerated = tolerated_missing_sources(cmake_text(package) or "") if sources else frozenset()
    nested = nested_packages(package.files) if sources else frozenset()
    for source in sorted(sources or ()):
        if source in ("", ".") or package.has_file(source) or package.has_folder(source) or \
                source in tolerated or ignored(source, package.ignores) or \
                under(source, package.unfetched) or under(source, nested) or _outside(source):
            continue
        found = _place(source, text)
        if found is None:
            continue  # written in an included file, or built from parts: not placed
        yield Hit(Span.of_offset("CMakeLists.txt", text, found),
                  f"`install()` names `{source}`, which the package does not have: "
                  "`colcon build` fails at the install step")


def _outside(source: str) -> bool:
    """True for a source outside the package folder (``../dbc/can.dbc``, an absolute path):
    a file of the repository or the system that pkgtool does not see."""
    normal = posixpath.normpath(source)
    return posixpath.isabs(normal) or normal == ".." or normal.startswith("../")


_INSTALL = re.compile(r"\binstall\s*\(", re.IGNORECASE)


def _place(source: str, text: str) -> int | None:
    """The offset of ``source`` in CMakeLists.txt: where an ``install()`` call names it (not
    an earlier mention, ``add_service_files(FILES x.srv)``; a folder also with its trailing
    slash, ``DIRECTORY include/``; a source built from a variable by its last part,
    ``${PROJECT_NAME}/node.py``), else its first mention."""
    mentions = [m.start() for m in re.finditer(
        rf"(?<![\w.-]){re.escape(source)}(?![\w.-])(?!/[\w.-])", text)] or \
        [m.start() for m in re.finditer(  # built from a variable: `${PROJECT_NAME}/node.py`
            rf"\$\{{\w+\}}/{re.escape(posixpath.basename(source))}(?![\w.-])(?!/[\w.-])",
            text)]
    for call in _INSTALL.finditer(text):
        end = text.find(")", call.end())
        inside = [at for at in mentions if call.end() <= at < (end if end >= 0 else len(text))]
        if inside:
            return inside[0]
    return mentions[0] if mentions else None
