"""PYC084: Pillow names that Pillow 10 removed."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.pillow_removed import (DRAW_MAKERS, FONT_MAKERS, REMOVED_CONSTANTS,
                                              REMOVED_DRAW_METHODS, REMOVED_FONT_METHODS,
                                              SYSTEM_PILLOW)
from pkgtool.model.package import Package
from pkgtool.model.python_visitor import catches_import_error
from pkgtool.model.span import Span
from pkgtool.rules.python._attribute_guards import guarded, probed_names
from pkgtool.rules.registry import rule
from pkgtool.rules.relative_paths import assigned_value
from pkgtool.rules.syntax_trees import Index, installed_trees, resolved_attributes


@rule("PYC084", "pillow-removed-name", Severity.ERROR,
      fix="Use the replacement Pillow 10 documents (`Image.LANCZOS` for `Image.ANTIALIAS`, "
          "`textbbox()` for `textsize()`)")
def pillow_removed_name(package: Package) -> Iterator[Hit]:
    """Installed code uses a Pillow constant or method that Pillow 10 removed.

    ## What it does
    Reports `Image.ANTIALIAS`, `Image.LINEAR` and `Image.CUBIC` of `PIL.Image` (read as an
    attribute or imported by name), `textsize()` called on an `ImageDraw.Draw(...)`, and
    `getsize()` or `getoffset()` called on a font `ImageFont.truetype()` or
    `ImageFont.load_default()` made (directly, or through a name or `self.x` given that one
    value; also `multiline_textsize()` and `getsize_multiline()`). Code written for two
    Pillow releases is left alone: names the module probes (`hasattr(Image, 'ANTIALIAS')`),
    reads where AttributeError or ImportError is caught, and branches of a test asking which
    Pillow runs (`if hasattr(Image, 'Resampling'):`, `PIL.__version__`).

    ## Why is this bad?
    The line raises `AttributeError` when it runs. Ubuntu 24.04, which ROS 2 Jazzy and
    Kilted target, ships Pillow 10.2 (`python3-pil`), and pip installs Pillow 11 or newer:
    code from older tutorials (`img.resize(size, Image.ANTIALIAS)`,
    `draw.textsize(text, font)`) crashes the node there. Only Humble's Pillow 9.0 has them.

    ## Example
    ```python
    thumbnail = image.resize((64, 64), Image.ANTIALIAS)
    ```

    ## Use instead
    ```python
    thumbnail = image.resize((64, 64), Image.LANCZOS)
    ```
    """
    where = _shipped(package.context.distro)
    for module, _, index in installed_trees(package):
        if not any(i.top_level == "PIL" for i in module.imports):
            continue
        probed = probed_names(index)
        for node, owner, attr in resolved_attributes(index):
            if owner == "PIL.Image" and attr in REMOVED_CONSTANTS and \
                    not guarded(node, index, probed) and not _for_old_pillow(node, index):
                yield _hit(module.path, node, f"Image.{attr}", where,
                           f"`{REMOVED_CONSTANTS[attr]}`")
        for node in index.import_froms:
            if node.module == "PIL.Image" and node.level == 0 and \
                    not _for_old_pillow(node, index):
                for alias in node.names:
                    if alias.name in REMOVED_CONSTANTS:
                        yield _hit(module.path, node, f"Image.{alias.name}", where,
                                   f"`{REMOVED_CONSTANTS[alias.name]}`",
                                   "the import raises ImportError")
        for call in index.calls:
            found = _removed_method(call, index)
            if found is not None and isinstance(call.func, ast.Attribute) and \
                    not guarded(call.func, index, probed) and not _for_old_pillow(call, index):
                yield _hit(module.path, call, found[0], where, found[1])


_VERSION_TESTS = frozenset({"hasattr", "getattr", "__version__", "version", "parse",
                            "PILLOW_VERSION", "VERSION", "Version"})
"""Names a test of which Pillow runs reads (``hasattr(Image, 'Resampling')``,
``PIL.__version__``, ``parse(...)``)."""


def _for_old_pillow(node: ast.AST, index: Index) -> bool:
    """True inside a branch (of an ``if`` or a conditional expression) whose test asks which
    Pillow runs, or inside a ``try`` (or its handler) that catches ImportError or anything:
    code written for two Pillow releases."""
    child, parent = node, index.parents.get(id(node))
    while parent is not None:
        if isinstance(parent, (ast.If, ast.IfExp)) and child is not parent.test and \
                _VERSION_TESTS & _names_in(parent.test):
            return True
        if isinstance(parent, ast.Try) and any(catches_import_error(h) for h in parent.handlers):
            return True
        child, parent = parent, index.parents.get(id(parent))
    return False


def _names_in(test: ast.expr) -> set[str]:
    """The names and attribute names a test reads."""
    return {node.id if isinstance(node, ast.Name) else node.attr for node in ast.walk(test)
            if isinstance(node, (ast.Name, ast.Attribute))}


def _removed_method(call: ast.Call, index: Index) -> tuple[str, str] | None:
    """(the removed method as shown, its replacement) for ``draw.textsize(...)`` and
    ``font.getsize(...)`` on objects Pillow made; None for any other call."""
    func = call.func
    if not isinstance(func, ast.Attribute):
        return None
    table = REMOVED_DRAW_METHODS if func.attr in REMOVED_DRAW_METHODS else \
        REMOVED_FONT_METHODS if func.attr in REMOVED_FONT_METHODS else None
    if table is None:
        return None
    made = assigned_value(func.value, index)
    maker = index.qualified(made.func) if isinstance(made, ast.Call) and \
        isinstance(made.func, (ast.Name, ast.Attribute)) else None
    makers = DRAW_MAKERS if table is REMOVED_DRAW_METHODS else FONT_MAKERS
    if maker not in makers:
        return None
    return f"{func.attr}()", table[func.attr]


def _shipped(distro: str) -> str:
    """Which Pillow lacks the names, as said in the message."""
    system = SYSTEM_PILLOW.get(distro, "10.2")
    if system.startswith("9."):
        return (f"pip's Pillow (11 and newer) lacks it; the Pillow {system} Ubuntu ships for "
                f"{distro} still has it")
    return f"the Pillow {system} Ubuntu ships for {distro} (and pip's) lacks it"


def _hit(path: str, node: ast.AST, name: str, where: str, shown: str,
         raises: str = "the line raises AttributeError") -> Hit:
    return Hit(Span(path, node.lineno, node.col_offset + 1),  # type: ignore[attr-defined]
               f"`{name}` was removed in Pillow 10: {where}, so {raises}",
               f"Use {shown} instead")
