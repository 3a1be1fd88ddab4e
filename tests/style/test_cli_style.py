"""`pkgtool lint --style` adds the STY and CPY families through the normal CLI."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

from tests.helpers import MINIMAL_MANIFEST, run_cli, write_tree

HEADER = "# Copyright 2026 Dev\n# SPDX-License-Identifier: Apache-2.0\n"


def _package(root: Path, node: str) -> Path:
    return write_tree(root / "demo", {
        "package.xml": MINIMAL_MANIFEST.format(name="demo"),
        "setup.py": "from setuptools import setup\nsetup(name='demo')\n",
        "demo/__init__.py": "",
        "demo/node.py": node,
    })


def test_style_findings_only_with_the_flag(tmp_path: Path) -> None:
    _package(tmp_path, HEADER + '"""Node."""\n\nSPEED = "fast"\n')
    plain = run_cli("lint", "--select", "SYN", "demo", cwd=tmp_path)
    assert plain.exit_code == 0, plain.output
    styled = run_cli("lint", "--select", "SYN", "--style", "--format", "json", "demo",
                     cwd=tmp_path)
    assert styled.exit_code == 1
    found = json.loads(styled.output)["findings"]
    assert [(f["rule"], f["path"], f["line"]) for f in found] == [
        ("STY001", "demo/demo/node.py", 5)]
    assert "`Q000`" in found[0]["message"]


def test_style_clean_package_passes(tmp_path: Path) -> None:
    _package(tmp_path, HEADER + '"""Node."""\n\nSPEED = \'fast\'\n')
    result = run_cli("lint", "--select", "SYN", "--style", "--strict", "demo", cwd=tmp_path)
    assert result.exit_code == 0, result.output


def test_a_missing_checker_is_one_finding_with_an_install_hint(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    _package(tmp_path, HEADER + '"""Node."""\n')
    monkeypatch.setitem(sys.modules, "pydocstyle", None)  # `import pydocstyle` raises
    result = run_cli("lint", "--select", "STY002", "--format", "json", "demo", cwd=tmp_path)
    [found] = json.loads(result.output)["findings"]
    assert (found["path"], found["line"]) == ("demo/package.xml", None)
    assert found["message"] == "`pydocstyle` is not installed"
    assert found["fix"] == 'Install the style checkers: `pip install "pkgtool-ros[style]"`'
