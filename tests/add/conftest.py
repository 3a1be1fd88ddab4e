"""Packages for the ``pkgtool add`` tests, and a strict lint of them."""

from __future__ import annotations

from pathlib import Path

import pytest

from pkgtool.commands.create import run
from pkgtool.commands.lint import LintOptions
from pkgtool.commands.lint import run as lint
from tests.create.conftest import request


def created(destination: Path, name: str = "grow", **values: object) -> Path:
    """A package made by ``pkgtool create`` (fixed maintainer and year)."""
    values.setdefault("nodes", ("talker:publisher",))
    result = run(request(destination, name, **values))
    assert not result.error, result.error
    return destination / name


def strict_findings(root: Path) -> list[str]:
    """``lint --strict`` of the package: ``CODE path:line message`` of every finding."""
    result = lint([str(root)], options=LintOptions(strict=True, isolated=True))
    return [f"{f.code} {f.span.path}:{f.span.line} {f.message}" for f in result.findings]


@pytest.fixture
def package(tmp_path: Path) -> Path:
    """A fresh package with one publisher node, no launch file, no config."""
    return created(tmp_path)
