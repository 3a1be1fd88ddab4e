"""Fixers of data_files: the ament index marker, package.xml, launch files and what they read.

Entries are added to (or literals changed in) setup.py's data_files list through
:class:`pkgtool.edit.setup_py.SetupDoc`, which refuses, with the reason, a data_files that code
pkgtool does not evaluate computes. Every fix installs more, or installs into the right place
what was installed into the wrong one: none removes an installed file the package relies on.
"""

from __future__ import annotations

import ast
import posixpath
from collections.abc import Callable, Iterator, Sequence

from pkgtool.edit.core import Edit, Fix
from pkgtool.edit.setup_py import SetupDoc
from pkgtool.findings import Finding
from pkgtool.fix.common import offer, renames, setup_doc
from pkgtool.fix.registry import Refusal, fixer
from pkgtool.lazy_regex import lazy_pattern
from pkgtool.model.installed import is_ament_python
from pkgtool.model.launch import LAUNCH_SUFFIXES
from pkgtool.model.package import Package
from pkgtool.model.setup_py import DataFile, DataSource
from pkgtool.rules.data_files.common import uninstalled_launch_resources
from pkgtool.rules.plain_projects import MARKER_FOLDER

Build = Callable[[SetupDoc], Sequence[Edit]]


def _offer(package: Package, title: str, build: Build) -> Iterator[Fix | Refusal]:
    """``build``'s edits against setup.py as one fix (a refusal says why there is none)."""
    doc = setup_doc(package)
    if doc is not None:
        yield from offer(title, lambda: build(doc))


def _entry_at(package: Package, finding: Finding) -> DataFile | None:
    """The data_files entry a finding of setup.py points at."""
    setup = package.setup_py
    return next((e for e in setup.data_files or () if e.span == finding.span), None) \
        if setup else None


def _literal_only(entry: DataFile, doc: SetupDoc) -> tuple[object, object] | None:
    """The evaluated ``(destination, sources)`` pair of ``entry``, if setup.py gives it."""
    for pair in doc.value("data_files", "data_files") or ():
        if getattr(pair, "span", None) == entry.span and isinstance(pair, tuple) and \
                len(pair) == 2:
            return pair[0], pair[1]
    return None


@fixer("DAT001", "Create the missing marker file, or make a string of sources a list")
def missing_file(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    """Write a string given as an entry's sources as a one-item list (setuptools would install
    each of its characters), or create the empty ``resource/<package>`` data_files installs as
    the ament index marker. Safe: the list installs what the string meant, and the marker's
    content is never read. Any other missing file has content only its author knows: no fix."""
    marker_path = f"resource/{package.name}"
    entries = package.setup_py.data_files or () if package.setup_py else ()
    for finding in findings:
        for entry in entries:
            source = next((s for s in entry.sources if s.span == finding.span), None)
            if source is None:
                continue
            if entry.sources_is_text:
                yield from _offer(package, f"Write `['{source.pattern}']`",
                                  lambda doc, s=source: _as_list(doc, s))
            elif (entry.destination.rstrip("/") == MARKER_FOLDER
                  and posixpath.normpath(source.pattern) == marker_path):
                create = _marker_file(package)
                if create:
                    yield Fix(f"Create the empty `{marker_path}`", tuple(create))
            break


def _as_list(doc: SetupDoc, source: DataSource) -> list[Edit]:
    span = source.span
    node = next((n for n in doc.nodes.get((span.line, span.col), [])
                 if isinstance(n, ast.Constant) and n.value == source.pattern), None)
    if node is None:
        doc.refuse(f"computes the sources on line {span.line} with code")
    written = doc.doc.source.text[doc.doc.start(node):doc.doc.end(node)]
    return [doc.edit(node, f"[{written}]")]


@fixer("DAT003", "Install the ament index marker")
def marker(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    """Add the marker entry (creating the empty ``resource/<package>``), or correct the
    destination or the marker's file name when a string literal gives it. Safe: without the
    marker no ROS tool finds the package."""
    name = package.name
    for finding in findings:
        entry = _entry_at(package, finding)
        if entry is None:
            yield from _offer(package, f"Install `{MARKER_FOLDER}/{name}`",
                              lambda doc: _add_marker(package, doc))
        elif entry.destination.rstrip("/") != MARKER_FOLDER:
            yield from _offer(package, f"Install the marker into `{MARKER_FOLDER}`",
                              lambda doc, e=entry: _retarget(doc, e,
                                                             doc.doc.string(MARKER_FOLDER)))
        else:
            yield from _offer(package, f"Install `resource/{name}` as the marker",
                              lambda doc, e=entry: _rename_marker(package, doc, e))


def _marker_file(package: Package) -> list[Edit]:
    path = f"resource/{package.name}"
    return [] if package.has_file(path) else [Edit(path, 0, 0, "", create=True)]


def _marker_source(doc: SetupDoc, package: Package) -> str:
    bound = doc.expression(package.name, "")
    return f"{doc.doc.string('resource/')} + {bound}" if bound else \
        doc.doc.string(f"resource/{package.name}")


def _add_marker(package: Package, doc: SetupDoc) -> list[Edit]:
    if doc.installs(MARKER_FOLDER, f"resource/{package.name}"):
        return []
    item = f"({doc.doc.string(MARKER_FOLDER)}, [{_marker_source(doc, package)}])"
    return doc.add_data_entry(item) + _marker_file(package)


def _rename_marker(package: Package, doc: SetupDoc, entry: DataFile) -> list[Edit]:
    pair = _literal_only(entry, doc)
    sources = pair[1] if pair else None
    if not isinstance(sources, list) or len(sources) != 1:
        doc.refuse(f"installs several markers or computes them on line {entry.span.line}")
    replacement = _marker_source(doc, package)
    return [doc.replace_value(sources[0], replacement, "the marker")] + _marker_file(package)


def _retarget(doc: SetupDoc, entry: DataFile, destination: str) -> list[Edit]:
    """Write ``destination`` (source text) over the entry's literal destination."""
    pair = _literal_only(entry, doc)
    if pair is None:
        doc.refuse(f"computes the data_files entry on line {entry.span.line}")
    return [doc.replace_value(pair[0], destination, "the destination")]


@fixer("DAT004", "Install package.xml into `share/<package>`")
def package_xml(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    """Add ``('share/' + package_name, ['package.xml'])``, or point an entry that installs
    only package.xml elsewhere at ``share/<package>``. Safe: installs the manifest where
    ``ros2 pkg xml`` and colcon look."""
    for finding in findings:
        entry = _entry_at(package, finding)
        if entry is None:
            yield from _offer(package, "Install `package.xml`", lambda doc: doc.add_data_files(
                "", "package.xml", package.name, files=True))
        elif [s.pattern for s in entry.sources] == ["package.xml"]:
            yield from _offer(package, f"Install `package.xml` into `share/{package.name}`",
                              lambda doc, e=entry: _retarget(doc, e, _share(doc, package)))
        else:
            yield Refusal(f"setup.py installs package.xml with other files into "
                          f"`{entry.destination}`: move it to `share/{package.name}` by hand.")


def _share(doc: SetupDoc, package: Package) -> str:
    bound = doc.expression(package.name, "")
    return f"{doc.doc.string('share/')} + {bound}" if bound else \
        doc.doc.string(f"share/{package.name}")


@fixer("DAT005", "Install the launch files")
def launch_files(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    """Install each folder's launch files by a glob of their suffix (``launch/*.launch.py``)
    into ``share/<package>/<folder>``. Safe: it only installs files. Not for a package built
    with CMake (its setup.py, if any, is never run): CMakeLists.txt is the user's to edit."""
    if not is_ament_python(package):
        yield Refusal("the package is built with CMake: add the `install()` the help names")
        return
    wanted = dict.fromkeys(_launch_glob(f.span.path) for f in findings)
    for folder, pattern in wanted:
        yield from _offer(package, f"Install `{pattern}`",
                          lambda doc, f=folder, p=pattern: doc.add_data_files(f, p, package.name))


def _launch_glob(path: str) -> tuple[str, str]:
    """(share sub-folder, glob) for a launch file: its folder and suffix."""
    folder, name = posixpath.split(path)
    suffix = next((s for s in LAUNCH_SUFFIXES if name.endswith(s)), None)
    return folder, posixpath.join(folder, f"*{suffix}") if suffix else path


@fixer("DAT006", "Install the file a launch file or module reads")
def launch_resources(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    """Install the files of that kind in its folder (``config/*.yaml``), or a folder's files
    (DAT006 reports only paths the package has; DAT012 the others). Safe: only installs."""
    at = {(f.span.path, f.span.line, f.span.col) for f in findings}
    paths = dict.fromkeys(relative for _, ref, relative, _ in uninstalled_launch_resources(package)
                          if (ref.span.path, ref.span.line, ref.span.col) in at)
    for path in paths:
        if package.has_file(path):
            folder, name = posixpath.split(path)
            stem, dot, suffix = name.rpartition(".")
            pattern = posixpath.join(folder, f"*.{suffix}") if dot and stem else path
            yield from _offer(package, f"Install `{pattern}`",
                              lambda doc, f=folder, p=pattern: doc.add_data_files(
                                  f, p, package.name))
        else:
            yield from _folder_files(package, path)


def _folder_files(package: Package, folder: str) -> Iterator[Fix | Refusal]:
    edits = _folder_entries(package, folder, folder)
    if edits is None:
        yield Refusal(f"`{folder}` has nested sub-folders: install them by hand.")
    else:
        yield from _offer(package, f"Install the files of `{folder}`", lambda doc: [
            e for sub, pattern in edits for e in doc.add_data_files(sub, pattern, package.name)])


def _files_glob(package: Package, folder: str) -> str | None:
    """A glob of the files directly in ``folder`` that matches none of its sub-folders:
    ``folder/*``, or ``folder/*.ext`` when the files share that suffix; else None."""
    prefix = folder.rstrip("/") + "/"
    inside = [f[len(prefix):] for f in package.files if f.startswith(prefix)]
    files = [f for f in inside if "/" not in f]
    folders = {f.split("/")[0] for f in inside if "/" in f}
    suffixes = {posixpath.splitext(f)[1] for f in files}
    if files and not folders:
        return f"{prefix}*"
    suffix = suffixes.pop() if len(suffixes) == 1 else ""
    if files and suffix and not any(f.endswith(suffix) for f in folders):
        return f"{prefix}*{suffix}"
    return None


def _sub_folders(package: Package, folder: str) -> list[str]:
    prefix = folder.rstrip("/") + "/"
    return sorted({prefix + f[len(prefix):].split("/")[0] for f in package.files
                   if f.startswith(prefix) and "/" in f[len(prefix):]})


def _folder_entries(package: Package, folder: str, target: str
                    ) -> list[tuple[str, str]] | None:
    """(share sub-folder, glob) pairs installing ``folder`` into ``share/<pkg>/<target>``,
    one per folder level (files of a sub-folder of a sub-folder: None)."""
    own = _files_glob(package, folder)
    pairs = [(target, own)] if own else []
    for sub in _sub_folders(package, folder):
        pattern = _files_glob(package, sub)
        if pattern is None or _sub_folders(package, sub):
            return None
        pairs.append((posixpath.join(target, posixpath.basename(sub)), pattern))
    return pairs or None


@fixer("DAT007", "Replace the folder by globs of its files")
def folder_source(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    """A folder source becomes globs of its files: ``glob('config/*')`` that also matches
    ``config/maps/`` becomes ``glob('config/*.yaml')`` plus an entry for ``config/maps``; a
    literal ``'config'`` becomes ``glob('config/*')`` when it is the entry's only source,
    else its own entry into ``<destination>/config``. Deeper folders are refused. Safe:
    setuptools could not install the folder, the build failed."""
    setup = package.setup_py
    at = {(f.span.line, f.span.col) for f in findings if f.span.path == "setup.py"}
    share = f"share/{package.name}"
    for entry in setup.data_files or () if setup else ():
        destination = posixpath.normpath(entry.destination)
        if destination != share and not destination.startswith(share + "/"):
            continue
        target = posixpath.relpath(destination, share)
        target = "" if target == "." else target
        for source in entry.sources:
            if (source.span.line, source.span.col) in at:
                yield from _folder_fix(package, entry, source, target)


def _folder_fix(package: Package, entry: DataFile, source: DataSource, target: str
                ) -> Iterator[Fix | Refusal]:
    name = package.name
    if source.is_glob:
        folders = [m for m in source.matches if package.has_folder(m)]
        base = folders[0] if folders == list(source.matches) and len(folders) == 1 else \
            posixpath.dirname(source.pattern)
        subs = _sub_folders(package, base) if base in folders else folders
        pattern = _files_glob(package, base) if base else None
        more = [(posixpath.join(target, posixpath.basename(f)), _files_glob(package, f))
                for f in subs if posixpath.dirname(f) == base and not _sub_folders(package, f)]
        if pattern is None or any(p is None for _, p in more) or len(more) != len(subs):
            yield Refusal(f"`{source.pattern}` matches folders pkgtool cannot list: list the "
                          "files by hand.")
            return
        yield from _offer(package, f"Glob `{pattern}`", lambda doc: [
            doc.edit(doc.glob_pattern(source.span), doc.doc.string(pattern)),
            *(e for sub, p in more for e in doc.add_data_files(sub, p, name))])
        return
    folder = posixpath.normpath(source.pattern)
    if len(entry.sources) == 1 and not _sub_folders(package, folder):
        yield from _offer(package, f"Install the files of `{folder}`",
                          lambda doc: _glob_instead(doc, entry, f"{folder}/*"))
        return
    pairs = _folder_entries(package, folder, posixpath.join(target, posixpath.basename(folder)))
    if pairs is None:
        yield Refusal(f"`{folder}` has nested sub-folders: install them by hand.")
        return
    yield from _offer(package, f"Install the files of `{folder}` in their own entries",
                      lambda doc: [_drop_source(doc, entry, source), *(
                          e for sub, p in pairs for e in doc.add_data_files(sub, p, name))])


def _drop_source(doc: SetupDoc, entry: DataFile, source: DataSource) -> Edit:
    pair = _literal_only(entry, doc)
    sources = pair[1] if pair else None
    item = next((s for s in sources or () if getattr(s, "span", None) == source.span), None)
    if item is None:
        doc.refuse(f"computes the sources on line {entry.span.line}")
    return doc.remove_from(sources, item, "the data_files sources")


def _glob_instead(doc: SetupDoc, entry: DataFile, pattern: str) -> list[Edit]:
    pair = _literal_only(entry, doc)
    sources = pair[1] if pair else None
    if not isinstance(sources, list) or len(sources) != 1:
        doc.refuse(f"computes the sources on line {entry.span.line}")
    call, imports = doc.glob_call(pattern)
    return [doc.replace_sequence(sources, call, "the data_files sources")] + \
        doc.doc.add_imports(imports)


_TYPO_OF = lazy_pattern(r": `([\w.-]+)` is a typo of")
"""The misspelt name in a DAT021 or DAT022 message."""
_SHARE_MEANT = lazy_pattern(r"Install into `share/([\w.-]+)(?:/[^`]*)?`")
_FOLDER_MEANT = lazy_pattern(r"Install into `share/[\w.-]+/([\w.-]+)`")
"""The names meant in DAT021's and DAT022's help."""


@fixer("DAT021", "Write the package's name where the share folder misspells it")
def share_folder(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename the misspelt package name of a data_files destination (``'share/deom/config'``
    to ``'share/demo/config'``): the files were installed where nothing looks."""
    yield from renames(package, findings, _TYPO_OF, _SHARE_MEANT)


@fixer("DAT022", "Name the installed folder like its source folder", safe=False)
def data_folder(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Rename the misspelt folder of a data_files destination (``'lauch'`` to ``'launch'``).
    Unsafe: code may read the files from the misspelt folder."""
    yield from renames(package, findings, _TYPO_OF, _FOLDER_MEANT)
