"""Edits of setup.py: console scripts, data_files entries and the imports they need.

The static evaluator runs setup.py over plain data and tags every list, tuple and dict with
the literal that made it. An edit goes into that literal only when the literal still is the
whole value setup() receives (no later ``append``, ``+``, comprehension or ``**``); anything
else is refused with the code that computes it, so the user edits by hand where pkgtool
cannot be sure.
"""

from __future__ import annotations

import ast
import posixpath
from fnmatch import fnmatchcase
from typing import Any, NoReturn

from pkgtool.edit.core import Edit, EditError
from pkgtool.edit.pysource import PyDoc
from pkgtool.edit.source import Source
from pkgtool.model.setup_eval import Evaluation, evaluate
from pkgtool.model.setup_eval.entries import Malformed, data_files, entry_points
from pkgtool.model.setup_eval.tree import normalize
from pkgtool.model.setup_eval.values import Builtin, Dct, Lst, Tup
from pkgtool.model.span import ParseProblem, Span

_LITERALS = (ast.Constant, ast.List, ast.Tuple, ast.Dict, ast.JoinedStr)


class SetupDoc:
    """setup.py's source, its evaluation, and the ``setup(...)`` call node."""

    def __init__(self, source: Source, files: tuple[str, ...]) -> None:
        self.doc = PyDoc(source)
        found = evaluate(source.path, source.text, files)
        if isinstance(found, ParseProblem) or found.call is None:
            raise EditError(f"`{source.path}` has no `setup(...)` call pkgtool can read: "
                            "make the change by hand.")
        self.evaluation: Evaluation = found
        self.call = found.call
        self.nodes: dict[tuple[int, int], list[ast.AST]] = {}
        for node in ast.walk(self.doc.tree):
            if hasattr(node, "col_offset"):
                where = (node.lineno, node.col_offset + 1)  # type: ignore[attr-defined]
                self.nodes.setdefault(where, []).append(node)
        span = self.call.span
        self.node = next((n for n in self.nodes.get((span.line, span.col), [])
                          if isinstance(n, ast.Call)), None)
        if self.node is None or any(key == "**" for key, _ in self.call.unresolved):
            raise self._refusal("**", "the setup() call")

    # Console scripts ---------------------------------------------------------------------

    def add_console_script(self, name: str, target: str) -> list[Edit]:
        """Register ``name = target`` in ``entry_points['console_scripts']``."""
        spec = f"{name} = {target}"
        value = self.value("entry_points", "the entry points")
        if value is None:
            item = "entry_points=" + "{" + f"{self.doc.string('console_scripts')}: " \
                f"[{self.doc.string(spec)}]" + "}"
            return self._into_call(item)
        try:
            known = entry_points(value, self.call.spans["entry_points"])
        except Malformed:
            raise self._refusal("entry_points", "the entry points") from None
        for entry in known:
            if entry.group == "console_scripts" and entry.name == name:
                if f"{entry.module}:{entry.attr}" == target:
                    return []
                raise EditError(f"setup.py already registers the console script `{name}` as "
                                f"`{entry.spec}`: pick another name or change it by hand.")
        groups = self._literal(value, "the entry points")
        assert isinstance(groups, ast.Dict)
        scripts = value.get("console_scripts")
        if scripts is None:
            item = f"{self.doc.string('console_scripts')}: [{self.doc.string(spec)}]"
            return self._into_dict(groups, item)
        if isinstance(scripts, str):
            raise EditError("setup.py gives `console_scripts` as one string: write it as a list "
                            f"and add `{spec}` to it by hand.")
        listed = self._literal(scripts, "the console scripts")
        return self._into_sequence(listed, self.doc.string(spec))

    def console_scripts(self) -> list[tuple[str, str]]:
        """(name, module) of each console script, as far as setup.py evaluates."""
        value = self.call.values.get("entry_points")
        try:
            found = entry_points(value, self.call.spans["entry_points"]) if value else ()
        except Malformed:
            return []
        return [(e.name, e.module) for e in found if e.group == "console_scripts" and e.valid]

    # data_files --------------------------------------------------------------------------

    def installs(self, destination: str, path: str) -> bool:
        """True when data_files already installs ``path`` into ``destination``."""
        value = self.value("data_files", "data_files")
        if value is None:
            return False
        try:
            entries = data_files(value, self.evaluation.tree, self.call.spans["data_files"])
        except Malformed:
            raise self._refusal("data_files", "data_files") from None
        for entry in entries:
            if normalize(entry.destination) != normalize(destination):
                continue
            for source in entry.sources:
                pattern = normalize(source.pattern) or source.pattern
                if pattern == path or (source.is_glob and fnmatchcase(path, pattern)):
                    return True
        return False

    def add_data_files(self, folder: str, pattern: str, package: str, *, files: bool = False
                       ) -> list[Edit]:
        """Install ``pattern`` (a glob; a literal path with ``files``) into
        ``share/<package>/<folder>``."""
        destination = posixpath.join("share", package, folder).rstrip("/")
        if self.installs(destination, pattern):
            return []
        name = self._bound_to(package, str)
        if folder:
            join, imports = self._function("os.path.join", ("os", None))
            target = (f"{join}({self.doc.string('share')}, {name or self.doc.string(package)}"
                      f", {self.doc.string(folder)})")
        else:
            imports = []
            target = f"{self.doc.string('share/')} + {name}" if name \
                else self.doc.string(destination)
        if files:
            sources = f"[{self.doc.string(pattern)}]"
        else:
            sources, glob_import = self.glob_call(pattern)
            imports += glob_import
        return self.add_data_entry(f"({target}, {sources})") + self.doc.add_imports(imports)

    def add_data_entry(self, item: str) -> list[Edit]:
        """Edits appending the entry ``item`` (source text) to data_files."""
        value = self.value("data_files", "data_files")
        if value is None:
            return self._into_call(f"data_files=[{item}]")
        return self._into_sequence(self._literal(value, "data_files"), item)

    def glob_call(self, pattern: str) -> tuple[str, list[tuple[str, str | None]]]:
        """``glob('pattern')`` as setup.py spells it, and the import it needs."""
        glob, glob_import = self._function("glob.glob", ("glob", "glob"))
        return f"{glob}({self.doc.string(pattern)})", glob_import

    def replace_sequence(self, value: Any, replacement: str, what: str) -> Edit:
        """An edit writing ``replacement`` over the list or tuple literal that is ``value``."""
        return self.edit(self._literal(value, what), replacement)

    def remove_from(self, sequence: Any, item: object, what: str) -> Edit:
        """An edit deleting the string literal ``item`` from the list literal ``sequence``."""
        node = self._literal(sequence, what)
        span = getattr(item, "span", None)
        element = next((e for e in node.elts  # type: ignore[attr-defined]
                        if span and isinstance(e, ast.Constant) and e.value == item
                        and (e.lineno, e.col_offset + 1) == (span.line, span.col)), None)
        if element is None:
            self.refuse(f"computes an item of {what}")
        return self.doc.remove_item(self.doc.start(element), self.doc.end(element),
                                    self.doc.end(node) - 1)

    def glob_pattern(self, span: Span) -> ast.Constant:
        """The string literal giving the pattern of the glob call at ``span``."""
        call = next((n for n in self.nodes.get((span.line, span.col), [])
                     if isinstance(n, ast.Call)), None)
        first = call.args[0] if call is not None and call.args else None
        if not isinstance(first, ast.Constant) or not isinstance(first.value, str):
            self.refuse(f"builds the glob pattern on line {span.line} with code")
        return first

    # Values ------------------------------------------------------------------------------

    def replace_value(self, value: object, replacement: str, what: str) -> Edit:
        """An edit writing the expression ``replacement`` over the literal that is ``value``.

        Only a string literal that produced exactly ``value`` (wherever it is written, e.g.
        ``package_name = '...'``) is replaced; anything computed is refused.
        """
        span = getattr(value, "span", None)
        candidates = self.nodes.get((span.line, span.col), []) if span else []
        node = next((n for n in candidates if isinstance(n, ast.Constant)
                     and isinstance(value, str) and n.value == value), None)
        if node is None:
            line = f" (line {span.line})" if span else ""
            raise EditError(f"setup.py computes {what} with code{line}, not as one string "
                            "literal: make the change by hand.")
        return self.edit(node, replacement)

    def edit(self, node: ast.AST, replacement: str) -> Edit:
        """An edit writing ``replacement`` over ``node``'s source."""
        return Edit(self.doc.source.path, self.doc.start(node), self.doc.end(node), replacement)

    def refuse(self, why: str) -> NoReturn:
        """Raise the EditError saying setup.py ``why`` (what it does that pkgtool won't edit)."""
        raise EditError(f"setup.py {why}: make the change by hand.")

    def keyword(self, name: str) -> ast.keyword | None:
        """The ``name=`` keyword of the setup() call, if given."""
        assert isinstance(self.node, ast.Call)
        return next((k for k in self.node.keywords if k.arg == name), None)

    def replace_keyword(self, name: str, replacement: str) -> Edit:
        """An edit writing ``replacement`` (``key=value``) over the whole ``name=...``."""
        found = self.keyword(name)
        assert found is not None
        return self.edit(found, replacement)

    def remove_keyword(self, name: str) -> Edit:
        """An edit deleting ``name=...`` from the setup() call, with its comma and line."""
        found = self.keyword(name)
        assert found is not None
        return self.doc.remove_item(self.doc.start(found), self.doc.end(found),
                                    self.doc.end(self.node) - 1)

    def add_to_dict(self, value: Any, item: str, what: str) -> list[Edit]:
        """Edits adding ``key: value`` source ``item`` to the dict literal that is ``value``."""
        node = self._literal(value, what)
        assert isinstance(node, ast.Dict)
        return self._into_dict(node, item)

    def expression(self, value: object, fallback: str) -> str:
        """A module-level name bound to the string ``value`` (``package_name``), else
        ``fallback``."""
        return self._bound_to(value, str) or fallback

    # Helpers -----------------------------------------------------------------------------

    def value(self, keyword: str, what: str) -> Any:
        """The evaluated value of ``keyword`` (None when absent); EditError when computed."""
        if any(key == keyword for key, _ in self.call.unresolved):
            raise self._refusal(keyword, what)
        return self.call.values.get(keyword)

    def _refusal(self, keyword: str, what: str) -> EditError:
        why = dict(self.call.unresolved).get(keyword)
        where = f" (`{why.source}` on line {why.span.line})" if why else ""
        return EditError(f"setup.py computes {what} with code pkgtool does not evaluate{where}: "
                         "make the change by hand.")

    def _literal(self, value: Any, what: str) -> ast.AST:
        """The literal that is exactly ``value``, or EditError saying it is computed."""
        span = getattr(value, "span", None)
        kinds = (ast.Dict,) if isinstance(value, Dct) else (ast.List, ast.Tuple)
        candidates = self.nodes.get((span.line, span.col), []) if span else []
        node = next((n for n in candidates if isinstance(n, kinds)), None)
        if node is None or not isinstance(value, (Dct, Lst, Tup)) or not _same(node, value):
            line = f" (line {span.line})" if span else ""
            raise EditError(f"setup.py builds {what} with code{line}, not as one literal "
                            "pkgtool can extend: make the change by hand.")
        return node

    def _into_sequence(self, node: ast.AST, item: str) -> list[Edit]:
        elements = node.elts  # type: ignore[attr-defined]
        return self.doc.insert_item(node, [(self.doc.start(e), self.doc.end(e)) for e in elements],
                                    item)

    def _into_dict(self, node: ast.Dict, item: str) -> list[Edit]:
        pairs = [(self.doc.start(k), self.doc.end(v)) for k, v in zip(node.keys, node.values)
                 if k is not None]
        return self.doc.insert_item(node, pairs, item)

    def _into_call(self, item: str) -> list[Edit]:
        call = self.node
        assert isinstance(call, ast.Call)
        parts = sorted([*call.args, *call.keywords], key=lambda n: (n.lineno, n.col_offset))
        opening = self.doc.text.index("(", self.doc.end(call.func))
        return self.doc.insert_item(call, [(self.doc.start(p), self.doc.end(p)) for p in parts],
                                    item, opening=opening)

    def _bound_to(self, value: object, kind: type) -> str | None:
        """A module-level name bound to ``value`` (e.g. ``package_name``), if any."""
        names = self.evaluation.scope.names
        return next((n for n, v in names.items() if isinstance(v, kind) and v == value
                     and not n.startswith("__")), None)

    def _function(self, qualified: str, fallback: tuple[str, str | None]
                  ) -> tuple[str, list[tuple[str, str | None]]]:
        """How setup.py can call ``qualified`` (``os.path.join``), and any import it needs."""
        parts = qualified.split(".")
        for depth in range(len(parts), 0, -1):
            name = self._bound_to(Builtin(".".join(parts[:depth])), Builtin)
            if name:
                return ".".join([name, *parts[depth:]]), []
        spelled = fallback[1] or qualified
        return spelled, [fallback]


def _same(node: ast.AST, value: Any) -> bool:
    """True when the literal ``node`` evaluated to ``value`` and nothing changed it since."""
    if isinstance(node, ast.Dict):
        if any(k is None for k in node.keys) or len(node.keys) != len(value):
            return False
        return all(_at(key, item) for key, item in zip(node.keys, value.keys()))
    elements = node.elts  # type: ignore[attr-defined]
    if any(isinstance(e, ast.Starred) for e in elements) or len(elements) != len(value):
        return False
    return all(_at(element, item) for element, item in zip(elements, value))


def _at(node: ast.AST, item: object) -> bool:
    """False when a literal ``node`` did not produce ``item`` (it was replaced or moved)."""
    span = getattr(item, "span", None)
    if not isinstance(node, _LITERALS) or span is None:
        return True
    where = (node.lineno, node.col_offset + 1)  # type: ignore[attr-defined]
    return (span.line, span.col) == where
