"""The generated tables under ``pkgtool/knowledge/data/``: their text format, read and written.

A table is UTF-8 text. ``#`` lines are comments; a ``source ...`` line names where the data
came from; a ``@FLAGS`` line starts a group; every other line is one entry, a name and
optional space-separated values. An entry takes the flags of the group it is in (``hjkr``:
the distributions, ``-`` none). Tables are read on first use only: lint start-up never pays
for a table no rule asks for.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from functools import cache
from pathlib import Path

from pkgtool.records import record

DATA = Path(__file__).resolve().parent / "data"

DISTROS = ("humble", "jazzy", "kilted", "rolling")
"""The ROS 2 distributions the tables know, oldest first."""
DEFAULT_DISTRO = "jazzy"
"""The distribution linted for when none is configured."""
FLAGS = {distro: distro[0] for distro in DISTROS}
"""The one-letter flag of each distribution in a table."""


@record
class Table:
    """A parsed table: its first ``source`` line (without the word), each entry's group flags and
    the values of the entries that have any (as one space-separated string)."""

    source: str
    flags: dict[str, str]
    values: dict[str, str]


@cache
def read(name: str) -> Table:
    """The table ``data/<name>.txt``, parsed once per process (a few ms for the largest).

    Groups are split with ``str`` methods and names looked up through dicts built in C:
    lint pays this on every start, per table it uses.
    """
    head, *groups = (DATA / f"{name}.txt").read_text(encoding="utf-8").split("\n@")
    source = next((line[len("source "):] for line in head.splitlines()
                   if line.startswith("source ")), "")
    flags: dict[str, str] = {}
    values: dict[str, str] = {}
    for group in groups:
        group_flags, _, body = group.partition("\n")
        if " " in body:
            pairs = [line.partition(" ") for line in body.split("\n") if line]
            flags.update(dict.fromkeys([entry for entry, _, _ in pairs], group_flags))
            values.update((entry, rest) for entry, _, rest in pairs if rest)
        else:
            flags.update(dict.fromkeys(body.split("\n"), group_flags))
    flags.pop("", None)
    return Table(source, flags, values)


def render(title: str, source: str | Sequence[str],
           groups: Iterable[tuple[str, Iterable[str]]]) -> str:
    """The text of a table: a comment ``title``, the ``source`` line (one per source when
    there are several) and each (flags, lines)."""
    out = [f"# {line}" if line else "#" for line in title.splitlines()]
    out.extend(f"source {s}" for s in ([source] if isinstance(source, str) else source))
    for flags, lines in groups:
        out.append(f"@{flags}")
        out.extend(lines)
    return "\n".join(out) + "\n"


def flags_of(distros: Iterable[str]) -> str:
    """The flag letters of ``distros`` in the order of :data:`DISTROS` (``-`` for none)."""
    chosen = set(distros)
    return "".join(FLAGS[d] for d in DISTROS if d in chosen) or "-"


def write(texts: dict[str, str], output: Path) -> None:
    """Write each table ``name -> text`` to ``output/<name>.txt`` and say how big it is."""
    output.mkdir(parents=True, exist_ok=True)
    for name, text in texts.items():
        target = output / f"{name}.txt"
        target.write_text(text, encoding="utf-8")
        print(f"{target}: {len(text.encode())} bytes")


def generator_main(name: str, make: Callable[[], str], description: str,
                   argv: list[str] | None = None) -> None:
    """The command line of a generator that writes the one table ``name`` from ``make()``."""
    import argparse

    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--output", type=Path, default=DATA, help="where to write the table")
    write({name: make()}, parser.parse_args(argv).output)
