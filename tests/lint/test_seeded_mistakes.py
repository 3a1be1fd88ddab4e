"""Recall on seeded mistakes: each case inserts one typical mistake into a correct package.

The bases are the package ``pkgtool create`` writes with three nodes, a launch file and a
config file, and the reference packages; all lint clean (checked here too). Every case must
make lint report its rule, at the file and line where the mistake is.
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from pkgtool.commands.create import Request, run
from pkgtool.findings import Finding
from pkgtool.model.package import load_package
from pkgtool.rules.registry import load_all
from tests.helpers import findings
from tests.lint.seeded import CASES, CREATED, Case
from tests.lint.seeded import (  # noqa: F401  (each module registers its cases)
    data_files, dependencies, entry_points, launch, manifest, python, setup_files)

REFERENCE = Path(__file__).resolve().parents[2] / "reference_packages"
NODES = ("talker:publisher", "listener:subscriber", "srv:service")


@pytest.fixture(scope="module")
def bases(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    """The correct packages the cases start from, by base name."""
    destination = tmp_path_factory.mktemp("seeded")
    result = run(Request("base_pkg", destination, maintainer_name="Jane Doe",
                         maintainer_email="jane@example.com", nodes=NODES, launch=True,
                         config=True, year=2026))
    assert result.root is not None, result.error
    found = {CREATED: result.root}
    found.update({case.base: REFERENCE / case.base for case in CASES if case.base != CREATED})
    return found


def _default_findings(root: Path) -> list[Finding]:
    """What a plain ``pkgtool lint`` reports (the rules enabled by default)."""
    codes = [code for code, rule in load_all().items() if rule.default_enabled]
    return findings(load_package(root), *codes)


def _line_of(root: Path, case: Case) -> int | None:
    if case.path is None or case.at is None:
        return None
    lines = (root / case.path).read_text().splitlines()
    return next(n for n, line in enumerate(lines, 1) if case.at in line)


@pytest.mark.parametrize("base", sorted({CREATED} | {c.base for c in CASES}))
def test_base_package_lints_clean(bases: dict[str, Path], base: str) -> None:
    assert findings(load_package(bases[base])) == []  # every rule, style too


@pytest.mark.parametrize("case", CASES, ids=lambda c: f"{c.code}-{c.id}")
def test_seeded_mistake_is_reported(bases: dict[str, Path], tmp_path: Path,
                                    case: Case) -> None:
    root = tmp_path / bases[case.base].name
    shutil.copytree(bases[case.base], root)
    case.mutate(root)
    got = _default_findings(root)
    line = _line_of(root, case)
    matching = [f for f in got if f.code == case.code  # at its first place or a related one
                and any(case.path in (None, s.path) and line in (None, s.line)
                        for s in (f.span, *f.related))]
    where = f" at {case.path}:{line}" if case.path else ""
    assert matching, (f"{case.code}{where} not reported; got: " +
                      "; ".join(f"{f.code} {f.span.path}:{f.span.line} {f.message}" for f in got))
