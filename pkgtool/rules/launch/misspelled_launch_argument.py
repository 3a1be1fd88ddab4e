"""LCH008: a launch configuration read under a misspelling of a declared argument."""

from __future__ import annotations

from collections.abc import Iterator
from difflib import get_close_matches

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.launch._python_launch import declaration_holders, undeclared_reads
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import launch_indexes


@rule("LCH008", "misspelled-launch-argument", Severity.ERROR,
      fix="Read the argument under the name it is declared with")
def misspelled_launch_argument(package: Package) -> Iterator[Hit]:
    """A launch file reads a launch configuration that nothing declares, under a name spelled
    almost like a declared argument.

    ## What it does
    In the package's Python launch files, collects the names declared with
    `DeclareLaunchArgument('name', ...)` (in any of them) and reports
    `LaunchConfiguration('other')` without a `default` when `other` is declared nowhere,
    nothing else in the files sets it (`SetLaunchConfiguration`, `launch_arguments`) and
    a declared name of the same file is spelled almost the same (`use_sim_tim` for
    `use_sim_time`), or the name read is that of the Python variable holding a declaration
    (`LaunchConfiguration('x_arg')` after `x_arg = DeclareLaunchArgument('x')`). In XML
    and YAML launch files, the same for `$(var other)` against the names of `<arg>` and
    `<let>` (`arg:` and `let:`), when `other` appears nowhere else in the file.

    ## Why is this bad?
    `ros2 launch` fails when it evaluates the substitution: `launch configuration
    'use_sim_tim' does not exist`, unless the user happens to pass that misspelt name on the
    command line. The declared argument is never used.

    ## Example
    ```python
    DeclareLaunchArgument('use_sim_time', default_value='false'),
    Node(..., parameters=[{'use_sim_time': LaunchConfiguration('use_sim_tim')}]),
    ```

    ## Use instead
    ```python
    DeclareLaunchArgument('use_sim_time', default_value='false'),
    Node(..., parameters=[{'use_sim_time': LaunchConfiguration('use_sim_time')}]),
    ```
    """
    holders = {path: declaration_holders(index) for path, index in launch_indexes(package)}
    for span, name, declared in undeclared_reads(package):
        held = holders.get(span.path, {}).get(name)
        close = [held] if held else get_close_matches(name, sorted(declared), n=1, cutoff=0.8)
        if close:
            yield _hit(span, name, close[0])


def _hit(span: Span, name: str, meant: str) -> Hit:
    return Hit(span, f"`{name}` is declared by no launch argument (did you mean `{meant}`?): "
                     f"the launch fails with launch configuration '{name}' does not exist")
