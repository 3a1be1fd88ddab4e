"""The fields and constants of ``.msg``, ``.srv`` and ``.action`` files, as rosidl generates them.

Each message class becomes one entry in the form of pkgtool's message table
(``data/message_fields.txt``): ``name:type`` words for the fields, with the types rosidl gives
the generated Python class (``float64`` is ``double``, ``int32[]`` is ``sequence<int32>``,
``Header`` is ``std_msgs/Header``), and a bare word per constant (a field with a default
value also gives the constant ``<FIELD>__DEFAULT``). A service ``S`` gives the
classes ``S_Request`` and ``S_Response``, an action ``A`` gives ``A_Goal``, ``A_Result`` and
``A_Feedback``. A file with a line this reading does not understand gives no entry at all: its
classes stay unknown, so no rule judges them.
"""

from __future__ import annotations

import re
from pkgtool.lazy_regex import lazy_pattern

_PRIMITIVES = {"bool": "boolean", "byte": "octet", "char": "uint8", "float32": "float",
               "float64": "double", "int8": "int8", "uint8": "uint8", "int16": "int16",
               "uint16": "uint16", "int32": "int32", "uint32": "uint32", "int64": "int64",
               "uint64": "uint64", "string": "string", "wstring": "wstring"}
"""The ``.msg`` names of the basic types, and the names the generated classes give them."""
PARTS = {"msg": ("",), "srv": ("_Request", "_Response"),
         "action": ("_Goal", "_Result", "_Feedback")}
"""Kind -> the suffixes of the message classes of one file's sections, in order."""
_TYPE = lazy_pattern(r"(?:(?P<package>[A-Za-z]\w*)/)?(?P<base>[A-Za-z]\w*)"
                     r"(?:(?P<strbound><=\d+))?(?:\[(?P<bound><=)?(?P<size>\d*)\])?")
_NAME = lazy_pattern(r"[a-z][a-z0-9_]*")
_CONSTANT = lazy_pattern(r"(?P<type>\S+)\s+(?P<name>[A-Z][A-Z0-9_]*)\s*=")


def definitions(package: str, kind: str, name: str, text: str) -> dict[str, str]:
    """``package/kind/Class`` -> table entry for each message class the interface file of
    ``kind`` (``msg``, ``srv``, ``action``) called ``name`` defines with ``text``; empty when
    a line is not understood."""
    sections = re.split(r"^\s*---\s*$", text, flags=re.M)
    suffixes = PARTS.get(kind, ())
    if len(sections) != len(suffixes):
        return {}
    found: dict[str, str] = {}
    for suffix, section in zip(suffixes, sections):
        entry = _entry(package, section)
        if entry is None:
            return {}
        found[f"{package}/{kind}/{name}{suffix}"] = entry
    return found


def _entry(package: str, text: str) -> str | None:
    """The table entry of one message's definition, or None when a line is not understood."""
    words: list[str] = []
    for line in text.splitlines():
        content = line.strip()
        if not content or content.startswith("#"):
            continue
        constant = _CONSTANT.match(content)
        if constant is not None:
            if _field_type(package, constant["type"]) is None:
                return None
            words.append(constant["name"])
            continue
        parts = content.split("#", 1)[0].split()
        kind = _field_type(package, parts[0]) if len(parts) >= 2 else None
        if kind is None or not _NAME.fullmatch(parts[1]):
            return None
        words.append(f"{parts[1]}:{kind}")
        if len(parts) > 2:  # a default value: the class keeps it as a constant too
            words.append(f"{parts[1].upper()}__DEFAULT")
    return " ".join(words)


def _field_type(package: str, written: str) -> str | None:
    """The type the generated class gives a field declared with type ``written``."""
    found = _TYPE.fullmatch(written)
    if found is None:
        return None
    base, owner = found["base"], found["package"]
    if owner is None and base in _PRIMITIVES:
        element = _PRIMITIVES[base]
        if found["strbound"]:
            if base not in ("string", "wstring"):
                return None
            element = f"{element}<{found['strbound'][2:]}>"
    elif found["strbound"]:
        return None
    elif owner is None:
        element = "std_msgs/Header" if base == "Header" else f"{package}/{base}"
    else:
        element = f"{owner}/{base}"
    if found.group(0).endswith("]"):
        size = found["size"]
        if found["bound"]:
            return f"sequence<{element},{size}>" if size else None
        return f"{element}[{size}]" if size else f"sequence<{element}>"
    return element
