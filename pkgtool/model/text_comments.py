"""The text of an XML or YAML file as its readers take it: comments blanked (launch files,
and the URDF, xacro and RViz files naming packages)."""

from __future__ import annotations

import re

_COMMENTS = {"xml": re.compile(r"<!--.*?-->", re.DOTALL), "yaml": re.compile(r"(?m)(?:^|\s)#.*$")}


def without_comments(text: str, kind: str) -> str:
    """``text`` of a file of ``kind`` (``xml``, ``yaml``) with every comment's characters as
    spaces, its line breaks kept (offsets and lines stay)."""
    pattern = _COMMENTS.get(kind)
    return pattern.sub(lambda comment: re.sub(r"[^\n]", " ", comment.group(0)), text) \
        if pattern else text
