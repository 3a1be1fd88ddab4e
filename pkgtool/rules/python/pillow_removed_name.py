"""PYC084: Pillow names that Pillow 10 removed."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.pillow_removed import (FONT_MAKERS, REMOVED_CONSTANTS,
                                              REMOVED_DRAW_METHODS, REMOVED_FONT_METHODS,
                                              SYSTEM_PILLOW)
from pkgtool.model.package import Package
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
    value). Names the module probes (`hasattr(Image, 'ANTIALIAS')`) or reads where
    AttributeError is caught are left alone.

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
                    not guarded(node, index, probed):
                yield _hit(module.path, node, f"Image.{attr}", where,
                           f"`{REMOVED_CONSTANTS[attr]}`")
        for node in index.import_froms:
            if node.module == "PIL.Image" and node.level == 0:
                for alias in node.names:
                    if alias.name in REMOVED_CONSTANTS:
                        yield _hit(module.path, node, f"Image.{alias.name}", where,
                                   f"`{REMOVED_CONSTANTS[alias.name]}`",
                                   "the import raises ImportError")
        for call in index.calls:
            found = _removed_method(call, index)
            if found is not None:
                yield _hit(module.path, call, found[0], where, found[1])


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
    makers = {"PIL.ImageDraw.Draw"} if table is REMOVED_DRAW_METHODS else FONT_MAKERS
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
