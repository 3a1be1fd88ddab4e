"""Which findings reports offer as fixable: the fixer's own answer, finding by finding."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest

from pkgtool.edit.core import Fix
from pkgtool.findings import Finding
from pkgtool.fix import offers, registry
from pkgtool.fix.registry import Fixer, Refusal
from pkgtool.model.context import Context
from pkgtool.model.package import Package, load_package
from tests.helpers import correct_package_files, make_finding, write_tree


def _fixes_the_first_line(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    for finding in findings:
        if finding.span.line == 1:
            yield Fix("mend it", ())
        elif finding.span.line == 2:
            yield Refusal("only the author knows")
        elif finding.span.line == 3:
            raise ValueError("a fixer bug")


@pytest.fixture()
def package(tmp_path: Path) -> Package:
    return load_package(write_tree(tmp_path / "demo", correct_package_files("demo")), Context())


def test_only_findings_the_fixer_makes_a_fix_for_are_offered(
        package: Package, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(offers, "FIXED", frozenset({"SET006"}))
    monkeypatch.setattr(registry, "fixers", lambda: {
        "SET006": Fixer("SET006", True, "mend", _fixes_the_first_line)})
    found = [make_finding("SET006", line=line) for line in (1, 2, 3, 4)]
    found.append(make_finding("SYN001", line=1))  # no fixer: left as it is
    marked = offers.offers_marked(package, found)
    assert [f.manual for f in marked] == [False, True, True, True, False]
    assert [f.span.line for f in marked] == [1, 2, 3, 4, 1]


def test_fixers_are_not_imported_without_a_fixable_finding(
        package: Package, monkeypatch: pytest.MonkeyPatch) -> None:
    def never() -> dict[str, Fixer]:
        raise AssertionError("fixers imported")

    monkeypatch.setattr(registry, "fixers", never)
    found = [make_finding("SYN001")]
    assert offers.offers_marked(package, found) is found


def test_a_clean_run_imports_no_fixer_module() -> None:
    """Offers import the fixers (and the edit layer) only for a finding one may repair."""
    import subprocess
    import sys

    program = ("import sys; from pkgtool.fix.offers import offers_marked; "
               "offers_marked(None, []); "
               "print(sorted(m for m in sys.modules if m.startswith(PREFIXES)))")
    shown = subprocess.run([sys.executable, "-c", program.replace(
        "PREFIXES", "('pkgtool.fix.', 'pkgtool.edit')")], capture_output=True, text=True,
        check=True, cwd=Path(__file__).resolve().parents[2]).stdout
    assert shown.strip() == "['pkgtool.fix.offers']"
