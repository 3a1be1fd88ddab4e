"""Findings to JSON and back, generically: every record field, whatever it holds (and the
workspace index's entries, :func:`index_record`).

A record (:mod:`pkgtool.records`) becomes ``{"@": "module:Class", field: value, ...}``, an
enum member ``{"@": "module:Class", "value": ...}``, a tuple ``{"@": "tuple", "items": [...]}``.
Reading accepts only classes of pkgtool's own modules: already imported ones, or the data-only
modules of :data:`_MODULE` (nothing else is imported or executed because of what a cache file
says); anything else raises :class:`BadEntry`.
"""

from __future__ import annotations

import importlib
import sys
from enum import Enum
from typing import Any

from pkgtool.model.context import WorkspacePackage
from pkgtool.records import fields, is_record
from pkgtool.lazy_regex import lazy_pattern

_MODULE = lazy_pattern(r"pkgtool\.(?:findings|model(?:\.\w+)+|edit(?:\.\w+)+)")
"""Modules a finding's values may come from that are safe to import because of an entry:
they only define data (a fix carries ``pkgtool.edit`` records, for example)."""


class BadEntry(ValueError):
    """A cache entry that is not what pkgtool wrote: ignored, then rewritten."""


def encode(value: Any) -> Any:
    """``value`` (records, enums, tuples, lists, dicts with str keys, JSON scalars) as JSON."""
    if isinstance(value, Enum):
        return {"@": _name(type(value)), "value": value.value}
    if is_record(value) and not isinstance(value, type):
        return {"@": _name(type(value)),
                **{f.name: encode(getattr(value, f.name)) for f in fields(value)}}
    if isinstance(value, tuple):
        return {"@": "tuple", "items": [encode(item) for item in value]}
    if isinstance(value, list):
        return [encode(item) for item in value]
    if isinstance(value, dict):
        if not all(isinstance(key, str) for key in value):
            raise TypeError("only dicts with str keys can be cached")
        return {"@": "dict", "items": {key: encode(item) for key, item in value.items()}}
    if value is None or isinstance(value, (str, int, float, bool)):
        return value
    raise TypeError(f"cannot cache a {type(value).__name__}")


def decode(data: Any) -> Any:
    """The value :func:`encode` gave ``data`` for; :class:`BadEntry` when it is not such data."""
    if isinstance(data, list):
        return [decode(item) for item in data]
    if not isinstance(data, dict):
        if data is None or isinstance(data, (str, int, float, bool)):
            return data
        raise BadEntry(f"unexpected {type(data).__name__}")
    tag = data.get("@")
    if tag == "tuple":
        return tuple(decode(item) for item in _items(data, list))
    if tag == "dict":
        return {key: decode(item) for key, item in _items(data, dict).items()}
    cls = _class(tag)
    try:
        if issubclass(cls, Enum):
            return cls(data["value"])
        return cls(**{key: decode(item) for key, item in data.items() if key != "@"})
    except (KeyError, TypeError, ValueError) as error:
        raise BadEntry(f"bad {tag}: {error}") from None


def _items(data: dict[str, Any], kind: type) -> Any:
    items = data.get("items")
    if not isinstance(items, kind):
        raise BadEntry("bad items")
    return items


def _name(cls: type) -> str:
    return f"{cls.__module__}:{cls.__qualname__}"


def _class(tag: Any) -> type:
    """The pkgtool record or enum named by ``tag``: from a module already imported, or one
    of the side-effect-free modules findings are made of (imported on demand)."""
    if not isinstance(tag, str) or ":" not in tag:
        raise BadEntry(f"bad tag {tag!r}")
    module_name, _, name = tag.partition(":")
    module = sys.modules.get(module_name) if module_name.split(".")[0] == "pkgtool" else None
    if module is None and _MODULE.fullmatch(module_name):
        try:
            module = importlib.import_module(module_name)
        except ImportError:
            module = None
    cls = getattr(module, name, None) if module is not None and "." not in name else None
    if not isinstance(cls, type) or not (is_record(cls) or issubclass(cls, Enum)):
        raise BadEntry(f"unknown class {tag!r}")
    return cls


def index_record(package: WorkspacePackage) -> list[Any]:
    """A workspace-index entry as JSON."""
    return [package.name, {kind: sorted(names) for kind, names in package.interfaces.items()},
            sorted(package.modules), dict(sorted(package.messages.items())), package.folder,
            package.setup_digest, sorted(package.depends),
            None if package.executables is None else sorted(package.executables),
            package.manifest, sorted(package.description_files)]


def index_entry(stored: Any) -> WorkspacePackage | None:
    """The :class:`WorkspacePackage` :func:`index_record` stored; None when it is not one."""
    try:
        name, interfaces, modules, messages, folder, setup_digest, depends, executables, \
            manifest, described = stored
        if isinstance(name, str) and isinstance(interfaces, dict) and \
                isinstance(modules, list) and all(isinstance(m, str) for m in modules) and \
                all(isinstance(k, str) and isinstance(v, list) and
                    all(isinstance(n, str) for n in v) for k, v in interfaces.items()) and \
                isinstance(messages, dict) and \
                all(isinstance(k, str) and isinstance(v, str) for k, v in messages.items()) and \
                isinstance(folder, str) and isinstance(setup_digest, str) and \
                isinstance(depends, list) and all(isinstance(d, str) for d in depends) and \
                (executables is None or isinstance(executables, list) and
                 all(isinstance(e, str) for e in executables)) and isinstance(manifest, bool) \
                and isinstance(described, list) and all(isinstance(d, str) for d in described):
            return WorkspacePackage(name, {k: frozenset(v) for k, v in interfaces.items()},
                                    frozenset(modules), messages, folder, setup_digest,
                                    frozenset(depends),
                                    None if executables is None else frozenset(executables),
                                    manifest, frozenset(described))
    except (TypeError, ValueError):
        pass
    return None
