"""setup() keywords with structure: entry points and data_files, from evaluated values."""

from __future__ import annotations

from typing import Any

from pkgtool.model.setup_eval.tree import Tree, normalize
from pkgtool.model.setup_eval.values import GlobOrigin, PathValue
from pkgtool.model.setup_py import DataFile, DataSource, EntryPoint
from pkgtool.model.span import Span
from pkgtool.lazy_regex import lazy_pattern


class Malformed(Exception):
    """A keyword value whose shape setuptools would not accept; treated as unresolved."""


_SECTION = lazy_pattern(r"^\[\s*(?P<group>[^\]]+?)\s*\]$")
_VALUE = lazy_pattern(
    r"^(?P<module>[^:\[\s]+)\s*(?::\s*(?P<attr>[^\[\s]+)\s*)?(?P<extras>\[.*\])?$")


_PART = lazy_pattern(r"\w+")


def _dotted(name: str | None) -> bool:
    """Dotted parts of word characters, as setuptools' entry-point pattern requires.

    Not Python identifiers: the console-script wrapper loads the module with ``importlib``
    and the function with ``getattr``, so ``pkg.96:main`` or ``pkg.class:main`` work.
    """
    return bool(name) and all(_PART.fullmatch(p) for p in name.split("."))  # type: ignore


def parse_entry_point(group: str, spec: str, span: Span) -> EntryPoint:
    """One ``name = module:attr [extras]`` line; ``valid`` False when it does not parse."""
    name, equals, value = spec.partition("=")
    match = _VALUE.match(value.strip()) if equals else None
    if not match:
        return EntryPoint(group, name.strip(), "", None, spec.strip(), span, False)
    module, attr = match.group("module"), match.group("attr")
    valid = bool(name.strip()) and _dotted(module) and (attr is None or _dotted(attr))
    package, dot, last = module.rpartition(".")
    if dot and last == "__init__":
        module = package  # `pkg.__init__` loads pkg/__init__.py, the package's own module
    return EntryPoint(group, name.strip(), module, attr, spec.strip(), span, valid)


def _lines(text: str, span: Span) -> list[tuple[str, Span]]:
    """Non-blank, non-comment lines of a multi-line string with their lines in setup.py."""
    return [(line.strip(), span.at(span.line + offset, span.col if offset == 0 else 1))
            for offset, line in enumerate(text.splitlines())
            if line.strip() and not line.strip().startswith(("#", ";"))]


def entry_points(value: Any, span: Span) -> tuple[EntryPoint, ...]:
    """``entry_points`` as a dict of lists or strings, or an INI-style string."""
    found: list[EntryPoint] = []
    if isinstance(value, str):
        group = None
        for line, where in _lines(value, _span_of(value, span)):
            section = _SECTION.match(line)
            if section:
                group = section.group("group")
            elif group is None:
                raise Malformed(line)
            else:
                found.append(parse_entry_point(group, line, where))
        return tuple(found)
    if not isinstance(value, dict):
        raise Malformed(repr(value))
    for group, specs in value.items():
        if not isinstance(group, str):
            raise Malformed(repr(group))
        items = [specs] if isinstance(specs, str) else specs
        if not isinstance(items, (list, tuple)) or not all(isinstance(s, str) for s in items):
            raise Malformed(repr(specs))
        for item in items:
            for line, where in _lines(item, _span_of(item, span)):
                found.append(parse_entry_point(group, line, where))
    return tuple(found)


def _span_of(value: Any, fallback: Span) -> Span:
    return getattr(value, "span", None) or fallback


def data_files(value: Any, tree: Tree, span: Span) -> tuple[DataFile, ...]:
    """``data_files``: ``(destination, [sources])`` pairs, or bare files for the prefix root."""
    if not isinstance(value, (list, tuple)):
        raise Malformed(repr(value))
    result = []
    for entry in value:
        where = _span_of(entry, span)
        if isinstance(entry, (str, PathValue)):
            result.append(DataFile("", _sources([entry], tree, where), where))
            continue
        if not isinstance(entry, (list, tuple)) or len(entry) != 2 or \
                not isinstance(entry[0], (str, PathValue)):
            raise Malformed(repr(entry))
        destination, sources = str(entry[0]), entry[1]
        if isinstance(sources, str):
            source = DataSource(str(sources), False, (), _span_of(sources, where))
            result.append(DataFile(destination, (source,), where, sources_is_text=True))
        elif isinstance(sources, (list, tuple, set)):
            result.append(DataFile(destination, _sources(sources, tree, where), where))
        else:
            raise Malformed(repr(sources))
    return tuple(result)


def _sources(items: Any, tree: Tree, span: Span) -> tuple[DataSource, ...]:
    globbed: dict[GlobOrigin, list[str]] = {o: [] for o in getattr(items, "origins", ())}
    plain: list[DataSource] = []
    for item in items:
        if not isinstance(item, (str, PathValue)):
            raise Malformed(repr(item))
        origin = getattr(item, "glob", None)
        if origin is not None:
            globbed.setdefault(origin, []).append(normalize(str(item)) or str(item))
            continue
        path = normalize(str(item))
        exists = path is not None and tree.is_file(path)
        plain.append(DataSource(str(item), False, (path,) if exists else (), _span_of(item, span)))
    sources = [DataSource(o.pattern, True, tuple(m), o.span) for o, m in globbed.items()]
    return tuple(sorted(sources + plain, key=lambda s: (s.span.line, s.span.col)))
