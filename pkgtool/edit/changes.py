"""Edits turned into whole-file changes: checked, shown as a unified diff, or written.

:func:`compute` reads each file once, splices its edits, and checks that what it produces still
parses whenever the original did (a safety net: pkgtool never writes a file it broke).
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable
from pathlib import Path

from pkgtool.edit.core import Edit, EditError, Fix, apply_edits, select_fixes
from pkgtool.edit.source import Source
from pkgtool.edit.write import Write, inside, write_all
from pkgtool.model.files import read_bytes
from pkgtool.records import record


@record
class FileChange:
    """The text of ``path`` before (None: a new file) and after, and its bytes to write."""

    path: str
    before: str | None
    after: str
    data: bytes


@record
class Changes:
    """Changed files of one package, in path order; empty when there is nothing to do."""

    root: Path
    files: tuple[FileChange, ...]

    def __bool__(self) -> bool:
        return bool(self.files)

    @property
    def paths(self) -> tuple[str, ...]:
        """The package-relative paths that change."""
        return tuple(change.path for change in self.files)

    def diff(self, label: str = "") -> str:
        """A unified diff of every change (``label`` prefixes the paths, e.g. the package)."""
        prefix = f"{label.rstrip('/')}/" if label else ""
        out = []
        for change in self.files:
            before = (change.before or "").splitlines(keepends=True)
            after = change.after.splitlines(keepends=True)
            old = "/dev/null" if change.before is None else f"a/{prefix}{change.path}"
            lines = difflib.unified_diff(before, after, old, f"b/{prefix}{change.path}")
            out.extend(line if line.endswith(("\n", "\r")) else line + "\n\\ No newline at end "
                       "of file\n" for line in lines)
        return "".join(out)

    def write(self) -> None:
        """Write every change atomically (all or none)."""
        write_all(self.root, [Write(c.path, c.data, c.before is None) for c in self.files])


def read_source(root: Path, relpath: str) -> Source | None:
    """The package file at ``relpath``, or None when it does not exist."""
    target = inside(root, relpath)
    if not target.exists():
        return None
    try:  # as the model reads: a FIFO or a device is not read, nor more than the limit
        data = read_bytes(str(target))
    except OSError as error:
        raise EditError(f"Cannot read `{relpath}`: {error.strerror or error}.") from None
    if isinstance(data, int):
        raise EditError(f"Cannot edit `{relpath}`: at {data} bytes it is too large to read.")
    return Source.from_bytes(relpath, data)


def compute(root: Path, edits: Iterable[Edit],
            sources: dict[str, Source | None] | None = None) -> Changes:
    """The changes ``edits`` make under ``root`` (``sources``: files already read)."""
    by_path: dict[str, list[Edit]] = {}
    for edit in edits:
        by_path.setdefault(edit.path, []).append(edit)
    known = dict(sources or {})
    files = []
    for path, group in sorted(by_path.items()):
        source = known[path] if path in known else read_source(root, path)
        change = _change(path, source, group)
        if change is not None:
            files.append(change)
    return Changes(root, tuple(files))


def _change(path: str, source: Source | None, edits: list[Edit]) -> FileChange | None:
    if any(edit.create for edit in edits):
        text = apply_edits("", edits)
        if source is not None:
            if source.text == text:
                return None  # created before: nothing to do
            raise EditError(f"`{path}` already exists with other content: pkgtool does not "
                            "replace it. Move it away or add what you need by hand.")
        return FileChange(path, None, text, Source(path, text).encode(text))
    if source is None:
        raise EditError(f"`{path}` does not exist; nothing to edit.")
    after = apply_edits(source.text, edits)
    if after == source.text:
        return None
    if parses(path, source.text) and not parses(path, after):
        raise EditError(f"pkgtool's edit of `{path}` would not parse; nothing was written. "
                        "Please report this as a pkgtool bug.")
    return FileChange(path, source.text, after, source.encode(after))


def fix_changes(root: Path, fixes: Iterable[Fix], *, unsafe: bool = False
                ) -> tuple[Changes, list[Fix], list[Fix]]:
    """(changes, applied, deferred) for ``fixes``: safe ones only unless ``unsafe``.

    A fix that overlaps one applied before it is deferred: apply the changes, re-read the
    package and ask the rules again, as ``lint --fix`` loops until nothing changes.
    """
    wanted = [fix for fix in fixes if fix.safe or unsafe]
    applied, deferred = select_fixes(wanted)
    return compute(root, [e for fix in applied for e in fix.edits]), applied, deferred


class Session:
    """Edits applied one step at a time in memory; :meth:`changes` compares with the disk.

    Each editor reads :meth:`source` (the text so far) and returns edits against it, so later
    steps see earlier ones; nothing is written until the caller writes :meth:`changes`.
    """

    def __init__(self, root: Path) -> None:
        self.root = root
        self.original: dict[str, Source | None] = {}
        self.current: dict[str, Source | None] = {}

    def source(self, path: str) -> Source | None:
        """The file's text as edited so far (None: it does not exist, nor was created)."""
        if path not in self.current:
            self.original[path] = self.current[path] = read_source(self.root, path)
        return self.current[path]

    def apply(self, edits: Iterable[Edit]) -> None:
        """Apply ``edits`` (against the current texts) in memory."""
        edits = list(edits)
        for edit in edits:
            self.source(edit.path)
        for path, change in ((c.path, c) for c in compute(self.root, edits, self.current).files):
            base = self.original.get(path)
            template = base if base is not None else Source(path, "")
            self.current[path] = Source(path, change.after, template.encoding, template.bom)

    def changes(self) -> Changes:
        """Every file that differs from the disk, as whole-file changes."""
        files = []
        for path, source in sorted(self.current.items()):
            before = self.original.get(path)
            if source is None or (before is not None and before.text == source.text):
                continue
            created = before is None
            data = source.encode(source.text)
            files.append(FileChange(path, None if created else before.text, source.text, data))
        return Changes(self.root, tuple(files))


def parses(path: str, text: str) -> bool:
    """True when ``text`` parses as what ``path``'s name says (Python, XML, YAML, INI)."""
    if path.endswith(".py"):
        import ast

        try:
            ast.parse(text)
        except (SyntaxError, ValueError, RecursionError, MemoryError):
            return False
        return True
    if path.endswith(".xml"):
        from pkgtool.model.xml import XmlElement, parse_xml

        return isinstance(parse_xml(path, text), XmlElement)
    if path.endswith((".yaml", ".yml")):
        from pkgtool.model.launch_reader import yaml_problem
        from pkgtool.model.span import ParseProblem

        return not isinstance(yaml_problem(path, text), ParseProblem)
    if path.endswith(".cfg"):
        from pkgtool.model.setup_cfg import SetupCfg, parse_setup_cfg

        return isinstance(parse_setup_cfg(path, text), SetupCfg)
    return True
