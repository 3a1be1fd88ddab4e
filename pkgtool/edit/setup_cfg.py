"""Edits of setup.cfg: set, rename or remove one option or section, keeping every other line."""

from __future__ import annotations


from pkgtool.edit.core import Edit, EditError
from pkgtool.edit.source import Source
from pkgtool.lazy_regex import lazy_pattern

_SECTION = lazy_pattern(r"^\[(?P<name>[^\]]+)\]\s*(?:[#;].*)?$")
_OPTION = lazy_pattern(r"^(?P<key>[^\s=:#;][^=:]*?)(?P<sep>\s*[=:]\s*)(?P<value>.*?)\s*$")


def _lines(source: Source) -> list[tuple[int, str]]:
    starts = source.line_starts
    return [(start, source.text[start:source.line_end(start)]) for start in starts
            if start < len(source.text) or start == 0]


def _find(source: Source, section: str, key: str, *, exact: bool = False
          ) -> tuple[int | None, int | None, int | None]:
    """(section header offset, option line offset, end of the section's last line).

    Keys match with dashes and underscores alike unless ``exact``.
    """
    header = option = last = None
    current = None
    wanted = key if exact else key.replace("-", "_")
    for start, line in _lines(source):
        found = _SECTION.match(line.strip())
        if found:
            current = found.group("name").strip()
            if current == section:
                header, last = start, source.line_end(start)
            continue
        if current != section:
            continue
        if line.strip() and not line.lstrip().startswith(("#", ";")):
            last = source.line_end(start)
            match = _OPTION.match(line)
            if match and not line[:1].isspace() and \
                    (match.group("key") if exact else match.group("key").replace("-", "_")) \
                    == wanted:
                option = start
    return header, option, last


def set_option(source: Source, section: str, key: str, value: str) -> list[Edit]:
    """Edits giving ``key`` the one-line ``value`` in ``[section]`` (added when missing)."""
    if "\n" in value or "\r" in value:
        raise EditError("pkgtool writes one-line setup.cfg values only.")
    header, option, last = _find(source, section, key)
    newline = source.newline
    if option is not None:
        line = source.text[option:source.line_end(option)]
        match = _OPTION.match(line)
        assert match is not None
        if match.group("value") == value and match.group("key") == key:
            return []
        return [Edit(source.path, option, source.line_end(option),
                     f"{key}{match.group('sep')}{value}")]
    if header is not None and last is not None:
        return [Edit(source.path, last, last, f"{newline}{key}={value}")]
    end = len(source.text)
    lead = newline if source.text and not source.text.endswith(("\n", "\r")) else ""
    return [Edit(source.path, end, end, f"{lead}[{section}]{newline}{key}={value}{newline}")]


def remove_option(source: Source, section: str, key: str) -> list[Edit]:
    """Edits deleting ``key`` (and its continuation lines) from ``[section]``."""
    _, option, _ = _find(source, section, key)
    if option is None:
        return []
    end = source.line_end(option)
    while end < len(source.text):
        following = source.line_end(end + len(source.newline))
        line = source.text[end + len(source.newline):following]
        if not line[:1].isspace() or not line.strip():
            break
        end = following
    stop = min(end + len(source.newline), len(source.text))
    return [Edit(source.path, option, stop, "")]


def rename_option(source: Source, section: str, key: str, new_key: str) -> list[Edit]:
    """Edits renaming the option written exactly ``key`` in ``[section]``, value kept."""
    _, option, _ = _find(source, section, key, exact=True)
    if option is None:
        return []
    return [Edit(source.path, option, option + len(key), new_key)]


def rename_section(source: Source, section: str, new_name: str) -> list[Edit]:
    """Edits renaming the header ``[section]`` (the first one) to ``[new_name]``."""
    header, _, _ = _find(source, section, "")
    if header is None:
        return []
    at = source.text.index(section, header)
    return [Edit(source.path, at, at + len(section), new_name)]


def has_section(source: Source, section: str) -> bool:
    """True when setup.cfg has a ``[section]`` header."""
    return _find(source, section, "")[0] is not None
