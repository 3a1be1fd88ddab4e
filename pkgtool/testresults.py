"""Read pytest's JUnit XML into per-test results, treating the file as untrusted input."""

from __future__ import annotations

from collections import Counter
from pathlib import Path

from pkgtool.records import record
from pkgtool.safe_xml import parser

MAX_XML_BYTES = 16 * 1024 * 1024
OUTCOMES = ("passed", "failed", "error", "skipped")
_COLCON_PLACEHOLDER = ".pytest.missing_result"
"""The test case colcon writes in place of the report of a pytest that did not write one."""


@record
class TestCase:
    """One test: ``name`` is ``classname.name`` as pytest reports it; ``outcome`` in OUTCOMES."""

    name: str
    outcome: str
    seconds: float
    message: str = ""
    details: str = ""


@record
class TestSummary:
    """The tests of one run, or ``problem`` saying why there are none to read."""

    cases: tuple[TestCase, ...] = ()
    problem: str | None = None

    @property
    def counts(self) -> dict[str, int]:
        """How many tests had each outcome (every outcome present, zero included)."""
        found = Counter(c.outcome for c in self.cases)
        return {outcome: found[outcome] for outcome in OUTCOMES}

    @property
    def ran(self) -> int:
        """Tests that ran (skipped ones do not count)."""
        return sum(1 for c in self.cases if c.outcome != "skipped")

    @property
    def passed(self) -> int:
        """Tests that passed."""
        return self.counts["passed"]

    @property
    def ok(self) -> bool:
        """True when tests ran and every one of them passed: no tests is not a pass."""
        return self.ran > 0 and self.passed == self.ran

    def describe(self) -> str:
        """``3 passed, 1 failed`` style summary, or the problem."""
        if self.problem:
            return self.problem
        if not self.ran:
            return "no tests ran"
        return ", ".join(f"{n} {outcome}{'s' if outcome == 'error' and n > 1 else ''}"
                         for outcome, n in self.counts.items() if n)


def parse_junit(path: Path, *, within: Path | None = None) -> TestSummary:
    """The test cases of a pytest JUnit XML file; a missing or bad file is a ``problem``.

    When the file was written by untrusted code, ``within`` names the folder it must stay
    in: it is opened component by component without following links, as a regular file
    only (a FIFO or device there cannot block or feed the reader), at most MAX_XML_BYTES.
    """
    from pkgtool.safe_fs import UnsafeFile, read_regular

    try:
        if within is None:
            size = path.stat().st_size
            if size > MAX_XML_BYTES:
                return TestSummary(problem=f"the test report is {size} bytes, too large to read")
            data = path.read_bytes()
        else:
            data = read_regular(path, within=within, max_bytes=MAX_XML_BYTES)
    except FileNotFoundError:
        return TestSummary(problem="no tests ran (pytest wrote no report)")
    except UnsafeFile as error:
        return TestSummary(problem=f"the test report is not a plain file of the workspace "
                                   f"({error}); not read")
    except OSError as error:
        return TestSummary(problem=f"the test report cannot be read: {error}")
    return parse_junit_bytes(data)


def parse_junit_bytes(data: bytes) -> TestSummary:
    """The test cases of a JUnit XML document (bytes); a bad document is a ``problem``."""
    from lxml import etree

    try:
        root = etree.fromstring(data, parser())
    except etree.XMLSyntaxError as error:
        return TestSummary(problem=f"the test report cannot be read: {error}")
    cases = tuple(_case(element) for element in root.iter("testcase"))
    if any(c.name.endswith(_COLCON_PLACEHOLDER) for c in cases):
        return TestSummary(problem="pytest ended without a report (it crashed or was stopped)")
    return TestSummary(cases)


def _case(element) -> TestCase:  # type: ignore[no-untyped-def]
    classname, name = element.get("classname") or "", element.get("name") or "?"
    full = f"{classname}.{name}" if classname else name
    try:
        seconds = float(element.get("time") or 0.0)
    except ValueError:
        seconds = 0.0
    for tag, outcome in (("failure", "failed"), ("error", "error"), ("skipped", "skipped")):
        found = element.find(tag)
        if found is not None:
            text = (found.text or "").strip()
            message = found.get("message") or (text.splitlines() or [""])[-1]
            if message == "collection failure":  # pytest's words; the reason is in the text
                raised = [line[1:].strip() for line in text.splitlines() if line[:2] == "E "]
                message += f": {raised[-1]}" if raised else ""
            return TestCase(full, outcome, seconds, message[:500], text[-4000:])
    return TestCase(full, "passed", seconds)


@record
class PackageTests:
    """One package's build and test outcome; ``summary`` is None when the build failed."""

    name: str
    built: bool
    summary: TestSummary | None
    output: str = ""
    limit: str | None = None
    seconds: float = 0.0

    @property
    def ok(self) -> bool:
        """True when it built, tests ran, and all of them passed."""
        return self.built and self.summary is not None and self.summary.ok
