"""Splicing into Python source on ``ast`` positions: items into containers, imports, quotes.

Positions come from ``ast`` (1-based lines, UTF-8 byte columns) and are mapped onto the text
by :class:`~pkgtool.edit.source.Source`; everything between the positions stays untouched.
New items copy their neighbours' layout: one per line with the same indentation and trailing
comma in a multi-line container, inline in a one-line container (split one per line when the
line would pass 99 characters).
"""

from __future__ import annotations

import ast
import re
import sys
from collections.abc import Sequence

from pkgtool.edit.core import Edit, EditError
from pkgtool.edit.source import Source
from pkgtool.lazy_regex import lazy_pattern

MAX_LINE = 99
"""ament's flake8 line length."""
_PREFIX = lazy_pattern(r"^[rRbBuUfF]*")


class PyDoc:
    """A Python file's source and its ``ast``."""

    def __init__(self, source: Source) -> None:
        try:
            self.tree = ast.parse(source.text)
        except (SyntaxError, ValueError, RecursionError, MemoryError):
            raise EditError(f"`{source.path}` does not parse as Python: fix it (pkgtool lint "
                            "says where) and retry.") from None
        self.source = source
        self.text = source.text

    def start(self, node: ast.AST) -> int:
        """Offset of the first character of ``node``."""
        line, column = node.lineno, node.col_offset  # type: ignore[attr-defined]
        return self.source.offset_of_utf8(line, column)

    def end(self, node: ast.AST) -> int:
        """Offset just past ``node``."""
        line, column = node.end_lineno, node.end_col_offset  # type: ignore[attr-defined]
        return self.source.offset_of_utf8(line, column)

    def segment(self, node: ast.AST) -> str:
        """The source text of ``node``."""
        return self.text[self.start(node):self.end(node)]

    # Style -------------------------------------------------------------------------------

    def quote(self) -> str:
        """The quote character most string literals of the file use (``'`` on a tie)."""
        counts = {"'": 0, '"': 0}
        for node in ast.walk(self.tree):
            if isinstance(node, ast.Constant) and isinstance(node.value, str) and \
                    hasattr(node, "end_col_offset"):
                first = _PREFIX.sub("", self.text[self.start(node):self.start(node) + 4])[:1]
                if first in counts:
                    counts[first] += 1
        return '"' if counts['"'] > counts["'"] else "'"

    def string(self, value: str) -> str:
        """``value`` as a literal in the file's quote style."""
        literal = repr(value)
        if self.quote() == '"' and '"' not in value:
            literal = '"' + literal[1:-1].replace("\\'", "'") + '"'
        return literal

    def indent_unit(self) -> str:
        """The file's indentation step (four spaces unless it indents otherwise)."""
        steps = [len(m.group(1)) for m in re.finditer(r"^( +)\S", self.text, re.M)]
        smallest = min((s for s in steps if s), default=4)
        return " " * (smallest if smallest in (2, 3, 4, 8) else 4)

    # Containers --------------------------------------------------------------------------

    def insert_item(self, container: ast.AST, items: Sequence[tuple[int, int]], item: str,
                    *, opening: int | None = None) -> list[Edit]:
        """Edits adding ``item`` as the last element of ``container``.

        ``items`` are the (start, end) offsets of its present elements; ``opening`` is the
        offset of the opening bracket when it is not the node's first character (calls).
        """
        open_at = self.start(container) if opening is None else opening
        close_at = self.end(container) - 1
        if self.text[open_at] not in "([{" or self.text[close_at] not in ")]}":
            line = getattr(container, "lineno", 0)
            raise EditError(f"`{self.source.path}` line {line} has a container without "
                            "brackets: pkgtool does not extend it. Edit it by hand.")
        if not items:
            return self._into_empty(open_at, close_at, item)
        last_end = items[-1][1]
        comma = _comma_after(self.text, last_end, close_at)
        if self.source.line_start(last_end) == self.source.line_start(close_at):
            return self._inline(container, open_at, close_at, items, item, comma)
        return self._on_new_line(open_at, items, item, last_end, comma)

    def item_indent(self, container: ast.AST, items: Sequence[tuple[int, int]]) -> str:
        """The indentation a new item of a multi-line ``container`` gets."""
        indent = self.source.indent_at(items[-1][0]) if items else None
        if indent is None:
            opening = self.source.line_start(self.start(container))
            indent = _leading(self.text, opening) + self.indent_unit()
        return indent

    def remove_item(self, start: int, end: int, close_at: int) -> Edit:
        """An edit deleting the container item at ``start``..``end`` and its comma.

        An item alone on its line(s) goes with those whole lines (a comment after it too); an
        inline one with the comma after it, or, when it is last, the comma before it.
        ``close_at`` is the offset of the container's closing bracket.
        """
        path = self.source.path
        comma = _comma_after(self.text, end, close_at)
        after = comma + 1 if comma is not None else end
        line_start = self.source.line_start(start)
        line_end = self.source.line_end(after)
        if not self.text[line_start:start].strip() and _line_tail(self.source, after) == line_end:
            return Edit(path, line_start, min(line_end + len(self.source.newline),
                                              len(self.text)), "")
        if comma is not None:
            while after < close_at and self.text[after] in " \t":
                after += 1
            return Edit(path, start, after, "")
        before = start
        while before > 0 and self.text[before - 1].isspace():
            before -= 1
        return Edit(path, before - 1 if self.text[before - 1] == "," else start, end, "")

    def _into_empty(self, open_at: int, close_at: int, item: str) -> list[Edit]:
        inner = self.text[open_at + 1:close_at]
        path = self.source.path
        opening_indent = _leading(self.text, self.source.line_start(open_at))
        if "\n" not in inner and "\r" not in inner:
            if len(self._line_with(open_at, close_at, item)) <= MAX_LINE:
                return [Edit(path, open_at + 1, close_at, item)]
            newline = self.source.newline
            return [Edit(path, open_at + 1, close_at, newline + opening_indent +
                         self.indent_unit() + item + "," + newline + opening_indent)]
        at = self.source.line_start(close_at)
        if self.text[at:close_at].strip():  # something precedes the bracket on its line
            at = close_at
            return [Edit(path, at, at, self.source.newline + opening_indent +
                         self.indent_unit() + item + "," + self.source.newline)]
        indent = _leading(self.text, at) + self.indent_unit()
        if _leading(self.text, at) == opening_indent:
            indent = opening_indent + self.indent_unit()
        return [Edit(path, at, at, indent + item + "," + self.source.newline)]

    def _inline(self, container: ast.AST, open_at: int, close_at: int,
                items: Sequence[tuple[int, int]], item: str, comma: int | None) -> list[Edit]:
        path = self.source.path
        at = comma + 1 if comma is not None else items[-1][1]
        addition = f" {item}," if comma is not None else f", {item}"
        line_start = self.source.line_start(open_at)
        new_line = (self.text[line_start:at] + addition +
                    self.text[at:self.source.line_end(close_at)])
        multi_line_item = "\n" in item or "\r" in item
        if not multi_line_item and (len(new_line) <= MAX_LINE or
                                    "\n" in self.text[open_at:close_at]):
            return [Edit(path, at, at, addition)]
        newline = self.source.newline
        inner = _leading(self.text, line_start) + self.indent_unit()
        pieces = [self.text[s:e] for s, e in items] + [item]
        body = "".join(newline + inner + piece + "," for piece in pieces)
        closing = newline + _leading(self.text, line_start)
        return [Edit(path, open_at + 1, close_at, body + closing)]

    def _on_new_line(self, open_at: int, items: Sequence[tuple[int, int]], item: str,
                     last_end: int, comma: int | None) -> list[Edit]:
        path = self.source.path
        last_start = items[-1][0]
        indent = self.source.indent_at(last_start)
        if indent is None:
            indent = _leading(self.text, self.source.line_start(open_at)) + self.indent_unit()
        after = comma + 1 if comma is not None else last_end
        tail = _line_tail(self.source, after)
        text = self.source.newline + indent + item + ("," if comma is not None else "")
        if comma is not None:
            return [Edit(path, tail, tail, text)]
        if tail == last_end:
            return [Edit(path, last_end, last_end, "," + text)]
        return [Edit(path, last_end, last_end, ","), Edit(path, tail, tail, text)]

    def _line_with(self, open_at: int, close_at: int, item: str) -> str:
        start = self.source.line_start(open_at)
        end = self.source.line_end(close_at)
        return self.text[start:open_at + 1] + item + self.text[close_at:end]

    # Imports -----------------------------------------------------------------------------

    def has_import(self, module: str, name: str | None) -> bool:
        """True when the module level has ``import module`` / ``from module import name``."""
        for node in self.tree.body:
            if isinstance(node, ast.Import) and name is None:
                if any(a.name == module and a.asname is None for a in node.names):
                    return True
            elif isinstance(node, ast.ImportFrom) and node.module == module and node.level == 0:
                if any(a.name == name and a.asname is None for a in node.names):
                    return True
        return False

    def add_imports(self, wanted: Sequence[tuple[str, str | None]]) -> list[Edit]:
        """Edits adding each ``(module, name)`` import that is missing, in google order.

        ``(module, None)`` is ``import module``; imports that land on one spot share one edit.
        """
        sites: dict[tuple[int, str, str], list[tuple[tuple[int, str], str]]] = {}
        for module, name in dict.fromkeys(wanted):
            if self.has_import(module, name):
                continue
            line = f"import {module}" if name is None else f"from {module} import {name}"
            key = (_group(module), module.lower())
            sites.setdefault(self._import_site(key), []).append((key, line))
        return [Edit(self.source.path, at, at,
                     lead + self.source.newline.join(line for _, line in sorted(lines)) + trail)
                for (at, lead, trail), lines in sites.items()]

    def _import_site(self, key: tuple[int, str]) -> tuple[int, str, str]:
        """Where an import with sort ``key`` goes: (offset, text before it, text after it)."""
        imports = _import_block(self.tree.body)
        newline = self.source.newline
        same = [n for n in imports if _key(n)[0] == key[0]]
        if same:
            later = [n for n in same if _key(n) > key]
            if later:
                return self.source.line_start(self.start(later[0])), "", newline
            return self.source.line_end(self.end(same[-1])), newline, ""
        if imports:
            if key[0] < _key(imports[0])[0]:
                return self.source.line_start(self.start(imports[0])), "", newline * 2
            return self.source.line_end(self.end(imports[-1])), newline * 2, ""
        body = self.tree.body
        if body and _is_docstring(body[0]):
            return self.source.line_end(self.end(body[0])), newline * 2, ""
        if body:
            return self.source.line_start(self.start(body[0])), "", newline * 2
        return len(self.text), "", newline


def _leading(text: str, line_start: int) -> str:
    end = line_start
    while end < len(text) and text[end] in " \t":
        end += 1
    return text[line_start:end]


def _comma_after(text: str, offset: int, limit: int) -> int | None:
    """Offset of the comma after an item (comments and line breaks skipped), else None."""
    at = offset
    while at < limit:
        char = text[at]
        if char == ",":
            return at
        if char == "#":
            at = text.find("\n", at)
            if at < 0:
                return None
        elif not char.isspace() and char not in "\\)":
            return None
        at += 1
    return None


def _line_tail(source: Source, offset: int) -> int:
    """End of ``offset``'s line when only blanks or a comment follow; else ``offset``."""
    end = source.line_end(offset)
    rest = source.text[offset:end].strip()
    return end if not rest or rest.startswith("#") else offset


def _group(module: str) -> int:
    top = module.split(".")[0]
    if top == "__future__":
        return -1
    return 0 if top in sys.stdlib_module_names else 1


def _key(node: ast.stmt) -> tuple[int, str]:
    if isinstance(node, ast.ImportFrom):
        if node.level:
            return (2, node.module or "")
        return (_group(node.module or ""), (node.module or "").lower())
    assert isinstance(node, ast.Import)
    return (_group(node.names[0].name), node.names[0].name.lower())


def _is_docstring(node: ast.stmt) -> bool:
    return isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant) and \
        isinstance(node.value.value, str)


def _import_block(body: list[ast.stmt]) -> list[ast.stmt]:
    """The module's leading imports (after its docstring), up to the first other statement."""
    block = []
    for index, node in enumerate(body):
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            block.append(node)
        elif not (index == 0 and _is_docstring(node)):
            break
    return block
