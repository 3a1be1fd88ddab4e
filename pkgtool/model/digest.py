"""SHA-256 without hashlib's start-up cost, for the lint cache and the workspace index."""

from __future__ import annotations

try:  # CPython's own SHA-256: hashlib loads OpenSSL first, ~5 ms of every cached run's start
    from _sha2 import sha256  # Python 3.12 and later
except ImportError:
    try:
        from _sha256 import sha256  # Python 3.10 and 3.11
    except ImportError:
        from hashlib import sha256

__all__ = ["sha256", "text_digest"]


def text_digest(*texts: str | None) -> str:
    """One digest of several texts, each told apart from an absent one (None)."""
    found = sha256()
    for text in texts:
        found.update(b"\x01" if text is None else b"\x00" + text.encode("utf-8", "surrogateescape")
                     + b"\x00")
    return found.hexdigest()
