"""LCH001: a launch file starts an executable of this package that the package does not install."""

from __future__ import annotations

import posixpath
from difflib import get_close_matches
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import typo_of
from pkgtool.model.installed import is_ament_python
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule


def executables(package: Package) -> frozenset[str] | None:
    """Names the package installs into ``lib/<package>``, or None when that cannot be known.

    Console scripts of setup.py and setup.cfg count, and so do files that data_files copies
    into ``lib/<package>``. Anything dynamic (unevaluated keywords, ``scripts=``, a setup.cfg or
    pyproject.toml that did not parse or may declare scripts) makes the answer unknown, and so
    does a package colcon builds with CMake (another build type, or a CMakeLists.txt and none):
    CMake installs the executables then.
    """
    setup = package.setup_py
    if setup is None or "scripts" in setup.keywords or package.has_file("pyproject.toml"):
        return None
    if not is_ament_python(package):
        return None  # CMake installs its executables; a setup.py beside it is not run
    if any(setup.is_unresolved(k) for k in ("entry_points", "data_files", "**")):
        return None
    if package.has_file("setup.cfg") and package.setup_cfg is None:
        return None
    names = {entry.name for entry in setup.console_scripts}
    option = package.setup_cfg.get("options.entry_points", "console_scripts") \
        if package.setup_cfg else None
    if option is not None:
        names.update(line.split("=", 1)[0].strip() for line in option.value.splitlines()
                     if "=" in line)
    library = f"lib/{package.name}"
    for entry in setup.data_files or ():
        if posixpath.normpath(entry.destination.strip("/")) == library:
            for source in entry.sources:
                names.update(posixpath.basename(m) for m in source.matches)
                if not source.is_glob:
                    names.add(posixpath.basename(source.pattern))
    return frozenset(names)


@rule("LCH001", "launch-unknown-executable", Severity.ERROR,
      fix="Add the executable to `console_scripts` in setup.py, or launch an existing one")
def launch_unknown_executable(package: Package) -> Iterator[Hit]:
    """A launch file starts an executable of this package that setup.py does not install.

    ## What it does
    For every `Node(package=..., executable=...)` (or `<node pkg= exec=>`) naming this
    package, checks that the executable is a console script of setup.py or setup.cfg, or a
    file data_files installs into `lib/<package>`. Executables given by launch arguments or
    other substitutions are not checked, nor nodes that are never started (assigned to a
    local name the function never reads): the executable is looked up only when a node
    starts, so such a node cannot fail. LCH005 still checks their arguments, which the
    `Node()` call itself rejects.

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
    known = executables(package)
    if known is None:
        return
    for launch in package.launch_files:
        for node in launch.nodes:
            if node.package != package.name or node.executable is None or node.unused:
                continue
            if node.executable not in known:
                choices = ", ".join(f"`{n}`" for n in sorted(known)) or "none"
                close = get_close_matches(node.executable, sorted(known), n=1)
                meant = typo_of(node.executable, known)
                yield Hit(node.executable_span or node.span,
                          f"`{node.executable}` is not an executable of `{package.name}` "
                          f"({f'did you mean `{close[0]}`? ' if close else ''}it installs: "
                          f"{choices})",
                          f"Write `{meant}`" if meant else
                          f"Add `{node.executable} = {package.name}.<module>:main` to "
                          f"console_scripts, or launch one of the installed executables")
