"""LCH001: a launch file starts an executable of this package that the package does not install."""

from __future__ import annotations

from collections.abc import Iterator
from difflib import get_close_matches

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import typo_of
from pkgtool.model.package import Package
from pkgtool.rules.launch._executables import LAUNCH_FILE_NAME, console_scripts, executables
from pkgtool.rules.registry import rule


@rule("LCH001", "launch-unknown-executable", Severity.ERROR,
      fix="Add the executable to `console_scripts` in setup.py, or launch an existing one")
def launch_unknown_executable(package: Package) -> Iterator[Hit]:
    """A launch file starts an executable of this package that setup.py does not install.

    ## What it does
    For every `Node(package=..., executable=...)` (or `<node pkg= exec=>`) naming this
    package, checks that the executable is a console script of setup.py or setup.cfg, or a
    file data_files installs into `lib/<package>` (a data_files that could not be evaluated
    may install any file of the package: a name no file has is still reported). Executables
    given by launch arguments or other substitutions are not checked, nor nodes that are
    never started (assigned to a local name the function never reads): the executable is
    looked up only when a node starts, so such a node cannot fail. LCH005 still checks
    their arguments, which the `Node()` call itself rejects.

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
    if known is None:
        return
    shown = executables(package) or console_scripts(package) or frozenset()
    # what certainly is there: a data_files never evaluated may copy any file
    for launch in package.launch_files:
        for node in launch.nodes:
            if node.package != package.name or node.executable is None or node.unused or \
                    LAUNCH_FILE_NAME.search(node.executable):  # LCH017's
                continue
            if node.executable not in known:
                choices = ", ".join(f"`{n}`" for n in sorted(shown)) or "none"
                close = get_close_matches(node.executable, sorted(shown), n=1)
                meant = typo_of(node.executable, shown)
                yield Hit(node.executable_span or node.span,
                          f"`{node.executable}` is not an executable of `{package.name}` "
                          f"({f'did you mean `{close[0]}`? ' if close else ''}it installs: "
                          f"{choices})",
                          f"Write `{meant}`" if meant else
                          f"Add `{node.executable} = {package.name}.<module>:main` to "
                          f"console_scripts, or launch one of the installed executables")
