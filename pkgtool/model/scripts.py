"""The executables setup.py and setup.cfg install into ``lib/<package>``: a linted package's,
and another workspace package's, read only when a rule asks (a launch file starting its node).
"""

from __future__ import annotations

import functools
import posixpath
import re

from pkgtool.model.context import WorkspacePackage, setup_texts
from pkgtool.model.digest import text_digest
from pkgtool.model.setup_cfg import SetupCfg, parse_setup_cfg
from pkgtool.model.setup_py import DataFile, SetupPy, parse_setup_py
from pkgtool.model.span import ParseProblem


def script_names(setup: SetupPy, setup_cfg: SetupCfg | None) -> frozenset[str] | None:
    """The console scripts of setup.py and setup.cfg and the ``scripts=`` of setup.py, or None
    when they cannot be known: a keyword that was not evaluated (``entry_points``, ``**``,
    ``scripts``) or a malformed console script (setuptools then refuses the whole list, ENT001:
    nothing is installed)."""
    if "scripts" in setup.keywords and setup.scripts is None or \
            any(setup.is_unresolved(k) for k in ("entry_points", "**")) or \
            not all(entry.valid for entry in setup.console_scripts):
        return None
    names = {entry.name for entry in setup.console_scripts}
    names.update(posixpath.basename(script) for script in setup.scripts or ())
    option = setup_cfg.get("options.entry_points", "console_scripts") if setup_cfg else None
    if option is not None:
        names.update(line.split("=", 1)[0].strip() for line in option.value.splitlines()
                     if "=" in line)
    return frozenset(names)


def library_entries(setup: SetupPy, name: str) -> list[DataFile]:
    """The data_files entries that copy into ``lib/<name>`` (beside the console scripts)."""
    library = f"lib/{name}"
    return [entry for entry in setup.data_files or ()
            if posixpath.normpath(entry.destination.strip("/")) == library]


def sibling_executables(package: WorkspacePackage) -> frozenset[str] | None:
    """The executables another package of the workspace certainly installs, and nothing else;
    None when that cannot be known: not an ament_python package (see
    :attr:`~pkgtool.model.context.WorkspacePackage.setup_digest`), setup.py or setup.cfg
    changed since the workspace was indexed or do not parse, :func:`script_names` unknown,
    data_files not evaluated or copying files into ``lib/<package>``."""
    if not package.setup_digest or not package.folder:
        return None
    return _executables(package.folder, package.name, package.setup_digest)


@functools.lru_cache(maxsize=512)
def _executables(folder: str, name: str, digest: str) -> frozenset[str] | None:
    setup_text, cfg_text = setup_texts(folder)
    if setup_text is None or text_digest(setup_text, cfg_text) != digest:
        return None
    # the files are not read: the data_files destinations with globs matching nothing, the
    # console scripts with no glob nor package finder evaluated (else a file added later
    # would change them, and the cache is keyed to setup.py and setup.cfg alone)
    destinations = parse_setup_py("setup.py", setup_text, ())
    scripts = parse_setup_py("setup.py", setup_text, None)
    setup_cfg = parse_setup_cfg("setup.cfg", cfg_text) if cfg_text is not None else None
    if not isinstance(destinations, SetupPy) or not isinstance(scripts, SetupPy) or \
            isinstance(setup_cfg, ParseProblem) or destinations.is_unresolved("data_files") or \
            library_entries(destinations, name):
        return None
    return script_names(scripts, setup_cfg)


_WALKS = re.compile(r"\bdef\s|\blambda\b|os\.walk|listdir|scandir|iterdir|rglob|(?<!glob)\.glob\(")
"""What in a setup.py lists files other than ``glob()`` calls (evaluated against no files,
they would install nothing): its own functions, walks, ``Path.glob``."""
Installs = tuple[tuple[str, str, bool], ...]
"""data_files entries, a source each: (destination folder, source path or glob, is a glob)."""


def sibling_data_files(package: WorkspacePackage) -> Installs | None:
    """What another ament_python package of the workspace installs with data_files, read
    from setup.py alone (globs are kept as patterns: the files they match are not read, so
    the answer depends on nothing but the setup files the index digests); None when that
    cannot be known (see :func:`sibling_executables`, and a data_files not evaluated)."""
    if not package.setup_digest or not package.folder:
        return None
    return _data_files(package.folder, package.setup_digest)


@functools.lru_cache(maxsize=512)
def _data_files(folder: str, digest: str) -> Installs | None:
    setup_text, cfg_text = setup_texts(folder)
    if setup_text is None or text_digest(setup_text, cfg_text) != digest or \
            "data_files" in (cfg_text or "") or _WALKS.search(setup_text):
        return None  # setup.cfg's [options.data_files] add more; a walk or helper lists files
    setup = parse_setup_py("setup.py", setup_text, ())
    if not isinstance(setup, SetupPy) or setup.is_unresolved("data_files") or \
            setup.is_unresolved("**") or any(e.sources_is_text for e in setup.data_files or ()):
        return None
    return tuple((posixpath.normpath(entry.destination.strip("/")), source.pattern,
                  source.is_glob) for entry in setup.data_files or () for source in entry.sources)


def installs_share_path(installs: Installs, target: str) -> bool:
    """True when data_files entries ``installs`` may install ``target`` (``share/pkg/x/y``):
    a source of its name (or a glob its name matches) copied into its folder, or a folder
    at or below it (setuptools makes each destination)."""
    from fnmatch import fnmatchcase

    folder, name = posixpath.split(target)
    return any(destination == target or destination.startswith(target + "/") or
               destination == folder and (
                   fnmatchcase(name, posixpath.basename(pattern)) if is_glob else
                   posixpath.basename(posixpath.normpath(pattern)) == name)
               for destination, pattern, is_glob in installs)
