"""``pkgtool reference``: the course documents' packages, listed, generated, linted, built, tested.

The packages live in ``reference_packages/`` (see :mod:`pkgtool.resources`), listed in its
``catalog.toml``. Nothing here prints: results are frozen, progress goes to a callback.
"""

from __future__ import annotations

import re
import shutil
import tempfile
import time
from collections.abc import Callable, Sequence
from concurrent.futures import ThreadPoolExecutor, wait
from pathlib import Path
from typing import TYPE_CHECKING

from pkgtool.commands import ExitCode
from pkgtool.records import record
from pkgtool.lazy_regex import lazy_pattern

if TYPE_CHECKING:
    from pkgtool.testresults import TestSummary

__all__ = ["Entry", "GenerateResult", "ListResult", "PackageReport", "RequestError",
           "TestRunResult", "catalog", "generate", "list_packages", "run_tests"]

SUPPORT_FOLDER = "_support"
"""Folder of ``reference_packages/`` holding packages that others need built (nav2_msgs)."""
_SKIPPED = {"__pycache__", ".pytest_cache", "build", "install", "log"}
_JOB_EVENT = lazy_pattern(r"^\[(\d+(?:\.\d+)?)\] \((\S+)\) Job(Started|Ended):", re.MULTILINE)

Progress = Callable[[str, str], None]
"""Called with (package, stage): linted, lint failed, building, built, build failed, testing..."""


class RequestError(Exception):
    """A request that cannot be done; the message is a full sentence for the user."""


@record
class Entry:
    """One catalogued package: its seed document, console scripts and support packages."""

    name: str
    document: str
    nodes: tuple[str, ...]
    support: tuple[str, ...] = ()


@record
class ListResult:
    """The catalogue, in catalogue order."""

    exit_code: ExitCode
    entries: tuple[Entry, ...] = ()
    errors: tuple[str, ...] = ()


@record
class GenerateResult:
    """Folders written, support folders kept because they existed, or the errors."""

    exit_code: ExitCode
    written: tuple[Path, ...] = ()
    kept: tuple[Path, ...] = ()
    errors: tuple[str, ...] = ()


@record
class PackageReport:
    """One package's lint findings (rendered), build outcome, tests and time spent."""

    name: str
    findings: tuple[str, ...]
    built: bool = False
    summary: TestSummary | None = None
    seconds: float = 0.0
    output: str = ""

    @property
    def ok(self) -> bool:
        """True when lint reported nothing, it built, and its tests ran and passed."""
        return not self.findings and self.built and bool(self.summary and self.summary.ok)


@record
class TestRunResult:
    """Every package's report, and the kept workspace (None when it was removed)."""

    exit_code: ExitCode
    packages: tuple[PackageReport, ...] = ()
    workspace: Path | None = None
    errors: tuple[str, ...] = ()


def _root() -> Path:
    from pkgtool.resources import resource_dir
    return resource_dir("reference_packages")


def catalog(root: Path | None = None) -> tuple[Entry, ...]:
    """The entries of ``catalog.toml`` (default: the shipped one); RequestError if unreadable."""
    from pkgtool.compat import tomllib

    path = (root or _root()) / "catalog.toml"
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
        return tuple(Entry(str(t["name"]), str(t["document"]), tuple(map(str, t["nodes"])),
                           tuple(map(str, t.get("support", ())))) for t in data["package"])
    except (OSError, ValueError, KeyError, TypeError) as error:
        raise RequestError(f"The reference catalogue `{path}` cannot be read ({error}). "
                           "Reinstall pkgtool.") from None


def _select(names: Sequence[str], all_: bool) -> tuple[Entry, ...]:
    entries = catalog()
    if all_:
        return entries
    if not names:
        raise RequestError("Name the reference packages, or pass --all. "
                           "Run `pkgtool reference list` to see them.")
    known = {e.name: e for e in entries}
    unknown = [n for n in names if n not in known]
    if unknown:
        raise RequestError(f"Unknown reference package `{'`, `'.join(unknown)}`. "
                           "Run `pkgtool reference list` to see them.")
    return tuple(known[n] for n in dict.fromkeys(names))


def _files(folder: Path) -> dict[str, str]:
    """Every file under ``folder`` as relative POSIX path -> text (caches skipped)."""
    files = {}
    for path in sorted(folder.rglob("*")):
        relative = path.relative_to(folder)
        if path.is_file() and not _SKIPPED & set(relative.parts) and path.suffix != ".pyc":
            files[relative.as_posix()] = path.read_text(encoding="utf-8")
    return files


def list_packages() -> ListResult:
    """The catalogue of reference packages."""
    try:
        return ListResult(ExitCode.OK, catalog())
    except RequestError as error:
        return ListResult(ExitCode.INTERNAL, errors=(str(error),))


def generate(names: Sequence[str], *, all_: bool = False, dest: Path) -> GenerateResult:
    """Copy the packages (and the support packages they need) into ``dest``.

    An existing package folder is never touched: if any is in the way, nothing is written. A
    support package already in ``dest`` is kept as it is.
    """
    from pkgtool.create import CreateError
    from pkgtool.create.writer import write_package

    try:
        entries = _select(names, all_)
        root = _root()
    except RequestError as error:
        return GenerateResult(ExitCode.USAGE, errors=(str(error),))
    in_the_way = [dest / e.name for e in entries if (dest / e.name).exists()]
    if in_the_way:
        return GenerateResult(ExitCode.USAGE, errors=tuple(
            f"`{p}` already exists; pkgtool never overwrites it. Remove it or choose another "
            "--dest." for p in in_the_way))
    support = dict.fromkeys(s for e in entries for s in e.support)
    sources = [(dest / e.name, root / e.name) for e in entries]
    sources += [(dest / s, root / SUPPORT_FOLDER / s) for s in support]
    written: list[Path] = []
    kept = []
    try:
        for target, source in sources:
            if target.exists():
                kept.append(target)
                continue
            write_package(target, _files(source))
            written.append(target)
    except KeyboardInterrupt:  # Ctrl-C: take back the packages written so far
        _remove(written)
        raise
    except (CreateError, OSError, UnicodeDecodeError) as error:
        return GenerateResult(ExitCode.INTERNAL, tuple(written), tuple(kept), (
            f"Cannot generate into `{dest}`: {error}. Check the folder and retry.",))
    return GenerateResult(ExitCode.OK, tuple(written), tuple(kept))


def _lint(package: Path) -> tuple[str, ...]:
    """``pkgtool lint --strict`` of one package, ignoring configuration files: every finding."""
    from pkgtool.commands.lint import LintOptions, run as lint

    result = lint([str(package)], options=LintOptions(strict=True, isolated=True), cwd=package)
    return tuple(f"{f.span.path}:{f.span.line}:{f.span.col}: {f.code} {f.message}"
                 for f in result.findings) + result.errors


def _job_seconds(events_log: Path) -> dict[str, float]:
    """Seconds each package's colcon job took, from colcon's ``events.log``."""
    started: dict[str, float] = {}
    took: dict[str, float] = {}
    for stamp, name, kind in _JOB_EVENT.findall(_read(events_log) or ""):
        if kind == "Started":
            started[name] = float(stamp)
        elif name in started:
            took[name] = float(stamp) - started[name]
    return took


def _watched(work: Callable[[], object], rc_files: dict[str, Path], progress: Progress,
             done: Callable[[str, str], str]) -> object:
    """Run ``work`` in a thread, reporting each package as its colcon result file appears."""
    pending = dict(rc_files)
    with ThreadPoolExecutor(1) as pool:
        future = pool.submit(work)
        while True:
            finished = bool(wait([future], timeout=0.3).done)
            for name, path in list(pending.items()):
                if path.is_file():
                    progress(name, done(name, _read(path) or ""))
                    del pending[name]
            if finished:
                return future.result()


def run_tests(names: Sequence[str], *, all_: bool = False, jobs: int | None = None,
              keep: Path | None = None, progress: Progress | None = None) -> TestRunResult:
    """Generate into a fresh workspace, lint each package, colcon build and test them all."""
    report = progress or (lambda name, stage: None)
    try:
        entries = _select(names, all_)
    except RequestError as error:
        return TestRunResult(ExitCode.USAGE, errors=(str(error),))
    if keep is not None and keep.exists() and any(keep.iterdir()):
        return TestRunResult(ExitCode.USAGE, errors=(
            f"`{keep}` is not empty; --keep needs a new or empty folder.",))
    workspace = keep or Path(tempfile.mkdtemp(prefix="pkgtool-reference-"))
    fresh = keep is not None and not keep.exists()
    try:
        generated = generate([e.name for e in entries], dest=workspace / "src")
        if generated.exit_code is not ExitCode.OK:
            return TestRunResult(generated.exit_code, errors=generated.errors)
        findings, spent = {}, {}
        for entry in entries:
            start = time.monotonic()
            findings[entry.name] = _lint(workspace / "src" / entry.name)
            spent[entry.name] = time.monotonic() - start
            report(entry.name, "lint failed" if findings[entry.name] else "linted")
        reports = _build_and_test(workspace, findings, spent, jobs, report)
    except KeyboardInterrupt:  # Ctrl-C: a kept folder goes back to how it was (new or empty)
        if keep is not None:
            _remove([keep] if fresh else list(keep.iterdir()))
        raise
    finally:
        if keep is None:
            shutil.rmtree(workspace, ignore_errors=True)
    code = ExitCode.OK if all(r.ok for r in reports) else ExitCode.FINDINGS
    return TestRunResult(code, reports, keep)


def _build_and_test(workspace: Path, findings: dict[str, tuple[str, ...]],
                    spent: dict[str, float], jobs: int | None,
                    report: Progress) -> tuple[PackageReport, ...]:
    """Build every package in one colcon run, then test those that built."""
    import yaml

    from pkgtool.ros.domains import leased_domain

    workers = {"parallel-workers": jobs} if jobs else {}
    defaults = {"build": {"continue-on-error": True, **workers}, "test": workers}
    (workspace / "colcon_defaults.yaml").write_text(yaml.safe_dump(defaults, sort_keys=False))
    names = list(findings)
    with leased_domain() as domain_id:
        built, summaries = _colcon_build_test(workspace, names, domain_id, report)
    seconds = _job_seconds(workspace / "log" / "latest_build" / "events.log")
    tested = _job_seconds(workspace / "log" / "latest_test" / "events.log")
    logs = workspace / "log" / "latest_build"
    skipped = "colcon did not build it: a dependency failed, or the build timed out"
    return tuple(PackageReport(n, findings[n], n in built, summaries.get(n),
                               spent[n] + seconds.get(n, 0.0) + tested.get(n, 0.0),
                               "" if n in built else _tail(logs / n / "stdout_stderr.log")
                               or skipped) for n in names)


def _colcon_build_test(workspace: Path, names: list[str], domain_id: int,
                       report: Progress) -> tuple[list[str], dict[str, TestSummary]]:
    """Build ``names`` in one colcon run and test those that built; (built, summaries)."""
    from pkgtool.testresults import parse_junit
    from pkgtool.ros.colcon import colcon_build, colcon_env, colcon_test

    temp = workspace / "tmp"  # the packages' tests' temporary files go away with the workspace
    temp.mkdir(exist_ok=True)
    env = colcon_env(workspace, domain_id=domain_id, extra={"TMPDIR": str(temp)})
    src, build_dir = [workspace / "src"], workspace / "build"
    for name in names:
        report(name, "building")
    _watched(lambda: colcon_build(workspace, base_paths=src, env=env, packages=names,
                                  timeout=1800),
             {n: build_dir / n / "colcon_build.rc" for n in names}, report,
             lambda name, rc: "built" if rc == "0" else "build failed")
    built = [n for n in names if _read(build_dir / n / "colcon_build.rc") == "0"]
    for name in built:
        report(name, "testing")
    if not built:
        return built, {}
    _watched(lambda: colcon_test(workspace, base_paths=src, env=env, packages=built,
                                 timeout=1800),
             {n: build_dir / n / "colcon_test.rc" for n in built}, report,
             lambda name, rc: "passed" if parse_junit(build_dir / name / "pytest.xml").ok
             else "failed")
    return built, {n: parse_junit(build_dir / n / "pytest.xml") for n in built}


def _remove(paths: Sequence[Path]) -> None:
    for path in paths:
        if path.is_dir() and not path.is_symlink():
            shutil.rmtree(path, ignore_errors=True)
        else:
            path.unlink(missing_ok=True)


def _read(path: Path) -> str | None:
    return path.read_text(errors="replace").strip() if path.is_file() else None


def _tail(path: Path, lines: int = 40) -> str:
    """The last ``lines`` lines of a colcon log file ("" when there is none)."""
    return "\n".join((_read(path) or "").splitlines()[-lines:])
