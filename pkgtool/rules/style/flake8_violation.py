"""STY001: what ament_flake8 reports, without a ROS installation."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule
from pkgtool.rules.style._run import tool_hits
from pkgtool.ament.flake8_runner import run_flake8


@rule("STY001", "flake8-violation", Severity.ERROR, default_enabled=False,
      fix="Fix the code as the flake8 code asks, or add `# noqa: <code>` with a reason")
def flake8_violation(package: Package) -> Iterator[Hit]:
    """Code that ament_flake8 (the `test_flake8.py` of every ROS 2 package) rejects.

    ## What it does
    Runs flake8 in-process over the package's Python files with exactly ament's configuration:
    max line length 99, google import order, ament's ignore list, and the ROS plugin set
    (builtins, comprehensions, import order, quotes). Docstring codes (`D…`) are reported by
    STY002, which checks the superset ament_pep257 checks, so nothing is reported twice.
    Enabled by `pkgtool lint --style` or `--select STY`.

    ## Why is this bad?
    `colcon test` runs ament_flake8 in every package made by `ros2 pkg create`; a violation
    fails the package's test suite, and autograders that mirror ROS CI fail the submission.

    ## Example
    ```python
    import sys
    import os
    x = "value"
    ```

    ## Use instead
    ```python
    import os
    import sys

    x = 'value'
    ```
    """
    yield from tool_hits(package, run_flake8, lambda code: not code.startswith("D"))
