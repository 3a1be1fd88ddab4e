"""Every failing fixture of a fixable rule: ``--fix`` removes its findings and adds none."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from pkgtool.commands.lint import LintOptions, run
from pkgtool.fix.registry import fixers

FIXTURES = Path(__file__).resolve().parents[1] / "fixtures"
CASES = [(code, case) for code in fixers() for case in sorted((FIXTURES / code / "bad").iterdir())]
PARTLY = {("MAN019", "gplv3_and_bsd_3_clause"), ("MAN019", "spdx_case_and_deprecated_ids"),
          ("LCH002", "undeclared_packages"), ("DAT008", "wrong_shapes")}
"""GPLv3 can mean -only or -or-later, `my_robot_description` is no known package, values
outside `ros__parameters` belong to a node only the user knows: no fix guesses, the user
chooses; the other findings of the case are fixed."""
MANUAL = {("MAN018", "buildtool_depend_ament_python"), ("MAN018", "ros1_packages"),
          ("MAN018", "standard_library_modules"), ("DAT001", "typo_in_path"),
          ("DAT008", "flat_file_for_a_component_and_a_node")}
"""MAN018 fixes pip and import names only; build types, ROS 1 packages and standard library
modules need the user (a `<build_type>`, a ROS 2 replacement, or nothing). DAT001 fixes a
string of sources and creates the (empty) ament index marker: other missing files have content
only their author knows. DAT008's values at the top level belong to a node only the user knows
(here a component and a node share the file)."""

REVEALED = {("PYC013", "called_callbacks"): {"PYC026"}}
"""Findings a fix may bring to light: once `callback=self.handle()` is `self.handle`, rclpy
calls a service callback that returns no response (PYC026), which the call hid."""


def _keys(path: Path, code: str, **fix: bool) -> list[tuple[str, str]]:
    options = LintOptions(extend_select=(code,), isolated=True, **fix)
    return [(f.code, f.message) for f in run([str(path)], options=options).findings]


@pytest.mark.parametrize(("code", "case"), CASES, ids=[f"{c}-{p.name}" for c, p in CASES])
def test_fix_clears_the_rule_and_adds_nothing(tmp_path: Path, code: str, case: Path) -> None:
    package = tmp_path / case.name
    shutil.copytree(case, package)
    before = _keys(package, code)
    after = _keys(package, code, fix=True, unsafe_fixes=True)
    mine = [key for key in after if key[0] == code]
    if (code, case.name) not in MANUAL:
        assert len(mine) < len([key for key in before if key[0] == code])
        assert not mine or (code, case.name) in PARTLY, mine
    added = {key for key in set(after) - set(before)
             if key[0] not in REVEALED.get((code, case.name), set())}
    assert not added, added
    assert _keys(package, code, fix=True, unsafe_fixes=True) == after, "not idempotent"
