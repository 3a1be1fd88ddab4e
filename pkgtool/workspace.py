"""Find the packages to lint from command-line paths: packages, workspaces or files in packages.

A package is a folder holding ``package.xml`` or ``setup.py``. Discovery follows colcon:

- a folder holding an ignore marker (``COLCON_IGNORE``, ``AMENT_IGNORE``, ``CATKIN_IGNORE``) or
  the marker of an old catkin/ament_tools install space (``_setup_util.py``,
  ``_order_isolated_packages.py``) is skipped with everything below it; colcon writes
  ``COLCON_IGNORE`` into its ``build``/``install``/``log`` folders, which is why those are
  skipped: a folder merely named ``build`` is searched, as colcon does;
- hidden folders are skipped (colcon too); so are, beyond colcon, virtual environments (a
  ``pyvenv.cfg``), CMake build trees (a ``CMakeCache.txt``: generated, as a vendored
  library's build holding a copy of its Python bindings), colcon install and build folders
  committed without their ``COLCON_IGNORE`` (colcon's ``local_setup.sh``, ``setup.sh``,
  ``local_setup.bash`` and ``setup.bash`` together, a ``_local_setup_util_sh.py``, a
  ``colcon_build.rc``, an installed ``share/<name>`` beside ``share/ament_index``: ``colcon
  build`` writes the marker before it looks for packages), ``__pycache__``,
  ``node_modules``, ``site-packages`` and ``*.egg-info``;
- packages do not nest: once a folder is a package, its sub-folders are not searched; but a
  Python project without package.xml (a pip project's ``setup.py`` at a repository's root)
  that holds ROS packages (with package.xml) below gives those ROS packages, not itself.

A folder named on the command line is linted (or searched) even when it holds an ignore
marker: the user asked for it. A file, or a folder inside a package with no package below it,
is linted through its owning package, the nearest folder above it that is a package; files in
no package, or in a package that discovery would skip, are ignored (what pre-commit needs).
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from pkgtool.records import record

PACKAGE_MARKERS = ("package.xml", "setup.py")
SKIP_MARKERS = frozenset({"COLCON_IGNORE", "AMENT_IGNORE", "CATKIN_IGNORE"})
"""Files that make colcon (and ament, catkin) skip their folder."""
IGNORE_MARKERS = SKIP_MARKERS | {"_setup_util.py", "_order_isolated_packages.py"}
SKIPPED_NAMES = frozenset({"__pycache__", "node_modules", "site-packages"})
GENERATED_MARKERS = frozenset({"pyvenv.cfg", "CMakeCache.txt", "_local_setup_util_sh.py",
                               "_local_setup_util_ps1.py", "colcon_build.rc"})
VENDORED_NAMES = frozenset({"include"})
"""Folders discovery does not search for packages: a C/C++ header tree never holds a ROS
package's sources, and a package.xml there came with a copied library (mavlink's headers)."""
"""Files marking a folder whose contents are generated (a virtual environment, a CMake build
tree, a colcon install or build folder committed without the COLCON_IGNORE colcon writes
into it): skipped with everything below it, beyond colcon."""
INSTALL_SCRIPTS = frozenset({"local_setup.sh", "setup.sh", "local_setup.bash", "setup.bash"})
"""The scripts colcon writes at an install folder's top: all of them together, in a folder
that is no package, mark one (a hand-written ``local_setup.sh`` alone does not)."""
INSTALLED_SHARE = ("ament_index", "colcon-core")
"""Folders beside an installed package's ``share/<name>`` (a package.xml copied there by
``data_files``): a package folder in a ``share`` folder holding one is an install's copy."""


@record
class Discovery:
    """Package roots to lint (absolute, unique, sorted) and the arguments that gave none.

    ``missing`` are arguments that do not exist; ``empty`` are folders with no package below.
    """

    packages: tuple[Path, ...]
    missing: tuple[str, ...] = ()
    empty: tuple[str, ...] = ()


def is_package(folder: Path) -> bool:
    """True when ``folder`` holds a package.xml or a setup.py."""
    return any((folder / marker).is_file() for marker in PACKAGE_MARKERS)


def discover(paths: Sequence[str], *, cwd: Path) -> Discovery:
    """Resolve command-line ``paths`` (relative to ``cwd``; none means ``cwd``) to packages."""
    found: dict[str, Path] = {}
    missing: list[str] = []
    empty: list[str] = []
    for argument in paths or ["."]:
        path = Path(os.path.abspath(cwd / argument))
        if not os.path.lexists(path):
            missing.append(argument)
            continue
        if path.is_dir() and is_package(path):
            listed, real = listing(path), os.path.realpath(path)
            roots = list(_package_or_inner(path, real, listed, {e.name for e in listed}, {real}))
        elif path.is_dir():
            roots = list(_walk(path)) or _owner(path, cwd)
            if not roots:
                empty.append(argument)
        else:
            roots = _owner(path, cwd)
        for root, real in roots:
            found.setdefault(real or os.path.realpath(root), root)
    packages = tuple(sorted(found.values()))
    return Discovery(packages, tuple(missing), tuple(empty))


def _owner(path: Path, cwd: Path) -> list[tuple[Path, str]]:
    owner = owning_package(path)
    return [(owner, "")] if owner and not _skipped_below(owner, cwd) else []


def owning_package(file: Path) -> Path | None:
    """The nearest folder above ``file`` that is a package, not crossing a git repository root."""
    for folder in file.parents:
        if is_package(folder):
            return folder
        if (folder / ".git").exists():
            return None
    return None


def _skipped_below(root: Path, cwd: Path) -> bool:
    """True when discovery from ``cwd`` would skip ``root`` (only folders below ``cwd`` count)."""
    try:
        relative = root.relative_to(cwd)
    except ValueError:
        return _ignored_here(root)
    folder = cwd
    for part in relative.parts:
        folder = folder / part
        if _skipped_name(part) or _ignored_here(folder) or \
                any((folder / marker).is_file() for marker in GENERATED_MARKERS):
            return True
    return False


def _skipped_name(name: str) -> bool:
    return name.startswith(".") or name in SKIPPED_NAMES or name.endswith(".egg-info")


def _ignored_here(folder: Path) -> bool:
    return any((folder / marker).exists() for marker in IGNORE_MARKERS)


def _walk(top: Path) -> Iterable[tuple[Path, str]]:
    """Packages below ``top``, each with its real path; each folder is listed once and symlink
    cycles are cut.

    Symbolic links are followed only after every real folder, so a package that is also
    linked is reported at its real path. The real path of a folder that is no link is its
    parent's joined with its name (no system call).
    """
    real_top = os.path.realpath(top)
    folders: Found = []
    links: Found = []
    _below(top, real_top, listing(top), folders, links)
    yield from _search(folders, links, {real_top})


def _search(folders: Found, links: Found, seen: set[str]) -> Iterator[tuple[Path, str]]:
    """The packages in and below ``folders`` and ``links`` (see :func:`_walk`)."""
    while folders or links:
        sub, real = folders.pop() if folders else links.pop()
        real = real or os.path.realpath(sub)
        if real in seen:
            continue
        seen.add(real)
        listed = listing(sub)
        names = {e.name for e in listed}
        if not names.isdisjoint(IGNORE_MARKERS) or not names.isdisjoint(GENERATED_MARKERS) or \
                INSTALL_SCRIPTS <= names and names.isdisjoint(PACKAGE_MARKERS):
            continue
        if any(e.name in PACKAGE_MARKERS and _is_file(e) for e in listed):
            if not _installed_copy(sub):
                yield from _package_or_inner(sub, real, listed, names, seen)
        else:
            _below(sub, real, listed, folders, links)


def _installed_copy(folder: Path) -> bool:
    """True for ``<install>/share/<name>`` of a colcon or ament install: beside one of
    :data:`INSTALLED_SHARE`, or in colcon's isolated layout (``<name>/share/<name>``)."""
    return folder.parent.name == "share" and (
        folder.parent.parent.name == folder.name or
        any(os.path.isdir(folder.parent / name) for name in INSTALLED_SHARE))


_TEST_FOLDERS = frozenset({"test", "tests", "testdata", "test_data", "fixtures"})
"""Folders of a Python project whose ROS packages are its test material (rosdoc2's
``test/packages``): they keep the project a package."""


def _package_or_inner(folder: Path, real: str, listed: list[os.DirEntry[str]], names: set[str],
                      seen: set[str]) -> Iterator[tuple[Path, str]]:
    """``folder``, a package; but for a Python project without package.xml (a pip project's
    setup.py at a repository's root) holding ROS packages below (not in its test folders),
    those ROS packages instead:
    pkgtool checks ROS packages, which colcon builds from a workspace linking their folder."""
    if "package.xml" not in names:
        inner: Found = []
        inner_links: Found = []
        _below(folder, real, listed, inner, inner_links)
        ros = [(path, inner_real) for path, inner_real in _search(inner, inner_links, seen)
               if any(e.name == "package.xml" for e in listing(path)) and
               _TEST_FOLDERS.isdisjoint(path.relative_to(folder).parts)]
        if ros:
            yield from ros
            return
    yield folder, real


Found = list[tuple[Path, str]]
"""Folders to search, each with its real path ("" for a link: resolved when searched)."""


def _below(folder: Path, real: str, listed: list[os.DirEntry[str]], folders: Found,
           links: Found) -> None:
    """Add the sub-folders of ``folder`` worth searching to ``folders`` (real ones, with their
    real paths) and ``links``; only then are their paths made (a package's are never)."""
    for entry in listed:
        if not _skipped_name(entry.name) and entry.name not in VENDORED_NAMES and \
                _is_dir(entry):
            if entry.is_symlink():
                links.append((folder / entry.name, ""))
            else:
                folders.append((folder / entry.name, os.path.join(real, entry.name)))


Witness = Callable[[str, "os.stat_result | None", "list[Any]"], None]
"""Told of every folder :func:`listing` lists: its path, its status taken before listing it
(None when it has none) and its entries."""
Known = Mapping[str, "tuple[os.stat_result, list[Any]]"]
"""Folders whose entries are known without listing them: path -> (status, entries that stand
in for :class:`os.DirEntry`)."""
_witness: Witness | None = None
_known: Known = {}


@contextmanager
def witnessed(witness: Witness, known: Known | None = None) -> Iterator[None]:
    """Tell ``witness`` of every folder listed meanwhile, and take the entries of the ``known``
    folders from there (:mod:`pkgtool.cache.replay` records a run and gives what it knows)."""
    global _witness, _known
    _witness, _known = witness, known or {}
    try:
        yield
    finally:
        _witness, _known = None, {}


def listing(folder: str | Path) -> list[Any]:
    """The entries of ``folder`` (:class:`os.DirEntry`, or what stands in for them); none when
    it cannot be listed."""
    if _witness is None:
        return _listed(folder)
    path = os.fspath(folder)
    known = _known.get(path)
    if known is not None:
        _witness(path, *known)
        return known[1]
    status = _status(folder)
    found = _listed(folder)
    _witness(path, status, found)
    return found


def _listed(folder: str | Path) -> list[os.DirEntry[str]]:
    try:
        with os.scandir(folder) as entries:
            return list(entries)
    except OSError:
        return []


def _status(path: str | Path) -> os.stat_result | None:
    try:
        return os.stat(path)
    except OSError:
        return None


def _is_dir(entry: os.DirEntry[str]) -> bool:
    try:
        return entry.is_dir()
    except OSError:
        return False


def _is_file(entry: os.DirEntry[str]) -> bool:
    """As :func:`is_package` sees a marker (links followed), mostly without a system call."""
    try:
        return entry.is_file()
    except OSError:
        return False
