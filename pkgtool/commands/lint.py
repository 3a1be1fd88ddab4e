"""``pkgtool lint``: find packages, read each once, run the configured rules, decide the exit code.

Nothing here prints: :func:`run` returns a frozen :class:`LintResult` that the CLI renders.
"""

from __future__ import annotations

import gc
import importlib
import os
from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, Optional, Union

from pkgtool.commands import ExitCode
from pkgtool.commands.warm_worker import WarmWorker, chosen_jobs, cores, threads_running
from pkgtool.config import ConfigError, ConfigFinder, Layer, Settings, check_rosdistro
from pkgtool.findings import Finding, Severity
from pkgtool.model.context import WorkspacePackage, context_for, workspace_index
from pkgtool.records import record, replace
from pkgtool.report import PackageLabel
from pkgtool.workspace import discover, witnessed

if TYPE_CHECKING:
    from pkgtool.cache.replay import Witness
    from pkgtool.cache.store import Entry, LintCache, Lookup
    from pkgtool.model.files import Scan
    from pkgtool.model.package import Package

__all__ = ["LintOptions", "LintResult", "TextResult", "explain", "list_rules", "run"]

PACKAGES_PER_WORKER = 16
"""Below this many packages per extra process, a process pool costs more than it saves."""
YOUNG_OBJECTS = 50_000
"""While packages are checked, the youngest generation is collected after this many more
objects (Python's default: 700). A package's syntax trees and indexes are tens of thousands of
objects that reference counting frees when it is done: collections during it only walked
them (a tenth of a cold run). Reference cycles wait at most this many allocations."""


@record
class LintOptions:
    """Command-line choices; None means "not given" (the configuration files decide)."""

    select: tuple[str, ...] | None = None
    ignore: tuple[str, ...] = ()
    extend_select: tuple[str, ...] = ()
    strict: bool | None = None
    exit_zero: bool = False
    hide_info: bool = False
    isolated: bool = False
    rosdistro: str | None = None
    fix: bool = False
    diff: bool = False
    unsafe_fixes: bool = False
    cache: bool = False
    """Reuse and record findings in the lint cache (``cache_dir``, else ``$PKGTOOL_CACHE_DIR``,
    else ``.pkgtool_cache`` in the project root)."""
    cache_dir: str | None = None


@record
class LintResult:
    """Findings package by package, the packages checked, and what went wrong besides.

    ``errors`` are full sentences for stderr (usage or internal errors); ``notes`` are
    warnings about the run itself (a folder holding no package).
    """

    exit_code: ExitCode
    findings: tuple[Finding, ...] = ()
    packages: tuple[PackageLabel, ...] = ()
    errors: tuple[str, ...] = ()
    notes: tuple[str, ...] = ()
    fixed: tuple[str, ...] = ()
    diff: str = ""
    """``--fix``: the titles of the fixes applied; ``--diff``: what they would change."""


def run(paths: Sequence[str], *, options: LintOptions, cwd: Path | None = None,
        witness: Witness | None = None, worker: WarmWorker | None = None) -> LintResult:
    """Lint the packages found at ``paths`` (relative to ``cwd``; none means ``cwd``).

    ``witness`` is told what the run reads, for :mod:`pkgtool.cache.replay`; ``worker``
    (:mod:`pkgtool.commands.warm_worker`) checks the packages the cache has no entry for, when
    they are too few for a pool.
    """
    if witness is None:
        return _run(paths, options, cwd, None, worker)
    with witnessed(witness, witness.known):
        return _run(paths, options, cwd, witness, worker)


def _run(paths: Sequence[str], options: LintOptions, cwd: Path | None,
         witness: Witness | None, worker: WarmWorker | None) -> LintResult:
    here = Path(os.path.abspath(cwd or Path.cwd()))
    hint = witness.hint() if witness is not None else None
    found = hint.found if hint is not None else discover(paths, cwd=here)
    if found.missing:
        return LintResult(ExitCode.USAGE, errors=tuple(
            f"Path `{p}` does not exist. Check the spelling, or run from another folder."
            for p in found.missing))
    try:
        rosdistro = options.rosdistro and check_rosdistro(options.rosdistro, "`--rosdistro`")
    except ConfigError as error:
        return LintResult(ExitCode.USAGE, errors=(str(error),))
    command_line = Layer("the command line", None, options.select, options.ignore,
                         options.extend_select, options.strict, rosdistro=rosdistro or None)
    finder = ConfigFinder(command_line, isolated=options.isolated)
    notes = tuple(f"No package (a folder with package.xml or setup.py) found under `{p}`."
                  for p in found.empty)
    try:
        settings = [finder.settings(root) for root in found.packages]
        if not found.packages:
            finder.settings(here)  # still validate the command line and the config in reach
    except ConfigError as error:
        return LintResult(ExitCode.USAGE, errors=(str(error),), notes=notes)
    if witness is not None:
        witness.paths(finder.consulted())
        tops = [os.path.abspath(here / p) for p in paths or ["."]]
        witness.replayable = all(any(_within(str(root), top) for top in tops)
                                 for root in found.packages)  # else a package above is read
    cache = _open_cache(options, here)
    scans = {} if cache is None or options.fix else \
        hint.scans if hint is not None else _scans(found.packages)
    reused = hint.reused if hint is not None and cache is not None else {}
    if witness is not None:
        witness.found(found, scans)
    workspace = workspace_index(
        found.packages, [here / p for p in paths or ["."] if (here / p).is_dir()],
        {root: [path for path, _ in listed] for root, listed in scans.items()},
        {**cache.indexed({root: scans[root] for root in scans if root not in reused}),
         **{root: hint.index[root] for root in reused}} if cache is not None else None)
    if hint is not None and reused and any(workspace[root] != hint.index.get(root)
                                           for root in found.packages if root not in reused):
        reused = {}  # what the others see of a changed package changed: look each one up
    if cache is not None:
        cache.bind(workspace)
    jobs = [(root, _label(root, here), setting) for root, setting in zip(found.packages, settings)]
    findings: list[Finding] = []
    labels: list[PackageLabel] = []
    errors: list[str] = []
    fixed, diff, refused = _fix_all(jobs, workspace, options, errors) \
        if options.fix or options.diff else ((), "", ())
    notes += refused
    failing = False
    outcomes = _check_all(jobs, workspace) if cache is None else \
        _cached(jobs, workspace, cache, scans, reused, worker)
    checked: dict[str, tuple[str, list[Finding]]] = {}
    for (root, label, setting), (outcome, entry) in zip(jobs, outcomes):
        if entry is not None and cache is not None:
            cache.keep(entry)
        if isinstance(outcome, str):
            errors.append(outcome)
            labels.append(PackageLabel(root.name, label))
            continue
        checked[str(root)] = outcome
        name, mine = outcome
        labels.append(PackageLabel(name, label))
        if options.hide_info:
            mine = [f for f in mine if f.severity is not Severity.INFO]
        failing = failing or any(_fails(f, setting.strict) for f in mine)
        findings.extend(mine)
    if cache is not None:
        cache.save()
    if witness is not None:
        witness.checked(None if errors else checked, workspace)
    internal = bool(errors) or any(f.internal for f in findings)
    code = (ExitCode.INTERNAL if internal else
            ExitCode.FINDINGS if failing and not options.exit_zero else ExitCode.OK)
    if options.diff:
        code = ExitCode.FINDINGS if diff and not options.exit_zero else ExitCode.OK
    return LintResult(code, tuple(findings), tuple(labels), tuple(errors), notes, fixed, diff)


def warm_up() -> list[Callable[[], None]]:
    """What checking any package imports, in steps: the model and the engine, the rules
    enabled by default, lxml (a :mod:`warm worker <pkgtool.commands.warm_worker>` takes them
    while the run reads the cache). PyYAML is not among them: a package without YAML files
    does not need it, and a step begun when the call comes delays it."""
    return [partial(importlib.import_module, name) for name in
            ("pkgtool.engine", "pkgtool.model.package")] + \
        [_default_rules, partial(importlib.import_module, "lxml.etree")]


def _default_rules() -> None:
    from pkgtool.rules.registry import index, load

    load(code for code, rule in index().items() if rule.default_enabled)


def _fix_all(jobs: list[Job], workspace: Workspace, options: LintOptions, errors: list[str]
             ) -> tuple[tuple[str, ...], str, tuple[str, ...]]:
    """Apply (or, with ``--diff``, show) the fixes of every package: (titles applied, diff,
    notes on findings left to the user); edits the engine refuses go to errors."""
    from pkgtool.fix.apply import fix_package

    fixed: list[str] = []
    diffs: list[str] = []
    refused: list[str] = []
    for root, label, settings in jobs:
        check = partial(_model_and_findings, root, label=label, settings=settings,
                        workspace=workspace, offers=False)
        outcome = fix_package(root, label, lambda folder, check=check: check(read_from=folder),
                              unsafe=options.unsafe_fixes, write=not options.diff)
        fixed.extend(f"{label}: {title}" for title in outcome.applied)
        refused.extend(f"{label}: not fixed: {why}" for why in outcome.refused)
        diffs.append(outcome.diff)
        if outcome.error:
            errors.append(outcome.error)
    return tuple(fixed), "".join(diffs), tuple(refused)


def _model_and_findings(root: Path, *, label: str, settings: Settings, workspace: Workspace,
                        offers: bool = True, split: bool = False, read_from: Path | None = None
                        ) -> tuple[Package, list[Finding]]:
    """Read and check one package (exceptions propagate: ``_check`` reports them); with
    ``offers``, the findings ``--fix`` cannot repair are marked so (``--fix`` itself asks the
    fixers anyway); with ``split`` (the run's only package), on two cores when it can; with
    ``read_from``, the files of that copy of the package (``--diff``'s rounds), in the
    workspace of ``root``."""
    from pkgtool.engine import check_package
    from pkgtool.model.package import load_package
    from pkgtool.model.python_visitor import forget_trees

    context = context_for(root, workspace, settings.rosdistro, settings.python)
    package = load_package(read_from, context, surroundings=root) if read_from else \
        load_package(root, context)
    try:
        found = _split_check(package, label, settings) if split else None
        if found is None:
            found = check_package(package, settings.rules, root_label=label,
                                  severities=settings.severities)
        if offers:
            from pkgtool.fix.offers import offers_marked

            found = offers_marked(package, found)
    finally:
        forget_trees()
    if settings.path_ignores:
        found = [f for f in found
                 if f.internal or not settings.ignores(root / f.span.path, f.code)]
    return package, found


def _split_check(package: Package, label: str, settings: Settings) -> list[Finding] | None:
    """The package's findings from :mod:`pkgtool.commands.two_cores`, or None."""
    from pkgtool.commands.two_cores import check_on_two_cores

    return check_on_two_cores(package, settings.codes, root_label=label,
                              severities=settings.severities)


Job = tuple[Path, str, Settings]
Workspace = Mapping[Path, WorkspacePackage]
"""Every package of the run's workspaces by folder (:func:`workspace_index`)."""
Outcome = Union[tuple[str, list[Finding]], str]
Checked = tuple[Outcome, Optional["Entry"]]
"""A package's outcome, and the cache entry to record for it (when there is a new one)."""


def _check_all(jobs: list[Job], workspace: Workspace, cache: LintCache | None = None,
               worker: WarmWorker | None = None) -> Iterator[Checked]:
    """Each job's outcome in order; a process per core once there are enough packages, else
    the warm ``worker`` when there is one."""
    with _few_collections():
        yield from _check_each(jobs, workspace, cache, worker)


@contextmanager
def _few_collections() -> Iterator[None]:
    """Collect the youngest generation after :data:`YOUNG_OBJECTS` allocations meanwhile (the
    worker processes forked inherit it)."""
    threshold = gc.get_threshold()
    gc.set_threshold(YOUNG_OBJECTS, *threshold[1:])
    try:
        yield
    finally:
        gc.set_threshold(*threshold)


def _check_each(jobs: list[Job], workspace: Workspace, cache: LintCache | None,
                worker: WarmWorker | None) -> Iterator[Checked]:
    check = partial(_check, workspace=workspace, cache=cache)
    workers = _workers(len(jobs))
    if worker is not None and cache is not None and jobs and workers < 2:
        yield from _check_in(worker, jobs, workspace, cache)
        return
    if worker is not None:
        worker.close()
    if workers < 2 or threads_running():
        yield from map(partial(check, split=len(jobs) == 1), jobs)
        return
    import multiprocessing  # only here: importing it costs a small lint run ~10 ms

    if "fork" not in multiprocessing.get_all_start_methods():
        yield from map(check, jobs)
        return
    from concurrent.futures import ProcessPoolExecutor

    yield check(jobs[0])  # loads every table and pattern the rules use, before the workers fork
    gc.freeze()  # what the workers inherit is never walked by their collections (no copy-on-write)
    try:
        context = multiprocessing.get_context("fork")  # workers inherit the loaded rules
        with ProcessPoolExecutor(workers, mp_context=context) as pool:
            yield from pool.map(check, jobs[1:], chunksize=max(1, len(jobs) // (workers * 8)))
    finally:
        gc.unfreeze()


def _open_cache(options: LintOptions, cwd: Path) -> LintCache | None:
    """The cache this run uses, if any."""
    if not options.cache:
        return None
    from pkgtool.cache import cache_folder
    from pkgtool.cache.store import LintCache

    return LintCache(cache_folder(options.cache_dir, cwd))


def _scans(roots: Sequence[Path]) -> dict[Path, Scan]:
    """Every file of each package with its size and time: read once, for the workspace index
    and the cache's probes."""
    from pkgtool.model.files import scan

    return {root: scan(root) for root in roots}


def _cached(jobs: list[Job], workspace: Workspace, cache: LintCache,
            scans: Mapping[Path, Scan], reused: Mapping[Path, Outcome],
            worker: WarmWorker | None) -> Iterator[Checked]:
    """Each job's outcome in order: ``reused`` ones (the last run's, see
    :class:`pkgtool.cache.replay.Hint`) as they are; entries whose files kept their sizes and
    times (in ``scans`` when given) from the cache here; the others are looked up (reading
    files) and checked by :func:`_check`, in the worker processes when there are enough of
    them."""
    probes = [None if root in reused else
              cache.lookup(root, setting, read=False, scanned=scans.get(root))
              for root, _, setting in jobs]
    fresh = _check_all([job for job, probe in zip(jobs, probes) if job[0] not in reused and
                        (probe is None or probe.hit is None)], workspace, cache, worker)
    for (root, label, _), probe in zip(jobs, probes):
        if root in reused:
            yield reused[root], None
        else:
            yield (_relabelled(probe, label), None) if probe is not None and probe.hit \
                else next(fresh)


def _relabelled(found: Lookup, label: str) -> Outcome:
    assert found.hit is not None
    name, stored = found.hit
    return name, [replace(f, root=label) for f in stored]


def _workers(packages: int) -> int:
    """``$PKGTOOL_LINT_JOBS`` when set (1: no pool), else one per core once worth it."""
    chosen = chosen_jobs()
    if chosen > 0:
        return min(chosen, packages)
    return min(cores(), packages // PACKAGES_PER_WORKER)


def _check_in(worker: WarmWorker, jobs: list[Job], workspace: Workspace, cache: LintCache
              ) -> Iterator[Checked]:
    """Each job's outcome in order: looked up in ``cache`` here, the packages it has no entry
    for checked by ``worker`` (here, when it could not)."""
    found = [cache.lookup(root, settings) for root, _, settings in jobs]
    stale = [job for job, lookup in zip(jobs, found) if lookup is None or lookup.hit is None]
    lint = partial(_lint_one, workspace=workspace, split=len(stale) == 1)
    outcomes = iter((worker.map(lint, stale) or list(map(lint, stale))) if stale else ())
    for job, lookup in zip(jobs, found):
        fresh = lookup is None or lookup.hit is None
        yield _settled(job, lookup, cache, next(outcomes) if fresh else None)


def _check(job: Job, workspace: Workspace, cache: LintCache | None, split: bool = False
           ) -> Checked:
    """One package's outcome: from ``cache`` when valid, else checked (``split``: see
    :func:`_model_and_findings`); and the entry to record."""
    if cache is None:
        return _lint_one(job, workspace, split), None
    found = cache.lookup(job[0], job[2])
    fresh = found is None or found.hit is None
    return _settled(job, found, cache, _lint_one(job, workspace, split) if fresh else None)


def _settled(job: Job, found: Lookup | None, cache: LintCache, outcome: Outcome | None) -> Checked:
    """The outcome of a package looked up in ``cache``: the entry's when valid (``outcome``
    None), else ``outcome``, its check; and the entry to record."""
    root, label, _ = job
    assert found is not None  # read=True: never only a probe
    if found.hit is not None:  # when some file was read again, record its times: trusted next
        return _relabelled(found, label), cache.entry(root, found, *found.hit) \
            if found.refresh else None
    assert outcome is not None
    if isinstance(outcome, str) or any(f.internal for f in outcome[1]):
        return outcome, None
    return outcome, cache.entry(root, found, outcome[0],
                                [replace(f, root="") for f in outcome[1]])


def _lint_one(job: Job, workspace: Workspace, split: bool = False) -> Outcome:
    """Read one package and check it (``split``: see :func:`_model_and_findings`); an
    exception becomes an internal-error message."""
    root, label, settings = job
    try:
        package, found = _model_and_findings(root, label=label, settings=settings,
                                             workspace=workspace, split=split)
    except Exception as error:  # noqa: BLE001 - report it, keep linting the others
        return (f"Internal error while reading the package at `{label}`: "
                f"{type(error).__name__}: {error}. Please report this pkgtool bug.")
    return package.name, found


def _fails(finding: Finding, strict: bool) -> bool:
    return finding.severity is Severity.ERROR or (strict and finding.severity is Severity.WARNING)


def _label(root: Path, cwd: Path) -> str:
    """``root`` relative to ``cwd`` when inside it (``.`` for cwd itself), else absolute."""
    path, folder = str(root), str(cwd)
    if path == folder:
        return "."
    inside = path[len(folder.rstrip(os.sep)) + 1:] if _within(path, folder) else path
    return inside.replace(os.sep, "/")


def _within(path: str, folder: str) -> bool:
    """True when the normalised absolute ``path`` is ``folder`` or inside it (string tests:
    once per package, where pathlib's ``parents`` and ``relative_to`` cost milliseconds)."""
    return path == folder or path.startswith(folder.rstrip(os.sep) + os.sep)


@record
class TextResult:
    """Text to print (``--explain``, ``--list-rules``) or errors with the exit code."""

    exit_code: ExitCode
    text: str = ""
    errors: tuple[str, ...] = ()


def explain(selector: str) -> TextResult:
    """The documentation of the rules a code, name, family or prefix selects."""
    from pkgtool.docs_gen import explain as explain_rule
    from pkgtool.rules.registry import resolve

    rules = resolve(selector) if selector.strip() else []
    if not rules:
        return TextResult(ExitCode.USAGE, errors=(
            f"Unknown rule `{selector}`. Run `pkgtool lint --list-rules` to see the rules.",))
    return TextResult(ExitCode.OK, "\n".join(explain_rule(rule) for rule in rules))


def list_rules(*, as_json: bool = False) -> TextResult:
    """Every registered rule, as an aligned table or a JSON list."""
    import json

    from pkgtool.docs_gen import rules_table
    from pkgtool.rules.registry import load_all

    rules = load_all()
    if not as_json:
        return TextResult(ExitCode.OK, rules_table(rules))
    rows = [{"code": r.code, "name": r.name, "severity": r.severity.value, "family": r.family,
             "default_enabled": r.default_enabled, "summary": r.summary, "fix": r.fix}
            for r in rules.values()]
    return TextResult(ExitCode.OK, json.dumps(rows, indent=2) + "\n")
