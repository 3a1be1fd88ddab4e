"""No block of six or more lines stands twice in pkgtool/: shared code lives in one place.

Lines are compared stripped of indentation, blank lines and module-level imports skipped; a
block must hold some substance (not only brackets, quotes and keywords) to count.
"""

from __future__ import annotations

from collections import defaultdict
from pathlib import Path

PACKAGE = Path(__file__).resolve().parent.parent / "pkgtool"
SIZE = 6


def _blocks(path: Path) -> dict[tuple[str, ...], int]:
    """Every run of SIZE consecutive non-blank lines with substance, and the line it starts at."""
    numbered = [(n, line.strip()) for n, line in enumerate(path.read_text().splitlines(), 1)
                if line.strip() and not line.startswith(("from ", "import "))]
    found: dict[tuple[str, ...], int] = {}
    for start in range(len(numbered) - SIZE + 1):
        window = tuple(text for _, text in numbered[start:start + SIZE])
        if sum(len(text) >= 20 for text in window) >= SIZE // 2:
            found.setdefault(window, numbered[start][0])
    return found


def repeated(root: Path) -> list[str]:
    """Places where a block of one file below ``root`` stands again in another file."""
    places: dict[tuple[str, ...], list[str]] = defaultdict(list)
    for path in sorted(root.rglob("*.py")):
        for window, line in _blocks(path).items():
            places[window].append(f"{path.relative_to(root)}:{line}")
    return sorted(" ~ ".join(where) for where in places.values() if len(where) > 1)


def test_no_block_of_six_lines_is_repeated() -> None:
    assert repeated(PACKAGE) == []


def test_the_check_finds_a_repeated_block(tmp_path: Path) -> None:
    block = "".join(f"value_number_{i} = compute_something({i})\n" for i in range(SIZE))
    (tmp_path / "a.py").write_text("import os\n\n" + block)
    (tmp_path / "b.py").write_text("    " + block.replace("\n", "\n    ") + "print()\n")
    assert repeated(tmp_path) == ["a.py:3 ~ b.py:1"]
