"""What differs between the Python versions pkgtool runs on (3.10 and later): one place each."""

from __future__ import annotations

import sys

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10 reads TOML with tomli, the same API
    import tomli as tomllib

__all__ = ["tomllib"]
