"""``lint --fix`` measured: seeded mutants of fixable rules, clean packages, the real-world corpus.

    python bench/bench_fix.py [--colcon] [--corpus DIR]

1. Mutants: every seeded mistake (tests/lint/seeded) of a rule that has a fix, applied to the
   package ``pkgtool create`` writes or to a reference package. Share that ``--fix`` (with
   ``--unsafe-fixes`` for a rule whose fix is unsafe) returns to no finding of that rule
   (and, with ``--colcon``, that then build and pass their tests).
2. Clean packages (the created one, the reference packages): ``--fix --unsafe-fixes`` must not
   change a byte.
3. The real-world corpus (bench/realworld/corpus.py build): packages without fixable findings
   must stay byte-identical; the others must still parse and gain no new finding.
"""

from __future__ import annotations

import argparse
import functools
import shutil
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from pkgtool.commands.create import Request, run as create  # noqa: E402
from pkgtool.commands.lint import LintOptions, run as lint  # noqa: E402
from pkgtool.edit.changes import parses  # noqa: E402
from pkgtool.fix.registry import fixers  # noqa: E402
from tests.lint.seeded import CASES, CREATED  # noqa: E402
from tests.lint.seeded import (  # noqa: E402,F401  (each module registers its cases)
    data_files, dependencies, entry_points, launch, manifest, python, setup_files)

REFERENCE = ROOT / "reference_packages"
NODES = ("talker:publisher", "listener:subscriber", "srv:service")


def snapshot(root: Path) -> dict[str, bytes]:
    """Every file under ``root`` by relative path."""
    return {p.relative_to(root).as_posix(): p.read_bytes()
            for p in sorted(root.rglob("*")) if p.is_file() and not p.is_symlink()}


def keys(path: Path, **fix: bool) -> list[tuple[str, str, str]]:
    """(code, path, message) of the default findings after the optional fix."""
    found = lint([str(path)], options=LintOptions(isolated=True, **fix)).findings
    return [(f.code, f.span.path, f.message) for f in found]


def mutants(scratch: Path, colcon: bool) -> None:
    made = create(Request("base_pkg", scratch / "created", maintainer_name="Jane Doe",
                          maintainer_email="jane@example.com", nodes=NODES, launch=True,
                          config=True, year=2026))
    bases = {CREATED: made.root}
    fixable = [c for c in CASES if c.code in fixers()]
    cleared: list[bool] = []
    built: list[set[str]] = []
    unmeasured: list[str] = []
    for index, case in enumerate(fixable):
        root = scratch / f"m{index}" / "base_pkg"
        source = bases.get(case.base) or REFERENCE / case.base
        shutil.copytree(source, root)
        case.mutate(root)
        after = keys(root, fix=True, unsafe_fixes=not fixers()[case.code].safe)
        ok = not any(code == case.code for code, _, _ in after)
        cleared.append(ok)
        if not ok:
            print(f"  not cleared: {case.id} ({case.code})")
        missing = not_installed_here(root, source) if colcon and ok else []
        if missing:
            unmeasured.append(case.id)
            print(f"  not built: {case.id} imports {', '.join(missing)}, not installed here")
        elif colcon and ok:
            failed = colcon_failures(root)
            built.append(failed)
            if failed:
                print(f"  fixed but fails under colcon: {case.id}: {sorted(failed)}")
    print(f"mutants of fixable rules: {len(fixable)}; --fix clears the rule: {sum(cleared)} "
          f"({100 * sum(cleared) / len(fixable):.0f}%)")
    if colcon:
        measured = len(fixable) - len(unmeasured)
        passed = sum(1 for failed in built if not failed)
        functional = sum(1 for failed in built if failed <= {"test_flake8"})
        print(f"cleared, built and every test passed: {passed} of {measured} measurable "
              f"({100 * passed / measured:.0f}%; {len(unmeasured)} mutants import modules not "
              f"installed here); all but ament_flake8: {functional} "
              f"({100 * functional / measured:.0f}%)")


def not_installed_here(root: Path, base: Path) -> list[str]:
    """Top-level modules the mutant imports, and its base package does not, that this
    environment (the one colcon tests with) cannot import: its tests fail whatever the fix
    does."""
    import importlib.util

    added = _imported(root) - _imported(base)
    return sorted(n for n in added if importlib.util.find_spec(n) is None)


@functools.cache
def _imported(root: Path) -> frozenset[str]:
    """Top-level modules the package's Python files import (read once per folder)."""
    import ast

    names: set[str] = set()
    for path in root.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                names.update(alias.name.split(".")[0] for alias in node.names)
            elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
                names.add(node.module.split(".")[0])
    return frozenset(names)


def colcon_failures(root: Path) -> set[str]:
    """Names of the tests that fail (``build`` when it does not build) under colcon."""
    from pkgtool.commands.test import run as test

    (tested,) = test(str(root)).packages
    if not tested.built or tested.summary is None:
        return {"build"}
    return {case.name.rsplit(".", 1)[0].rsplit(".", 1)[-1] for case in tested.summary.cases
            if case.outcome not in ("passed", "skipped")}


def clean(scratch: Path) -> None:
    roots = [p.parent for p in sorted(REFERENCE.glob("*/package.xml"))]
    roots.append(scratch / "created" / "base_pkg")
    changed = []
    for source in roots:
        copy = scratch / "clean" / source.name
        shutil.copytree(source, copy)
        before = snapshot(copy)
        keys(copy, fix=True, unsafe_fixes=True)
        if snapshot(copy) != before:
            changed.append(source.name)
    print(f"clean packages: {len(roots)}; changed by --fix --unsafe-fixes: {changed or 'none'}")


def corpus(folder: Path, scratch: Path) -> None:
    from bench.realworld.corpus import ament_python_packages

    totals = {"packages": 0, "untouched": 0, "fixed": 0, "unparsable": 0, "new_findings": 0}
    for index, source in enumerate(ament_python_packages(folder)):
        copy = scratch / "corpus" / f"{index}" / source.name
        try:
            shutil.copytree(source, copy, symlinks=True)
        except (OSError, shutil.Error):
            continue
        totals["packages"] += 1
        before_files, before = snapshot(copy), keys(copy)
        after = keys(copy, fix=True)
        after_files = snapshot(copy)
        if after_files == before_files:
            totals["untouched"] += 1
            continue
        totals["fixed"] += 1
        broken = [p for p, data in after_files.items() if data != before_files.get(p)
                  and parses(p, before_files.get(p, b"").decode("utf-8", "replace"))
                  and not parses(p, data.decode("utf-8", "replace"))]
        totals["unparsable"] += bool(broken)
        new = set(after) - set(before)
        if new:
            totals["new_findings"] += 1
            print(f"  new findings in {source}: {sorted(new)[:3]}")
    print("real-world corpus:", totals)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--colcon", action="store_true", help="Also build and test mutants.")
    parser.add_argument("--corpus", type=Path, default=Path.home() / ".cache" / "pkgtool-corpus")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        scratch = Path(tmp)
        mutants(scratch, args.colcon)
        clean(scratch)
        if args.corpus.is_dir():
            corpus(args.corpus, scratch)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
