"""The seed documents' own listings, assembled into packages, give the findings their README lists.

Markers (``# expect: CODE``) in tests/fixtures/seeds/<package>/ name every error and warning
expected from the checked rules; packages without markers are correct and must stay clean.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from pkgtool.findings import Severity
from pkgtool.model.package import load_package
from pkgtool.rules.registry import load_all
from tests.helpers import findings
from tests.lint.test_rule_fixtures import _expected

SEEDS = Path(__file__).resolve().parent.parent / "fixtures" / "seeds"
PACKAGES = sorted(p.name for p in SEEDS.iterdir() if (p / "package.xml").is_file())
CHECKED_FAMILIES = ("DEP", "LCH", "PYC")
CHECKED_CODES = ("ENT002", "MAN018")
"""Rules whose seed findings are asserted exactly (other rules: style, headers, ...)."""
FOLDED = re.compile(r"`([^`\s]+):(\d+)` \(([A-Z]{3}\d{3})\)")
"""A place where a finding says the same mistake shows, with the rule that saw it there."""


def _checked() -> list[str]:
    return [code for code in load_all()
            if code.startswith(CHECKED_FAMILIES) or code in CHECKED_CODES]


@pytest.mark.parametrize("name", PACKAGES)
def test_seed_package_gives_exactly_the_marked_findings(name: str) -> None:
    case = SEEDS / name
    checked = _checked()
    found = [f for f in findings(load_package(case), *checked)
             if f.severity is not Severity.INFO]
    got = {(f.code, f.span.path, f.span.line) for f in found} | {
        (code, path, int(line)) for f in found  # consequences folded into their cause
        for path, line, code in FOLDED.findall(f.message)}
    expected = {(code, path, line) for code in checked for path, line in _expected(case, code)}
    assert got == expected


def test_the_readme_mistakes_are_all_marked() -> None:
    marked = {(name, code) for name in PACKAGES for code in _checked()
              if _expected(SEEDS / name, code)}
    assert {("physical_ai_sensors", "ENT002"), ("physical_ai_sensors", "DEP001"),
            ("physical_ai_sensors", "PYC003"), ("physical_ai_camera", "PYC001"),
            ("physical_ai_camera", "PYC002"), ("physical_ai_camera", "PYC003"),
            ("robot_monitor_subpackages", "ENT002"), ("simple_vision_agent", "MAN018"),
            ("simple_vision_agent", "DEP001"), ("nav_agent", "PYC004"),
            ("joint_controller_agent", "PYC005"), ("my_robot_pkg", "PYC040")} <= marked


def test_correct_seed_package_is_clean() -> None:
    name = "simple_avoidance_agent"
    found = findings(load_package(SEEDS / name), *_checked())
    assert [f for f in found if f.severity is not Severity.INFO] == []
