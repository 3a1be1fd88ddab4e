"""Where something stands in a package: a POSIX path relative to the package root, 1-based."""

from __future__ import annotations

from pkgtool.records import record


@record(order=True)
class Span:
    """A position in a file of the package (``line``/``col`` are 1-based; 0 means unknown)."""

    path: str
    line: int = 0
    col: int = 0

    def at(self, line: int, col: int = 0) -> Span:
        """Return a span in the same file at another position."""
        return Span(self.path, line, col)

    @classmethod
    def of_offset(cls, path: str, text: str, offset: int) -> Span:
        """The span of character ``offset`` of ``text``, the content of ``path``."""
        return cls(path, text.count("\n", 0, offset) + 1, offset - text.rfind("\n", 0, offset))


@record
class ParseProblem:
    """A file that could not be read or parsed; rules of the SYN family turn these into findings.

    ``kind`` is one of: ``unreadable``, ``binary``, ``too-large``, ``not-utf8``, ``empty``,
    ``xml-syntax``, ``xml-entity``, ``python-syntax``, ``yaml-syntax``, ``cfg-syntax``.
    """

    kind: str
    span: Span
    detail: str


@record
class Unresolved:
    """An expression the static evaluator refused to guess (dynamic code); never reported."""

    source: str
    span: Span
