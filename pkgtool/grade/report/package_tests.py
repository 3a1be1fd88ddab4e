"""Render ``pkgtool test`` results: text, JSON or JUnit XML (pytest's cases, per package)."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from collections.abc import Sequence
from dataclasses import asdict

from pkgtool import __version__
from pkgtool.grade.report import SCHEMA_VERSION
from pkgtool.grade.runner import first_error
from pkgtool.testresults import PackageTests

FORMATS = ("text", "json", "junit")


def render(fmt: str, packages: Sequence[PackageTests], *, isolation: str) -> str:
    """The tested ``packages`` in ``fmt`` (one of FORMATS); ``isolation`` is the sandbox used."""
    return {"text": _text, "json": _json, "junit": _junit}[fmt](packages, isolation)


def _text(packages: Sequence[PackageTests], isolation: str) -> str:
    lines = []
    for package in packages:
        summary = package.summary
        if summary is None:
            limit = f" ({package.limit})" if package.limit else ""
            first = first_error(package.output)
            lines += [f"{package.name}: BUILD FAILED{limit}",
                      *("  " + line for line in package.output.splitlines()[-40:]),
                      *([f"{package.name}: first error: {first}"] if first else [])]
            continue
        for case in summary.cases:
            lines.append(f"  {case.outcome.upper():7} {case.name} ({case.seconds:.2f} s)")
            if case.outcome in ("failed", "error"):
                lines += ["      " + line for line in case.details.splitlines()[-15:]]
        verdict = "ok" if package.ok else "FAILED"
        limit = f"; {package.limit}" if package.limit else ""
        lines.append(f"{package.name}: {verdict}: {summary.describe()}{limit} "
                     f"({package.seconds:.1f} s)")
    lines.append(f"sandbox: {isolation}")
    return "\n".join(lines) + "\n"


def _json(packages: Sequence[PackageTests], isolation: str) -> str:
    entries = []
    for package in packages:
        entry = {"name": package.name, "ok": package.ok, "built": package.built,
                 "limit": package.limit, "seconds": round(package.seconds, 2),
                 "counts": package.summary.counts if package.summary else None,
                 "problem": package.summary.problem if package.summary else "build failed",
                 "tests": [asdict(c) for c in package.summary.cases] if package.summary else [],
                 "output": package.output if not package.ok else ""}
        entries.append(entry)
    document = {"schema_version": SCHEMA_VERSION, "tool": "pkgtool", "version": __version__,
                "ok": bool(packages) and all(p.ok for p in packages), "isolation": isolation,
                "packages": entries}
    return json.dumps(document, indent=2) + "\n"


def _junit(packages: Sequence[PackageTests], isolation: str) -> str:
    del isolation  # JUnit has no place for it
    root = ET.Element("testsuites", name="pkgtool test")
    for package in packages:
        cases = package.summary.cases if package.summary else ()
        counts = package.summary.counts if package.summary else {}
        suite = ET.SubElement(root, "testsuite", name=package.name, tests=str(len(cases) or 1),
                              failures=str(counts.get("failed", 0)),
                              errors=str(counts.get("error", 0) if cases else 1),
                              skipped=str(counts.get("skipped", 0)),
                              time=f"{package.seconds:.2f}")
        if not cases:
            case = ET.SubElement(suite, "testcase", classname=package.name, name="build and test")
            why = package.summary.describe() if package.summary else "build failed"
            ET.SubElement(case, "error", message=why).text = package.output[-4000:]
        for test in cases:
            case = ET.SubElement(suite, "testcase", classname=package.name, name=test.name,
                                 time=f"{test.seconds:.3f}")
            tag = {"failed": "failure", "error": "error", "skipped": "skipped"}.get(test.outcome)
            if tag:
                ET.SubElement(case, tag, message=test.message).text = test.details
    ET.indent(root)
    return ET.tostring(root, encoding="unicode", xml_declaration=True) + "\n"
