"""Regular expressions compiled on first use, not when their module is imported.

A lint run imports every rule module, and their patterns (about 150) took some 10 ms to
compile at start-up, a tenth of a one-package run; most rules never reach theirs on a given
package. :func:`lazy_pattern` stands for ``re.compile`` at module level.
"""

from __future__ import annotations

import re
from typing import Any


class LazyPattern:
    """A compiled pattern made the first time one of its attributes is read (``search``,
    ``finditer``, ``pattern``...); it then forwards to the compiled pattern."""

    __slots__ = ("_source", "_flags", "_compiled")

    def __init__(self, source: str, flags: int = 0) -> None:
        self._source = source
        self._flags = flags
        self._compiled: re.Pattern[str] | None = None

    def __getattr__(self, name: str) -> Any:
        compiled = self._compiled
        if compiled is None:
            compiled = self._compiled = re.compile(self._source, self._flags)
        return getattr(compiled, name)


def lazy_pattern(source: str, flags: int = 0) -> re.Pattern[str]:
    """``re.compile(source, flags)``, compiled when first used."""
    return LazyPattern(source, flags)  # type: ignore[return-value]
