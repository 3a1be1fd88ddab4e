"""Fixers of parameter files: a misspelled ``ros__parameters`` key gets its right name, a
node block misspelt gets the node's."""

from __future__ import annotations

import re
from collections.abc import Iterator

from pkgtool.edit.changes import read_source
from pkgtool.edit.core import Edit, EditError, Fix
from pkgtool.findings import Finding
from pkgtool.fix.common import renames
from pkgtool.fix.registry import fixer
from pkgtool.model.package import Package
from pkgtool.rules.data_files.malformed_parameter_file import PARAMS_KEY, renamed


@fixer("DAT008", "Rename the misspelled key to `ros__parameters`")
def misspelled_key(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Write ``ros__parameters`` over the misspelled key (``ros_parameters``, ``ros_params``,
    ``parameters`` under a node name...), keeping its quotes and everything else in the file.
    Safe: the node then reads the parameters the file was written to give it. Other DAT008
    findings (values outside ``ros__parameters``, a missing node name) need the user."""
    for finding in findings:
        key = renamed(finding.fix)
        if key is None:
            continue
        try:
            source = read_source(package.root, finding.span.path)
        except EditError:
            continue
        if source is None or finding.span.line > len(source.line_starts):
            continue
        at = source.line_starts[finding.span.line - 1] + finding.span.col - 1
        written = re.match(rf"""(["']?){re.escape(key)}\1(?=\s*:)""", source.text[at:])
        if written:
            quote = written.group(1)
            yield Fix(f"Rename `{key}` to `{PARAMS_KEY}`",
                      (Edit(source.path, at, written.end() + at, quote + PARAMS_KEY + quote),))


@fixer("DAT009", "Name the block after the node its misspelt name is close to", safe=False)
def node_block(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename a parameter file's node block to the one node name the file is passed to that
    is spelled like it (``talkr:`` to ``talker:``). Unsafe: it guesses which node was meant;
    the block reached no node before."""
    yield from renames(package, findings,
                       re.compile(r"^`(?:[^`]*/)?([^`/]+)` is none of the nodes"))
