"""The executables setup.py and setup.cfg install into ``lib/<package>``: a linted package's,
and another workspace package's, read only when a rule asks (a launch file starting its node).
"""

from __future__ import annotations

import functools
import posixpath

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
