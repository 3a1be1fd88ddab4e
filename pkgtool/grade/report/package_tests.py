"""Render ``pkgtool test`` results: text, JSON or JUnit XML (pytest's cases, per package).

Test names, messages, details and build logs come from the package's code: the text report
shows names on one line and quotes details and logs behind a ``|`` gutter
(:mod:`pkgtool.report.untrusted`); JSON and JUnit go through their format's one writer.
"""

from __future__ import annotations

from collections.abc import Sequence

from pkgtool.grade.runner import first_error
from pkgtool.report.json import document
from pkgtool.report.junit import Case, Suite, write
from pkgtool.report.untrusted import line, quoted
from pkgtool.testresults import PackageTests

FORMATS = ("text", "json", "junit")
_ELEMENTS = {"failed": "failure", "error": "error", "skipped": "skipped", "passed": "passed"}


def render(fmt: str, packages: Sequence[PackageTests], *, isolation: str) -> str:
    """The tested ``packages`` in ``fmt`` (one of FORMATS); ``isolation`` is the sandbox used."""
    return {"text": _text, "json": _json, "junit": _junit}[fmt](packages, isolation)


def _text(packages: Sequence[PackageTests], isolation: str) -> str:
    out = []
    for package in packages:
        name, summary = line(package.name), package.summary
        if summary is None:
            limit = f" ({line(package.limit)})" if package.limit else ""
            first = first_error(package.output)
            out += [f"{name}: BUILD FAILED{limit}",
                    *quoted(package.output, "  ", last=40),
                    *([f"{name}: first error: {line(first)}"] if first else [])]
            continue
        for case in summary.cases:
            out.append(f"  {case.outcome.upper():7} {line(case.name)} ({case.seconds:.2f} s)")
            if case.outcome in ("failed", "error"):
                out += quoted(case.details, "      ", last=15)
        verdict = "ok" if package.ok else "FAILED"
        limit = f"; {line(package.limit)}" if package.limit else ""
        out.append(f"{name}: {verdict}: {line(summary.describe())}{limit} "
                   f"({package.seconds:.1f} s)")
    out.append(f"sandbox: {line(isolation)}")
    return "\n".join(out) + "\n"


def _json(packages: Sequence[PackageTests], isolation: str) -> str:
    entries = []
    for package in packages:
        summary = package.summary
        entries.append({
            "name": package.name, "ok": package.ok, "built": package.built,
            "limit": package.limit, "seconds": round(package.seconds, 2),
            "counts": summary.counts if summary else None,
            "problem": summary.problem if summary else "build failed",
            "tests": [{"name": c.name, "outcome": c.outcome, "seconds": c.seconds,
                       "message": c.message, "details": c.details}
                      for c in (summary.cases if summary else ())],
            "output": package.output if not package.ok else ""})
    return document("test", {"ok": bool(packages) and all(p.ok for p in packages),
                             "isolation": isolation, "packages": entries})


def _junit(packages: Sequence[PackageTests], isolation: str) -> str:
    del isolation  # JUnit has no place for it
    suites = []
    for package in packages:
        cases = tuple(Case(package.name, c.name, _ELEMENTS[c.outcome], c.message, c.details,
                           seconds=c.seconds)
                      for c in (package.summary.cases if package.summary else ()))
        if not cases:
            why = package.summary.describe() if package.summary else "build failed"
            cases = (Case(package.name, "build and test", "error", why, package.output[-4000:]),)
        suites.append(Suite(package.name, cases, package.seconds))
    return write("pkgtool test", suites)
