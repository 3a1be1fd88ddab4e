"""What the DAT rules share: data_files entries by destination, and folder tests."""

from __future__ import annotations

import ast
import fnmatch
import posixpath
from collections.abc import Iterable, Iterator

from pkgtool.model.context import lists_files_of
from pkgtool.model.files import DESCRIPTION_SUFFIXES
from pkgtool.model.installed import installed_data
from pkgtool.model.launch import EXISTENCE_CHECKS, LAUNCH_FILE_NAME, FileRef, LaunchFile
from pkgtool.model.launch_python import read_python_launch
from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.model.python_visitor import parse_tree
from pkgtool.model.scripts import Installs, installs_share_path, sibling_data_files
from pkgtool.model.setup_py import DataFile, DataSource
from pkgtool.rules.existence_checks import HANDLING_FILES, checks_files
from pkgtool.rules.setup_values import checked_setup
from pkgtool.rules.syntax_trees import index_of, installed_trees
from pkgtool.lazy_regex import lazy_pattern

_SEARCH_PATHS = lazy_pattern(r"\b(?:GZ_SIM|IGN_GAZEBO)_(?:RESOURCE|SYSTEM_PLUGIN)_PATH\b|"
                             r"\bGAZEBO_(?:MODEL|RESOURCE|PLUGIN)_PATH\b|\b(?:GZ|IGN)_FILE_PATH\b|"
                             r"\bSDF_PATH\b")
"""Environment variables of simulators' search paths: a launch file setting one joins share
folders to put on it, where a missing folder is skipped, not read."""


def destination_parts(entry: DataFile) -> list[str]:
    """The folders of a data_files entry's destination, normalised (``share/pkg/launch``)."""
    return posixpath.normpath(entry.destination.replace("\\", "/")).split("/")


def entries_to(package: Package, destination: str) -> Iterator[tuple[DataFile, DataSource]]:
    """data_files sources declared for ``destination`` (whether or not they exist)."""
    setup = package.setup_py
    for entry in setup.data_files or () if setup else ():
        if posixpath.normpath(entry.destination) == destination:
            yield from ((entry, source) for source in entry.sources)


def source_names(source: DataSource) -> set[str]:
    """Package-relative paths a source stands for: its matches, or its literal path."""
    return set(source.matches) or {posixpath.normpath(source.pattern)}


@per_package
def uninstalled_launch_resources(package: Package
                                 ) -> tuple[tuple[str, FileRef, str, dict[str, str]], ...]:
    """Each file an installed launch file or module reads from this package's share folder
    that data_files installs neither itself nor a folder of: the reader's path, the
    reference, the path relative to the share folder (``config/params.yaml``), and what
    data_files installs. Nothing when data_files is not known statically; nothing for a path
    only parameter files of nodes never started use (``mux = Node(..., parameters=[path])``
    left out of the LaunchDescription: the launch never reads it), nor for one data_files
    lists from a source that does not exist (DAT001's). Worked out once per package: DAT006,
    DAT012 and DAT006's fixer (asked finding by finding) read it."""
    return tuple(_uninstalled(package))


_GLOB = lazy_pattern(r"[*?[]")
"""A path that is a glob pattern (what ``glob.glob`` expands), not a file name."""


def _uninstalled(package: Package) -> Iterator[tuple[str, FileRef, str, dict[str, str]]]:
    setup = checked_setup(package)
    installed = installed_data(package) if setup else None
    if installed is None or setup is None:
        return
    share = f"share/{package.name}"
    listed = {posixpath.normpath(posixpath.join(entry.destination,
                                                posixpath.basename(source.pattern)))
              for entry in setup.data_files or () if not entry.sources_is_text
              for source in entry.sources if not source.is_glob}
    shared = {source for target, source in installed.items() if target.startswith(share + "/")}
    folders = {posixpath.normpath(entry.destination) for entry in setup.data_files or ()}
    # setuptools makes every destination folder, even for an empty list of files
    for path, refs in _share_reads(package, shared):
        for ref in refs:
            if ref.package != package.name or not ref.parts:
                continue
            target = posixpath.normpath(posixpath.join(share, *ref.parts))
            if target in installed or target in listed or target in folders or \
                    any(t.startswith(target + "/") for t in installed) or \
                    _GLOB.search(target) and any(fnmatch.fnmatchcase(t, target)
                                                 for t in (*installed, *listed)):
                continue  # a pattern (`config/*.yaml`) the code expands: installed files match
            yield path, ref, posixpath.relpath(target, share), installed


@per_package
def sibling_share_misses(package: Package) -> tuple[tuple[str, FileRef, str], ...]:
    """Each launch file an installed launch file or module includes, and each robot
    description, world or RViz file it reads, from the share folder of another ament_python
    package of the workspace that the package's setup.py certainly
    installs no file of that name for (:func:`~pkgtool.model.scripts.installs_share_path`;
    other files may be made there at run time, a calibration or a map saved, which the
    package's code, not read here, would tell): the reader's path, the reference and the
    path below that package's share folder."""
    installed = installed_data(package)
    if installed is None:
        return ()
    shared = {source for target, source in installed.items()
              if target.startswith(f"share/{package.name}/")}
    found: list[tuple[str, FileRef, str]] = []
    seen: set[tuple[str, str | None, str]] = set()  # a path built once, used again
    for path, refs in _share_reads(package, shared):
        for ref in refs:
            sibling = package.context.workspace.get(ref.package or "") \
                if ref.package != package.name and ref.parts and _kept_as_written(ref.parts[-1]) \
                else None
            installs = sibling_data_files(sibling) if sibling is not None else None
            relative = posixpath.normpath(posixpath.join(*ref.parts))
            target = f"share/{ref.package}/{relative}"
            if installs is not None and not _GLOB.search(relative) and \
                    (not installs_share_path(installs, target) or
                     _no_source(installs, target, sibling.description_files)) and \
                    (path, ref.package, relative) not in seen:
                seen.add((path, ref.package, relative))
                found.append((path, ref, relative))
    return tuple(found)


def _no_source(installs: Installs, target: str, present: frozenset[str]) -> bool:
    """True when ``target`` is a description file that only globs of one-folder-deep sources
    (``urdf/*.urdf``) may install, and none of those folders holds a file of its name, each
    holding other description files (an empty one may be a link the listing does not follow):
    ``present`` are the package's description files (``WorkspacePackage.description_files``)."""
    folder, name = posixpath.split(target)
    if not name.endswith(DESCRIPTION_SUFFIXES):
        return False
    sources = []
    for destination, pattern, is_glob in installs:
        if destination == target or destination.startswith(target + "/") or \
                destination == folder and not is_glob and \
                posixpath.basename(posixpath.normpath(pattern)) == name:
            return False  # a source listed by name: whether it exists is that package's DAT001
        if destination == folder and is_glob and \
                fnmatch.fnmatchcase(name, posixpath.basename(pattern)):
            sources.append(posixpath.join(posixpath.dirname(posixpath.normpath(pattern)), name))
    folders = {p.split("/")[0] for p in present}  # a folder listing none may be a link
    return bool(sources) and all(source.count("/") == 1 and lists_files_of(source.split("/")[0])
                                 and source.split("/")[0] in folders and source not in present
                                 for source in sources)


def installed_descriptions(package: Package, name: str) -> list[str]:
    """The paths below its share folder where the workspace package ``name`` (ament_python)
    installs its description files (``WorkspacePackage.description_files``), sorted."""
    sibling = package.context.workspace.get(name)
    installs = sibling_data_files(sibling) if sibling is not None else None
    share = f"share/{name}"
    found = set()
    for source in sibling.description_files if installs is not None else ():
        for destination, pattern, is_glob in installs or ():
            pattern = posixpath.normpath(pattern)
            if (fnmatch.fnmatchcase(source, pattern) if is_glob else pattern == source) and \
                    (destination == share or destination.startswith(share + "/")):
                found.add(posixpath.join(destination[len(share) + 1:],
                                         posixpath.basename(source)))
    return sorted(found)


def _kept_as_written(name: str) -> bool:
    """True for a launch file or a robot description, world or RViz file: what a package
    installs as written, never a file code makes at run time (a map, a calibration)."""
    return LAUNCH_FILE_NAME.search(name) is not None or name.endswith(DESCRIPTION_SUFFIXES)


def _share_reads(package: Package, shared: set[str]
                 ) -> Iterator[tuple[str, Iterable[FileRef]]]:
    """The share files each installed launch file (but those only nodes never started use)
    and each installed module reading a package's share folder reads."""
    for launch in package.launch_files:
        if launch.path in shared and not _launch_makes_folders(package, launch):
            unread = _only_unused_nodes_read(launch)
            searched = _SEARCH_PATHS.search(package.texts.get(launch.path, "")) is not None
            yield launch.path, (ref for ref in launch.files
                                if (ref.package, ref.parts) not in unread and not ref.checked
                                and not (searched and ref.parts and "." not in ref.parts[-1]))
    for module, tree, index in installed_trees(package):
        if index.imports_from("ament_index_python") and not checks_files(index):
            yield module.path, read_python_launch(module.path, tree, _imported_names(package))[2]


@per_package
def _imported_names(package: Package) -> frozenset[str]:
    """Every name a module of the package may take from another: those ``from`` imports name
    and every attribute read (``config.MAP_PATH``)."""
    names = {name for module in package.modules for imported in module.imports
             for name in imported.names}
    names.update(node.attr for _, _, index in installed_trees(package)
                 for node in index.attributes)
    return frozenset(names)


def _launch_makes_folders(package: Package, launch: LaunchFile) -> bool:
    """True when a Python launch file makes folders or loads an optional ``.env`` file
    (:data:`~pkgtool.rules.existence_checks.HANDLING_FILES` but the existence checks, which
    each file reference says itself: ``FileRef.checked``): it may make the share path it
    names."""
    text = package.texts.get(launch.path)
    tree = parse_tree(launch.path, text) if launch.kind == "python" and text else None
    return isinstance(tree, ast.Module) and \
        checks_files(index_of(tree), HANDLING_FILES - EXISTENCE_CHECKS)


def _only_unused_nodes_read(launch: LaunchFile) -> set[tuple[str | None, tuple[str, ...]]]:
    """The share files of ``launch`` given as parameters only to nodes it never starts."""
    def files(unused: bool) -> set[tuple[str | None, tuple[str, ...]]]:
        return {(ref.package, ref.parts) for node in launch.nodes if node.unused is unused
                for ref in node.parameter_files}

    return files(True) - files(False)
