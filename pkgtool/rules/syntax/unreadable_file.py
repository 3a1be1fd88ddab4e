"""SYN002: a package file that must be text is binary, not UTF-8, too large or unreadable.

Other files over pkgtool's read limit are SYN004's note, not an error.
"""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax._problems import is_oversized_build_file, problem_hits


@rule("SYN002", "unreadable-file", Severity.ERROR,
      fix="Make the file a readable UTF-8 text file, or remove it")
def unreadable_file(package: Package) -> Iterator[Hit]:
    """A package file that must be text is binary, not UTF-8, too large, or cannot be opened.

    ## What it does
    Reports package.xml, setup.py, setup.cfg, Python modules and launch files that contain NUL
    bytes, are not valid UTF-8 or cannot be opened, and a package.xml, setup.py or setup.cfg
    larger than pkgtool reads (2 MiB), which no real package has. Any other file that large is
    only noted as not checked (SYN004).

    ## Why is this bad?
    Python 3 and ROS tools read these files as UTF-8 text; anything else fails at build or run
    time, often with an error far from the cause.

    ## Example
    A ``setup.py`` saved as UTF-16 by an editor, or a ``package.xml`` in Latin-1 with an
    accented maintainer name.

    ## Use instead
    Save the file as UTF-8 (without a byte-order mark).
    """
    labels = {"binary": "binary file", "not-utf8": "not UTF-8 text",
              "too-large": "file too large to check", "unreadable": "file cannot be read"}
    yield from problem_hits(package, labels,
                            lambda p: p.kind != "too-large" or is_oversized_build_file(p))
