"""One-off measurement: splicing on evaluator positions versus libcst, for setup.py edits.

Not a test and not run in CI: libcst is not a pkgtool dependency (this measurement is why).
Run it with libcst importable, e.g. from a scratch virtual environment:

    python3 -m venv /tmp/cstvenv && /tmp/cstvenv/bin/pip install libcst==1.9.0
    export PKGTOOL_LIBCST=/tmp/cstvenv/lib/python3.11/site-packages
    .venv/bin/python bench/edit_vs_libcst.py

Both editors add a console script to the list literal that pkgtool's static evaluator located,
on the setup.py files of the property tests (random quotes, layout, comments, CRLF). For each
it reports how many results keep the property-test guarantees (bytes outside the span kept,
the re-read model gains exactly the script, the neighbours' layout copied), the median time of
one edit with the file already evaluated, and the import time of the editing library.
"""

from __future__ import annotations

import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
if os.environ.get("PKGTOOL_LIBCST"):
    sys.path.append(os.environ["PKGTOOL_LIBCST"])

import libcst as cst  # noqa: E402
from hypothesis import given, settings  # noqa: E402
from libcst.metadata import MetadataWrapper, PositionProvider  # noqa: E402

from pkgtool.edit import apply_edits  # noqa: E402
from pkgtool.edit.setup_py import SetupDoc  # noqa: E402
from pkgtool.edit.source import Source  # noqa: E402
from tests.edit.test_properties import FILES, _only_inserts, _setup, setup_files  # noqa: E402

SPEC = "fresh_node = demo.fresh_node:main"


def cases(count: int) -> list[str]:
    found: list[str] = []

    @settings(max_examples=count, derandomize=True, database=None, deadline=None)
    @given(setup_files())
    def collect(case: tuple[str, list[str]]) -> None:
        found.append(case[0])

    collect()
    return found


def splice(doc: SetupDoc) -> str:
    return apply_edits(doc.doc.text, doc.add_console_script("fresh_node",
                                                            "demo.fresh_node:main"))


def _ws_without_comment(ws: object) -> object:
    if isinstance(ws, cst.ParenthesizedWhitespace):
        return ws.with_changes(first_line=cst.TrailingWhitespace(), empty_lines=[])
    return ws


def with_libcst(text: str, doc: SetupDoc) -> str:
    """The same edit with libcst: find the List at the evaluator's position, add an Element."""
    scripts = doc.call.values["entry_points"]["console_scripts"]
    line, column = scripts.span.line, scripts.span.col - 1
    wrapper = MetadataWrapper(cst.parse_module(text))
    positions = wrapper.resolve(PositionProvider)
    target = next(node for node, where in positions.items() if isinstance(node, cst.List)
                  and (where.start.line, where.start.column) == (line, column))
    quote = doc.doc.quote()
    value = cst.SimpleString(f"{quote}{SPEC}{quote}")

    class Add(cst.CSTTransformer):
        def leave_List(self, original: cst.List, updated: cst.List) -> cst.List:
            if original is not target:
                return updated
            elements = list(updated.elements)
            if not elements:
                return updated.with_changes(elements=[cst.Element(value)])
            last = elements[-1]
            if isinstance(last.comma, cst.Comma):
                before = elements[-2].comma.whitespace_after if len(elements) > 1 else \
                    updated.lbracket.whitespace_after
                elements[-1] = last.with_changes(comma=last.comma.with_changes(
                    whitespace_after=_ws_without_comment(before)))
                elements.append(cst.Element(value, comma=cst.Comma(
                    whitespace_after=last.comma.whitespace_after)))
            else:
                elements[-1] = last.with_changes(comma=cst.Comma(
                    whitespace_after=cst.SimpleWhitespace(" ")))
                elements.append(cst.Element(value))
            return updated.with_changes(elements=elements)

    return wrapper.module.visit(Add()).code


def keeps_guarantees(before: str, after: str, reference: str) -> tuple[bool, bool]:
    """(model and bytes right, layout identical to the splice result)."""
    try:
        specs = [e.spec for e in _setup(after).console_scripts]
    except Exception:  # noqa: BLE001 - a broken result simply fails
        return False, False
    right = specs == [e.spec for e in _setup(before).console_scripts] + [SPEC]
    kept = before.replace("\r\n", "\n") in after.replace("\r\n", "\n") or right
    return right and kept, after == reference


def timed(function, repeat: int = 5) -> float:  # type: ignore[no-untyped-def]
    samples = []
    for _ in range(repeat):
        start = time.perf_counter()
        function()
        samples.append(time.perf_counter() - start)
    return statistics.median(samples)


def import_time(module: str) -> float:
    code = f"import time; t = time.perf_counter(); import {module}; print(time.perf_counter() - t)"
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    runs = [float(subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                                 env=env, check=True).stdout) for _ in range(5)]
    return statistics.median(runs)


def main() -> None:
    texts = cases(300)
    tallies = {"splice": [0, 0], "libcst": [0, 0]}
    times: dict[str, list[float]] = {"splice": [], "libcst": []}
    for text in texts:
        doc = SetupDoc(Source("setup.py", text), FILES)
        if doc.add_console_script("fresh_node", "demo.fresh_node:main") == []:
            continue
        reference = splice(doc)
        _only_inserts(text, reference, doc.add_console_script("fresh_node",
                                                              "demo.fresh_node:main"))
        for name, edit in (("splice", lambda: splice(doc)),
                           ("libcst", lambda: with_libcst(text, doc))):
            try:
                result = edit()
            except Exception:  # noqa: BLE001
                continue
            right, same = keeps_guarantees(text, result, reference)
            tallies[name][0] += right
            tallies[name][1] += same
            times[name].append(timed(edit))
    count = len(times["splice"])
    print(f"{count} setup.py files of the property tests")
    for name in ("splice", "libcst"):
        right, same = tallies[name]
        print(f"{name:7} model right {right}/{count}, same layout as splice {same}/{count}, "
              f"median edit {statistics.median(times[name]) * 1e3:.2f} ms")
    print(f"evaluation of setup.py (both need it): "
          f"{timed(lambda: SetupDoc(Source('setup.py', texts[0]), FILES)) * 1e3:.2f} ms")
    print(f"import: libcst {import_time('libcst') * 1e3:.0f} ms, "
          f"pkgtool.edit.setup_py {import_time('pkgtool.edit.setup_py') * 1e3:.0f} ms")


if __name__ == "__main__":
    main()
