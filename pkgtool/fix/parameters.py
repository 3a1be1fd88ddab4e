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
from pkgtool.lazy_regex import lazy_pattern


_NAMESPACE_MISSED = lazy_pattern(r"^`([^`]+)`(?: \(`[^`]+`\))? cannot name the node")
"""A DAT009 message on a key that misses its node's namespace, and the key."""
_WRITE_KEY = lazy_pattern(r"^Write `([^`]+)`")


@fixer("DAT008", "Rename the misspelled key to `ros__parameters`")
def misspelled_key(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Write ``ros__parameters`` over the misspelled key (``ros_parameters``, ``ros_params``,
    ``parameters`` under a node name...), keeping its quotes and everything else in the file.
    Safe: the node then reads the parameters the file was written to give it. Other DAT008
    findings (values outside ``ros__parameters``, a missing node name) need the user."""
    for finding in findings:
        key = renamed(finding.fix)
        edit = _rewrite_key(package, finding, key, PARAMS_KEY) if key else None
        if edit is not None:
            yield Fix(f"Rename `{key}` to `{PARAMS_KEY}`", (edit,))


def _rewrite_key(package: Package, finding: Finding, key: str, new: str) -> Edit | None:
    """The edit writing ``new`` over the mapping key ``key`` where ``finding`` points, in the
    key's quotes; None when the key is not written there."""
    try:
        source = read_source(package.root, finding.span.path)
    except EditError:
        return None
    if source is None or finding.span.line > len(source.line_starts):
        return None
    at = source.line_starts[finding.span.line - 1] + finding.span.col - 1
    written = re.match(rf"""(["']?){re.escape(key)}\1(?=\s*:)""", source.text[at:])
    if written is None:
        return None
    quote = written.group(1)
    return Edit(source.path, at, written.end() + at, quote + new + quote)


def _key_taken(package: Package, finding: Finding) -> bool:
    """True when the file of ``finding`` already holds a top-level key named as its help says
    to write (``Write `talker```): renaming another block to it would merge the two."""
    meant = _WRITE_KEY.match(finding.fix or "")
    text = package.texts.get(finding.span.path)
    return meant is not None and text is not None and re.search(
        rf"""^(["']?){re.escape(meant[1])}\1\s*:""", text, re.MULTILINE) is not None


@fixer("DAT009", "Name the block after the node its misspelt name is close to", safe=False)
def node_block(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename a parameter file's node block to the one node name the file is passed to that
    is spelled like it (``talkr:`` to ``talker:``), and a block whose key misses the
    namespace the launch file gives its node to ``/**/talker`` (``/ns/talker`` for an
    absolute namespace), when the key is written whole at the top of the file (not nested
    under a namespace mapping). Not when the file already has a block of that name: its
    values would then override one another. Unsafe: it guesses which node was meant; the
    block reached no node before."""
    free = [f for f in findings if not _key_taken(package, f)]
    yield from renames(package, free,
                       re.compile(r"^`(?:[^`]*/)?([^`/]+)` is none of the nodes"))
    for finding in free:
        key = _NAMESPACE_MISSED.match(finding.message)
        meant = _WRITE_KEY.match(finding.fix or "")
        edit = _rewrite_key(package, finding, key[1], meant[1]) if key and meant else None
        if edit is not None:
            yield Fix(f"Rename `{key[1]}` to `{meant[1]}`", (edit,))
