"""Python syntax errors that only the Python running pkgtool raises, not the target's."""

from __future__ import annotations

import sys

from pkgtool.knowledge.rosdistro import PYTHON_VERSIONS
from pkgtool.model.package import Package
from pkgtool.model.span import ParseProblem
from pkgtool.rules.syntax._fstrings import needs_python_312
from pkgtool.lazy_regex import lazy_pattern

_TYPE_PARAMETERS = lazy_pattern(r"^\s*(?:type\s+\w+\s*(?:\[|=)|(?:async\s+)?def\s+\w+\s*\[|"
                                r"class\s+\w+\s*\[)")
"""``type`` aliases and type parameters (Python 3.12, PEP 695)."""
_EXCEPT_STAR = lazy_pattern(r"^\s*except\s*\*")
"""``except*`` (Python 3.11, PEP 654)."""
_SINCE = (((3, 12), _TYPE_PARAMETERS), ((3, 11), _EXCEPT_STAR))


def newer_syntax(package: Package, problem: ParseProblem) -> bool:
    """True when ``problem`` is a Python syntax error the target's Python may not raise: pkgtool
    runs on an older Python, and the failing line uses syntax a version up to the target's
    added (an f-string only Python 3.12 reads, type parameters, ``except*``)."""
    if problem.kind != "python-syntax":
        return False
    major, minor = PYTHON_VERSIONS[package.context.distro].split(".")[:2]
    target = int(major), int(minor)
    running = sys.version_info[:2]
    if running >= target:
        return False
    text = package.texts.get(problem.span.path) or ""
    if running < (3, 12) <= target and needs_python_312(text, problem.span.line):
        return True
    lines = text.splitlines()
    line = lines[problem.span.line - 1] if 0 < problem.span.line <= len(lines) else ""
    return any(running < since <= target and pattern.search(line) for since, pattern in _SINCE)
