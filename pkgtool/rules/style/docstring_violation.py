"""STY002: what ament_pep257 reports, without a ROS installation."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule
from pkgtool.rules.style._run import tool_hits
from pkgtool.ament.pydocstyle_runner import run_pydocstyle


@rule("STY002", "docstring-violation", Severity.ERROR, default_enabled=False,
      fix="Rewrite the docstring as the pydocstyle code asks")
def docstring_violation(package: Package) -> Iterator[Hit]:
    """A docstring that ament_pep257 (the `test_pep257.py` of ROS 2 packages) rejects.

    ## What it does
    Runs pydocstyle in-process with ament's "ament" convention: every pydocstyle check except
    D100-D107 (missing docstrings), D203, D212 and D404. Enabled by `pkgtool lint --style` or
    `--select STY`.

    ## Why is this bad?
    `colcon test` runs ament_pep257 in packages made by `ros2 pkg create`; a violation fails
    the package's tests.

    ## Example
    ```python
    def speed():
        \"\"\"returns the speed\"\"\"
    ```

    ## Use instead
    ```python
    def speed():
        \"\"\"Return the speed.\"\"\"
    ```
    """
    yield from tool_hits(package, run_pydocstyle, lambda code: True)
