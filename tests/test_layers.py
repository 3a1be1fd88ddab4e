"""The import graph follows the layers of the README's layout table: no package-level cycle.

Every import counts, at module level or inside a function, under ``TYPE_CHECKING`` or not: a
lazy import is still a dependency.
"""

from __future__ import annotations

import ast
import fnmatch
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PACKAGE = ROOT / "pkgtool"
_ROW = re.compile(r"^\|\s*(\d+)\s*\|([^|]*)\|")


def layers() -> dict[str, tuple[int, int]]:
    """Path pattern (``pkgtool/grade/``, ``pkgtool/cli*.py``) -> (layer, row), from README.md."""
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    section = text.split("## Layout", 1)[1].split("\n## ", 1)[0]
    found = {}
    for row, line in enumerate(section.splitlines()):
        match = _ROW.match(line)
        if match:
            for pattern in re.findall(r"`([^`]+)`", match.group(2)):
                found[pattern] = (int(match.group(1)), row)
    return found


def row_of(path: Path, table: dict[str, tuple[int, int]]) -> tuple[int, int] | None:
    """The (layer, row) of the README row a source file belongs to (None: in no row)."""
    relative = path.relative_to(ROOT).as_posix()
    for pattern, place in table.items():
        if relative.startswith(pattern) if pattern.endswith("/") else \
                fnmatch.fnmatchcase(relative, pattern):
            return place
    return None


def module_file(name: str) -> Path | None:
    """The file of module ``pkgtool.x.y`` (a package's ``__init__.py``), None if not ours."""
    parts = name.split(".")
    if parts[0] != "pkgtool":
        return None
    base = ROOT.joinpath(*parts)
    for candidate in (base.with_suffix(".py"), base / "__init__.py"):
        if candidate.is_file():
            return candidate
    return None


def imported_files(path: Path) -> set[Path]:
    """Files of pkgtool modules that the source file ``path`` imports."""
    name = ".".join(path.relative_to(ROOT).with_suffix("").parts)
    package = name.removesuffix(".__init__") if path.name == "__init__.py" else \
        name.rpartition(".")[0]
    return imports_of(path.read_text(encoding="utf-8"), package)


def imports_of(source: str, package: str) -> set[Path]:
    """Files of pkgtool modules that ``source``, a module of ``package``, imports."""
    found = set()
    for node in ast.walk(ast.parse(source)):
        names: list[str] = []
        if isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                parts = package.split(".")
                anchor = parts[:len(parts) - node.level + 1]
                base = ".".join(anchor + ([base] if base else []))
            names = [f"{base}.{alias.name}" for alias in node.names
                     if module_file(f"{base}.{alias.name}")] or [base]
        found.update(file for file in map(module_file, names) if file is not None)
    return found


def test_every_module_has_a_row_and_imports_only_lower_rows() -> None:
    table = layers()
    assert "pkgtool/commands/" in table and "pkgtool/model/" in table, "layout table not found"
    unplaced, upward = [], []
    for path in sorted(PACKAGE.rglob("*.py")):
        if path == PACKAGE / "__init__.py":
            continue
        place = row_of(path, table)
        if place is None:
            unplaced.append(path.relative_to(ROOT).as_posix())
            continue
        for target in sorted(imported_files(path)):
            other = row_of(target, table) if target != PACKAGE / "__init__.py" else None
            if other is not None and other != place and other[0] <= place[0]:
                upward.append(f"{path.relative_to(ROOT)} (layer {place[0]}) imports "
                              f"{target.relative_to(ROOT)} (layer {other[0]})")
    assert not unplaced, f"add these to the layout table in README.md: {unplaced}"
    assert not upward, "imports against the layers of README.md:\n" + "\n".join(upward)


def test_the_graph_sees_absolute_relative_and_lazy_imports() -> None:
    """Else the layering test above could pass by seeing nothing."""
    source = """
from pkgtool import testresults
from .. import engine
from ..rules import registry
import pkgtool.report.json

def later():
    from pkgtool.commands.lint import run
"""
    assert imports_of(source, "pkgtool.grade") == {
        PACKAGE / "testresults.py", PACKAGE / "engine.py", PACKAGE / "rules" / "registry.py",
        PACKAGE / "report" / "json.py", PACKAGE / "commands" / "lint.py"}
    assert PACKAGE / "engine.py" in imported_files(PACKAGE / "grade" / "criteria.py")
