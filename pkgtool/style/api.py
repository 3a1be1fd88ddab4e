"""Style checks of a package folder as plain messages, for generated linter tests.

A package made by ``pkgtool create`` calls these from its test_flake8.py / test_pep257.py when
the ament linters are not installed, so the same checks run with pkgtool alone, and always from
its test_copyright.py (ament_copyright rejects SPDX headers).
"""

from __future__ import annotations

from pathlib import Path

from pkgtool.engine import check_package
from pkgtool.model.package import load_package
from pkgtool.rules.registry import resolve


def _messages(root: Path, selector: str) -> list[str]:
    package = load_package(root)
    found = check_package(package, resolve(selector), root_label=str(root))
    return [f"{f.span.path}:{f.span.line}:{f.span.col}: {f.code} {f.message}" for f in found]


def flake8_errors(root: Path) -> list[str]:
    """What ament_flake8 would report for the package at ``root`` (code style, STY001)."""
    return _messages(Path(root), "STY001")


def pep257_errors(root: Path) -> list[str]:
    """What ament_pep257 would report for the package at ``root`` (docstrings, STY002)."""
    return _messages(Path(root), "STY002")


def copyright_errors(root: Path) -> list[str]:
    """Missing or disagreeing copyright/license headers (CPY family)."""
    return _messages(Path(root), "CPY")
