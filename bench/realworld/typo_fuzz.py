"""Typo fuzzer (not a test): drop one letter of a name or word in a package file, lint the
package, and list the typos lint stays silent about.

For every Python, XML, YAML and setup.cfg file of the package (a copy: the original is never
written), each name and each word of a string (four characters or more) is misspelt once at its
first and once at its last occurrence, by dropping its middle letter. The package is linted in
process after each typo; a typo that adds no error or warning to the package's own findings is
"silent". Many silent typos are harmless (a log text, a docstring, a topic the node alone
uses); the others are the classes of mistakes no rule catches yet: session 35 turned those it
found into SET016, PYC062-PYC065, DAT013 and wider PYC004, PYC023, PYC029, PYC048 and DEP008.

    .venv/bin/python bench/realworld/typo_fuzz.py SRC PACKAGE [--out silent.jsonl]

``SRC`` is the folder holding the package folder ``PACKAGE`` and its workspace neighbours
(``reference_packages``). Prints the silent typos of lines that hold code (comments, docstrings
and log texts left out); writes every mutation with the findings it added to ``--out``.
"""

from __future__ import annotations

import argparse
import ast
import io
import json
import re
import shutil
import sys
import tempfile
import tokenize
from collections.abc import Iterator
from pathlib import Path

from pkgtool.config import settings_for
from pkgtool.engine import check_package
from pkgtool.model.context import context_for, workspace_index
from pkgtool.model.package import load_package
from pkgtool.model.python_visitor import forget_trees

WORD = re.compile(r"[A-Za-z_][A-Za-z0-9_]{3,}")
SUFFIXES = (".py", ".xml", ".yaml", ".yml", ".cfg")
KEYWORDS = frozenset({"self", "None", "True", "False", "import", "from", "return", "class"})
_PROSE = re.compile(r"^\s*(#|\"\"\"|'''|<description|<maintainer|<license|<\?xml)"
                    r"|get_logger|print\(")


def _spans(path: Path, text: str) -> Iterator[tuple[int, int]]:
    """(start, end) offsets of the names and string words of ``text`` a typo may hit."""
    if path.suffix != ".py":
        yield from (m.span() for m in WORD.finditer(text))
        return
    starts = [0]
    for line in text.splitlines(keepends=True):
        starts.append(starts[-1] + len(line))
    try:
        for token in tokenize.generate_tokens(io.StringIO(text).readline):
            begin = starts[token.start[0] - 1] + token.start[1]
            end = starts[token.end[0] - 1] + token.end[1]
            if token.type == tokenize.STRING:
                yield from (m.span() for m in WORD.finditer(text, begin, end))
            elif token.type == tokenize.NAME and len(token.string) >= 4:
                yield begin, end
    except (tokenize.TokenError, IndentationError):
        return


def _linter(root: Path, roots: list[Path]):
    settings = settings_for([])

    def lint() -> set[tuple[str, str]]:
        package = load_package(root, context_for(root, workspace_index(roots),
                                                 settings.rosdistro))
        try:
            found = check_package(package, settings.rules, root_label=".",
                                  severities=settings.severities)
        finally:
            forget_trees()
        return {(f.code, f.message) for f in found if f.severity.name != "INFO"}
    return lint


def _typos(path: Path, text: str) -> Iterator[tuple[int, str, str, str]]:
    """(offset, word, typo, new text) for each typo of ``text``."""
    places: dict[str, list[tuple[int, int]]] = {}
    for begin, end in _spans(path, text):
        places.setdefault(text[begin:end], []).append((begin, end))
    for word, spans in places.items():
        if word in KEYWORDS:
            continue
        for begin, end in dict.fromkeys((spans[0], spans[-1])):
            middle = begin + (end - begin) // 2
            yield (begin, word, word[:middle - begin] + word[middle - begin + 1:],
                   text[:middle] + text[middle + 1:])


def _deletions(path: Path, text: str) -> Iterator[tuple[int, str, str, str]]:
    """(offset, line, "deleted", new text) for each one-line statement of a Python file
    (replaced by ``pass``), and each one-line element or key of an XML, YAML or cfg file."""
    lines = text.splitlines(keepends=True)
    starts = [0]
    for line in lines:
        starts.append(starts[-1] + len(line))
    if path.suffix == ".py":
        try:
            tree = ast.parse(text)
        except (SyntaxError, ValueError):
            return
        numbers = [node.lineno for node in ast.walk(tree) if isinstance(node, ast.stmt)
                   and node.end_lineno == node.lineno and not isinstance(node, ast.Pass)
                   and not (isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant))]
    else:
        numbers = [i + 1 for i, line in enumerate(lines) if line.strip() and
                   not line.lstrip().startswith(("#", "<!--", "<?xml")) and
                   (path.suffix != ".xml" or re.search(r"<(\w+)[^>]*>.*</\1>|/>", line))]
    for number in dict.fromkeys(numbers):
        line = lines[number - 1]
        indent = line[:len(line) - len(line.lstrip())]
        replacement = f"{indent}pass\n" if path.suffix == ".py" else ""
        yield (starts[number - 1], line.strip(), "deleted",
               text[:starts[number - 1]] + replacement + text[starts[number]:])


def fuzz(src: Path, name: str, mutations=_typos) -> Iterator[dict[str, object]]:
    """Every mutation of the package ``name`` under ``src`` and the findings it adds."""
    work = Path(tempfile.mkdtemp()) / "src"
    shutil.copytree(src / name, work / name, ignore=shutil.ignore_patterns(
        ".pkgtool_cache", "__pycache__"))
    for other in src.iterdir():
        if other.name != name and (other / "package.xml").is_file():
            shutil.copytree(other, work / other.name)
    root = work / name
    lint = _linter(root, sorted(p for p in work.iterdir() if (p / "package.xml").is_file()))
    before = lint()
    for path in sorted(p for p in root.rglob("*") if p.is_file() and p.suffix in SUFFIXES):
        text = path.read_text(encoding="utf-8", errors="replace")
        for begin, word, typo, mutated in mutations(path, text):
            path.write_text(mutated, encoding="utf-8")
            added = sorted(lint() - before)
            path.write_text(text, encoding="utf-8")
            line = text.count("\n", 0, begin) + 1
            yield {"file": str(path.relative_to(root)), "line": line, "word": word,
                   "typo": typo, "code": text.splitlines()[line - 1].strip()[:100],
                   "added": added}
    shutil.rmtree(work.parent, ignore_errors=True)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("src", type=Path)
    parser.add_argument("package")
    parser.add_argument("--out", type=Path, help="write every mutation here (JSON lines)")
    parser.add_argument("--delete", action="store_true",
                        help="delete one statement, element or key at a time instead")
    options = parser.parse_args(argv)
    out = options.out.open("w", encoding="utf-8") if options.out else None
    total = silent = 0
    for row in fuzz(options.src, options.package, _deletions if options.delete else _typos):
        total += 1
        if out:
            out.write(json.dumps(row) + "\n")
        if not row["added"]:
            silent += 1
            code = str(row["code"])
            if not _PROSE.search(code) and (options.delete or any(c in code for c in "=(.[:")):
                print(f"{row['file']}:{row['line']}: {row['word']} -> {row['typo']}  |  "
                      f"{code}")
    print(f"{total} mutations, {silent} silent (code lines listed above)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
