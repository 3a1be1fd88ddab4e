"""What rules report: a ``Hit`` from a rule, a ``Finding`` once the engine knows the rule."""

from __future__ import annotations

from enum import Enum

from pkgtool.model.span import Span
from pkgtool.records import record


class Severity(str, Enum):
    """How bad a finding is; ``error`` fails lint, ``warning`` fails only with ``--strict``."""

    ERROR = "error"
    WARNING = "warning"
    INFO = "info"

    @property
    def rank(self) -> int:
        """Higher is worse."""
        return {"info": 0, "warning": 1, "error": 2}[self.value]


@record
class Hit:
    """One problem a rule found: where, what (``message``) and how to fix it (``fix``).

    ``message`` states the problem in sentence case without a final period, names in backticks;
    ``fix`` is an imperative one-liner, or None when the rule's generic fix applies.
    ``related`` are the other places of the same mistake (one root cause, one hit): ``span``
    is the first or root place, the message names the others.

    ``cause`` names a root cause that hits of several rules can share (``package-name:x``:
    the package is called ``x`` somewhere it should not be). A ``consequence`` hit is folded by
    the engine into the hit of the same cause that is not one (the hit stating the cause),
    when that one is reported too; otherwise it stands alone.
    """

    span: Span
    message: str
    fix: str | None = None
    related: tuple[Span, ...] = ()
    cause: str = ""
    consequence: bool = False


@record
class Finding:
    """A hit with its rule's code and (possibly configured) severity, in a named package.

    ``root`` is the package root as the user named it, so reporters can print
    ``root/span.path`` relative to the current directory. ``internal`` marks a rule that
    raised instead of checking (the message names it); lint then exits with 3. ``related``
    are the hit's other places of the same mistake; ``manual`` that the rule's fixer makes no fix
    for it (:mod:`pkgtool.fix.offers`): only the user can mend it; ``unsafe_fix`` that the fixes
    it makes for it are all unsafe (only ``--unsafe-fixes`` applies them), though the fixer's
    others may be safe.
    """

    code: str
    severity: Severity
    package: str
    root: str
    span: Span
    message: str
    fix: str | None = None
    internal: bool = False
    related: tuple[Span, ...] = ()
    manual: bool = False
    unsafe_fix: bool = False

    @property
    def sort_key(self) -> tuple[str, str, int, int, str]:
        """Deterministic order: package root, path, line, column, code."""
        return (self.root, self.span.path, self.span.line, self.span.col, self.code)


def shortened(text: str, limit: int = 40) -> str:
    """``text`` as a message quotes it: cut to ``limit`` characters, ending in ``...``."""
    return text if len(text) <= limit else text[:limit - 3] + "..."
