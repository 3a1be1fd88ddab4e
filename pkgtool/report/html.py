"""The HTML writer: text a student controls made safe for an element or a quoted attribute.

Everything passes :func:`pkgtool.report.untrusted.block` first (control characters and
bidirectional overrides become visible escapes), then HTML escaping of ``& < > " '``; the
result cannot open a tag, close an attribute or start a script.
"""

from __future__ import annotations

import html

from pkgtool.report.untrusted import block


def text(value: object) -> str:
    """``value`` as HTML text or a double-quoted attribute value."""
    return html.escape(block(str(value)), quote=True)


def page(title: str, style: str, body: str) -> str:
    """A complete, self-contained HTML5 document (no script, no external resource)."""
    return ("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
            "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
            "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; "
            "style-src 'unsafe-inline'; img-src data:\">\n"
            f"<title>{text(title)}</title>\n<style>\n{style}</style>\n</head>\n"
            f"<body>\n{body}</body>\n</html>\n")
