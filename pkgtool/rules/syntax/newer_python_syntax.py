"""SYN007: a Python file written for the target's newer Python, which the Python running
pkgtool cannot parse, so no rule checked it (but the imports above the line)."""

from __future__ import annotations

import sys
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import PYTHON_VERSIONS
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax._newer_syntax import newer_syntax


@rule("SYN007", "newer-python-syntax", Severity.INFO,
      fix="Run pkgtool on the target's Python (or newer) to check this file")
def newer_python_syntax(package: Package) -> Iterator[Hit]:
    """A Python file uses syntax of the target's Python that pkgtool's Python cannot parse, so
    it was not checked.

    ## What it does
    Notes a Python file that does not parse on the Python running pkgtool, where the failing
    line uses syntax the target distribution's Python reads (jazzy's Python 3.12: f-strings
    reusing their quotes, `f"{item["label"]}"`; type parameters; `except*` on 3.11). The file
    is no syntax error there (SYN001 stays silent), but no rule could read it: its node code
    and entry points went unchecked, and its imports but those of the top-level statements
    above the failing one. This is a limit of the Python running pkgtool, not a defect of the
    package.

    ## Why is this bad?
    It is not wrong in itself; the note says that a clean lint does not vouch for the file.

    ## Example
    ```python
    label = f"{detection["label"]}: {detection["score"]:.2f}"  # Python 3.12
    ```

    ## Use instead
    Run pkgtool on Python 3.12 or newer (the target's), which parses the file and checks it.
    """
    running = ".".join(str(part) for part in sys.version_info[:2])
    target = ".".join(PYTHON_VERSIONS[package.context.distro].split(".")[:2])
    imported = {module.path for module in package.modules if module.imports}
    for problem in package.problems:
        if problem.kind == "python-syntax" and newer_syntax(package, problem):
            checked = "only the imports above it were checked" if problem.span.path in \
                imported else "no rule checked the file"
            yield Hit(problem.span, f"Python {running} (running pkgtool) cannot parse this "
                      f"syntax of Python {target} ({package.context.distro}'s), so {checked}")
