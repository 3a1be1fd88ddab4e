"""LCH001: a launch file starts an executable of this package that the package does not install."""

from __future__ import annotations

from collections.abc import Iterator
from difflib import get_close_matches

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdep import metapackage_members
from pkgtool.knowledge.rosdistro import released_executables, released_installers, typo_of
from pkgtool.model.launch import LAUNCH_FILE_NAME, NodeRef
from pkgtool.model.package import Package
from pkgtool.model.scripts import sibling_executables
from pkgtool.rules.launch._executables import (cmake_executables, cmake_programs,
                                               console_scripts, executables)
from pkgtool.rules.registry import rule


@rule("LCH001", "launch-unknown-executable", Severity.ERROR,
      fix="Add the executable to `console_scripts` in setup.py, or launch an existing one")
def launch_unknown_executable(package: Package) -> Iterator[Hit]:
    """A launch file starts an executable that its package (this one, or another ament_python
    package of the workspace) does not install.

    ## What it does
    An empty executable (`executable=''`) is reported for any package. For every
    `Node(package=..., executable=...)` (or `<node pkg= exec=>`) naming this
    package, checks that the executable is a console script of setup.py or setup.cfg, or a
    file data_files installs into `lib/<package>` (a data_files that could not be evaluated
    may install any file of the package: a name no file has is still reported). A node of
    another package linted with this one (a bringup package starting a driver's node) is
    checked against that package's console scripts when it is an ament_python package whose
    setup.py and setup.cfg say all it installs (evaluated statically, no data_files into
    `lib/<package>`). Executables given by launch arguments or other substitutions are not
    checked, nor an absolute path (`executable='/usr/bin/python3'`: launch_ros runs a path
    with folders as it is, given `lib/<package>` exists), nor nodes that are never started
    (assigned to a local name the function never reads): the executable is looked up only
    when a node starts, so such a node cannot fail.
    LCH005 still checks their arguments, which the `Node()` call itself rejects. In a package
    built with CMake, a node naming `detector` is reported when the CMakeLists.txt installs
    the script `detector.py` with `install(PROGRAMS ...)` into `lib/` (under its file name)
    and names `detector` nowhere else (no target, `RENAME` or component of that name). A
    node of a package CMake builds (this one or one of the workspace) is checked against the
    executables its CMakeLists.txt installs into `lib/<package>`, when its text says so for
    certain: targets of `install(TARGETS ...)` (by their `OUTPUT_NAME`), files of
    `install(PROGRAMS ...)` (or their `RENAME`), `ament_auto_add_executable` targets and
    components' `EXECUTABLE`; not when it uses commands of the project's own, loops,
    subdirectories or folders installed into `lib/` (the setup.py a CMake package may hold
    is never run by colcon). A node of a released metapackage that is not in the workspace
    (`rtabmap_ros` since its split, `navigation2`) is reported: a metapackage only brings
    in other packages and installs no executable of its own. So is a node of a common
    released package (`robot_state_publisher`, `joint_state_publisher`, `tf2_ros`, `joy`,
    ... on Humble and Jazzy: `data/released_executables.txt`, read from their repositories
    at the released versions) naming an executable it does not install
    (`executable='state_publisher'`, ROS 1's name).

    ## Why is this bad?
    `ros2 launch` looks the executable up in `lib/<package>` only when the launch file runs
    and stops with "executable not found", usually after other nodes have started.

    ## Example
    ```python
    Node(package='my_robot', executable='talker_node')  # console script is 'talker'
    ```

    ## Use instead
    ```python
    Node(package='my_robot', executable='talker')
    ```
    """
    known = executables(package, any_data=True)
    # what certainly is there: a data_files never evaluated may copy any file
    shown = (executables(package) or console_scripts(package) or frozenset()) \
        if known is not None else None
    programs = cmake_programs(package)
    if known is None:  # a package CMake builds: what its CMakeLists.txt installs, if certain
        known = shown = cmake_executables(package)
    for launch in package.launch_files:
        for node in launch.nodes:
            if node.package is None or node.executable is None or node.unused or \
                    LAUNCH_FILE_NAME.search(node.executable) or \
                    node.executable.startswith("/"):  # LCH017's; a path runs as it is
                continue
            if not node.executable.strip():
                yield Hit(node.executable_span or node.span,
                          f"`executable='{node.executable}'` names no executable of "
                          f"`{node.package}`: launch stops with \"executable '' not found\"",
                          "Write the name of the executable, as `ros2 pkg executables "
                          f"{node.package}` lists it")
                continue
            if node.package == package.name and node.executable in programs:
                yield _kept_suffix(node, programs[node.executable])
                continue
            released = node.package not in package.context.workspace and \
                not node.other_distros  # a branch for another distribution's names
            members = metapackage_members(node.package, package.context.distro) \
                if released else None
            if members is not None:
                yield _in_metapackage(node, members)
                continue
            installed = (known, shown) if node.package == package.name else \
                _sibling(package, node.package, node.other_distros)
            if installed[0] is not None and node.executable not in installed[0]:
                yield _unknown(node, installed[1] or frozenset(), _built_by_cmake(package, node),
                               released, package.context.distro)


def _in_metapackage(node: NodeRef, members: tuple[str, ...]) -> Hit:
    """The finding for a node started from a released metapackage, which installs nothing."""
    named = ", ".join(f"`{m}`" for m in members[:16]) + (", ..." if len(members) > 16 else "")
    return Hit(node.executable_span or node.span,
               f"`{node.package}` is a metapackage, which installs no executables (it brings "
               f"in {named}): launch stops with \"executable '{node.executable}' not found\"",
               f"Name the package among them that installs `{node.executable}`")


def _kept_suffix(node: NodeRef, installed: str) -> Hit:
    """The finding for a node naming a script a CMake package installs under its file name."""
    return Hit(node.executable_span or node.span,
               f"`{node.executable}` is not an executable of `{node.package}`: its "
               f"CMakeLists.txt installs the script as `{installed}` (`install(PROGRAMS)` keeps "
               "the file's name)", f"Write `executable='{installed}'`, or install the script "
               f"with `RENAME {node.executable}`")


def _sibling(package: Package, name: str, other_distros: bool
             ) -> tuple[frozenset[str] | None, frozenset[str] | None]:
    """What another workspace package named ``name`` installs (twice, as :func:`executables`
    gives a package's own: what may be there, what is shown), or a common released one on
    the target distribution (unless the node is written for ``other_distros``); None when
    unknown."""
    sibling = package.context.workspace.get(name)
    if sibling is None:  # a released package, when it is a common one
        found = released_executables(name, package.context.distro) if not other_distros \
            else None
        return found, found
    found = sibling_executables(sibling)
    if found is None:
        found = sibling.executables
    return found, found


def _built_by_cmake(package: Package, node: NodeRef) -> bool:
    """True when the package ``node`` starts is one CMake builds."""
    if node.package == package.name:
        return cmake_executables(package) is not None
    sibling = package.context.workspace.get(node.package or "")
    return sibling is not None and sibling.executables is not None


def _unknown(node: NodeRef, shown: frozenset[str], cmake: bool, released: bool,
             distro: str) -> Hit:
    """The finding for ``node``, whose executable is none of ``shown`` (``cmake``: of a
    package CMake builds; ``released``: of a released package of ``distro``, not of the
    workspace)."""
    executable = node.executable or ""
    choices = ", ".join(f"`{n}`" for n in sorted(shown)) or "none"
    installers = released_installers(executable, distro) if released else ()
    close = get_close_matches(executable, sorted(shown), n=1) if not installers else []
    meant = typo_of(executable, shown)
    add = f"Install it: `install(TARGETS {executable} DESTINATION lib/${{PROJECT_NAME}})`" \
        if cmake else f"Add `{executable} = {node.package}.<module>:main` to console_scripts"
    fix = f"Write `{meant}`" if meant else \
        f"Write `package='{installers[0]}'`: it installs `{executable}`" \
        if len(installers) == 1 else \
        f"Launch one of the executables `{node.package}` installs, or name the package that " \
        f"installs `{executable}`" if released else \
        f"{add}, or launch one of the installed executables"
    elsewhere = [d for d in ("humble", "jazzy") if d != distro and released and
                 executable in (released_executables(node.package or "", d) or ())]
    where = f" on {distro}" if released else ""
    was = f"; on {elsewhere[0]} it has `{executable}`" if elsewhere else ""
    return Hit(node.executable_span or node.span,
               f"`{executable}` is not an executable of `{node.package}`{where} "
               f"({f'did you mean `{close[0]}`? ' if close else ''}it installs: {choices}{was})",
               fix)
