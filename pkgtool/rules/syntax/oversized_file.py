"""SYN004: a package file larger than pkgtool reads, which is therefore not checked."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax._problems import is_oversized_build_file, problem_hits


@rule("SYN004", "oversized-file", Severity.INFO,
      fix="Nothing to do if the file is meant to be this large; ignore this note")
def oversized_file(package: Package) -> Iterator[Hit]:
    """A package file is larger than pkgtool reads (2 MiB), so it was not checked.

    ## What it does
    Notes Python modules, launch files and YAML files over pkgtool's read limit of 2 MiB:
    pkgtool skips them, so no rule checks their syntax, imports or entry points. This is a
    limit of pkgtool, not a defect of the package (generated tables, recorded test data and
    large test scripts exist). A package.xml, setup.py or setup.cfg that large is an error,
    SYN002.

    ## Why is this bad?
    It is not wrong in itself; the note says that what the file holds went unchecked, so a
    clean lint does not vouch for it.

    ## Example
    A 4 MB `test/replay_scan_data.py` holding recorded laser scans as Python literals.

    ## Use instead
    Keep the file if it must be this large, or move the data to a file the code loads (a
    `.npy`, `.csv` or `.bag` installed as data), which pkgtool does not need to read.
    """
    yield from problem_hits(package, {"too-large": "file not checked, larger than pkgtool "
                                      "reads"}, lambda p: not is_oversized_build_file(p))
