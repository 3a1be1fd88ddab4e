"""What PYC008 and LCH005 share: why rcl rejects a node, topic or namespace name."""

from __future__ import annotations

from pkgtool.lazy_regex import lazy_pattern

_NODE_NAME = lazy_pattern(r"[A-Za-z_][A-Za-z0-9_]*")
_TOPIC_CHARS = lazy_pattern(r"[A-Za-z0-9_/~]*")


def node_name_problem(name: str) -> str | None:
    """Why rcl rejects ``name`` as a node name (``rmw_validate_node_name``), or None."""
    if _NODE_NAME.fullmatch(name) and len(name) <= 255:
        return None
    if not name:
        return "it is empty"
    if name[0].isdigit():
        return "it starts with a digit"
    return "only letters, digits and underscores are allowed"


def topic_name_problem(name: str) -> str | None:
    """Why rcl rejects ``name`` as a topic or service name, or None (substitutions: None)."""
    if "{" in name or "}" in name:
        return None
    if not name:
        return "it is empty"
    if not _TOPIC_CHARS.fullmatch(name):
        return "only letters, digits, underscores and `/` are allowed"
    if name.endswith("/") or "//" in name:
        return "it has an empty part between slashes"
    if "~" in name[1:] or (name.startswith("~") and len(name) > 1 and name[1] != "/"):
        return "`~` is only allowed as `~/` at the start"
    if any(part[:1].isdigit() for part in name.split("/")):
        return "a part starts with a digit"
    return None
