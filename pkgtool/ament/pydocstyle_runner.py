"""Run pydocstyle in-process with ament_pep257's "ament" convention."""

from __future__ import annotations

import logging
from pathlib import Path

from pkgtool.ament.settings import AMENT_DOCSTRING_IGNORE
from pkgtool.ament.flake8_runner import StyleToolMissing, StyleViolation

logging.getLogger("pydocstyle").addHandler(logging.NullHandler())
"""pydocstyle logs a file it cannot parse to stderr; SYN001 reports that file instead."""


def run_pydocstyle(root: Path, files: list[str]) -> list[StyleViolation]:
    """pydocstyle over ``files`` checking every code except ament's ignore list."""
    try:
        import pydocstyle
        from pydocstyle.violations import ErrorRegistry
    except ImportError as error:
        raise StyleToolMissing("`pydocstyle` is not installed") from error
    checked = sorted(set(ErrorRegistry.get_error_codes()) - set(AMENT_DOCSTRING_IGNORE))
    violations = []
    paths = [str(root / f) for f in files]
    for error in pydocstyle.check(paths, select=checked,
                                  property_decorators={"property", "cached_property",
                                                       "functools.cached_property"}):
        if not hasattr(error, "code"):
            continue  # a file pydocstyle could not parse; SYN001 reports it
        path = Path(error.filename).resolve().relative_to(root.resolve()).as_posix()
        text = error.message.split(": ", 1)[-1]
        violations.append(StyleViolation(path, error.line, 1, error.code, text))
    return sorted(violations, key=lambda v: (v.path, v.line, v.code))
