"""What a package is linted against: the target ROS distribution and the other workspace packages.

The workspace of a package is every package linted in the same run plus, when the package
lies under the ``src`` folder of a colcon workspace (a folder ``ws`` with ``ws/src``), every
package colcon would find there; of several packages of one name (two workspaces linted in one
run) a package sees the nearest one (:func:`workspace_near`). For each one the index keeps
its name, the interfaces of its ``msg/``, ``srv/`` and ``action/`` folders (their subfolders
too: see :func:`interface_file`) and the other files its CMakeLists.txt generates interfaces
from (none when that list is open), and its top-level Python packages (those its CMakeLists.txt
installs with ``ament_python_install_package`` too). Reading is cheap
(package.xml's name, CMakeLists.txt and a few folder listings) and never raises.
"""

from __future__ import annotations

import functools
import os
import re
from collections import Counter
from collections.abc import Callable, Iterable, Mapping
from pathlib import Path

from pkgtool.knowledge.interface_definitions import definitions
from pkgtool.knowledge.tables import DEFAULT_DISTRO
from pkgtool.model.cmake_install import installed_executables, installed_python_packages
from pkgtool.model.cmake_interfaces import with_listed
from pkgtool.model.cmake_text import with_included
from pkgtool.model.digest import text_digest
from pkgtool.model.files import DESCRIPTION_SUFFIXES, list_files, read_bytes
from pkgtool.model.manifest import CMAKE_BUILD_TYPES
from pkgtool.model.memo import per_object
from pkgtool.model.pyproject import pyproject_may_add_scripts
from pkgtool.records import field, record
from pkgtool.lazy_regex import lazy_pattern

_NAME = lazy_pattern(r"<name>\s*([^<\s]+)\s*</name>")
_KINDS = ("msg", "srv", "action")
_SUFFIX_KINDS = {".msg": "msg", ".srv": "srv", ".action": "action"}
_DEPTH = 4
"""How deep interface folders are read (``msg/a/b/c/X.msg`` at most)."""
_NOT_MODULES = frozenset({"test", "tests", "launch", "resource", "build", "install", "log"})


@record
class WorkspacePackage:
    """Another package of the workspace: its interfaces (kind -> names), Python packages, and
    the fields and constants of the message classes its ``.msg``, ``.srv`` and ``.action``
    files define (``pkg/kind/Class`` -> entry: :mod:`pkgtool.knowledge.interface_definitions`).

    ``folder`` is where it lies; ``setup_digest`` is a digest of its setup.py and setup.cfg
    when colcon builds it with setup.py alone (ament_python, no pyproject.toml), else empty:
    :func:`~pkgtool.model.scripts.sibling_executables` reads its executables from
    those files when a rule asks, and the digest keys the lint cache to them.
    """

    name: str
    interfaces: Mapping[str, frozenset[str]] = field(default_factory=dict)
    modules: frozenset[str] = frozenset()
    messages: Mapping[str, str] = field(default_factory=dict)
    folder: str = ""
    setup_digest: str = ""
    depends: frozenset[str] = frozenset()
    """The packages its package.xml declares as build or run dependencies (any tag but
    ``test_depend`` and ``doc_depend``)."""
    executables: frozenset[str] | None = None
    """For a package CMake builds, the executables its CMakeLists.txt installs into
    ``lib/<name>`` (:func:`~pkgtool.model.cmake_install.installed_executables`); None when
    not known or not such a package."""
    manifest: bool = True
    """False for a Python project without package.xml (a ``setup.py`` alone): colcon builds
    it, but rosdep knows no such package, so no package.xml can declare a dependency on it."""
    description_files: frozenset[str] = frozenset()
    """Its robot description, world and RViz files (:data:`~pkgtool.model.files.
    DESCRIPTION_SUFFIXES`) one folder deep (``urdf/robot.urdf``), in folders the index lists
    (:func:`lists_files_of`): whether a file its data_files glob would install exists."""


@record
class Context:
    """The target ``distro``, the workspace's packages by name (the linted one included) and
    the other folders of the workspace holding a package of the linted one's name."""

    distro: str = DEFAULT_DISTRO
    workspace: Mapping[str, WorkspacePackage] = field(default_factory=dict)
    twins: tuple[str, ...] = ()
    """Other folders of the package's colcon workspace holding a package of its name
    (:func:`same_named`)."""
    python: tuple[int, int] | None = None
    """The Python the project declares in a pyproject.toml, when it does
    (:mod:`pkgtool.model.declared_python`); else the distribution's."""

    def provider(self, module: str) -> str | None:
        """The workspace package whose Python package ``module`` is, if any: one installing a
        Python package of that name, else an interface package of that name (rosidl generates
        the Python package ``<name>`` holding its ``msg``, ``srv`` and ``action`` modules)."""
        installing = _installers(self.workspace).get(module)
        if installing is not None:
            return installing
        named = self.workspace.get(module)
        return module if named is not None and named.interfaces else None


@per_object(4)
def _installers(workspace: Mapping[str, WorkspacePackage]) -> dict[str, str]:
    """Each Python package the ``workspace`` installs, by the first package installing it:
    worked out once per workspace, not once per import looked up (a scan of every package)."""
    found: dict[str, str] = {}
    for package in workspace.values():
        for module in package.modules:
            found.setdefault(module, package.name)
    return found


def interface_file(path: str) -> tuple[str, str] | None:
    """The kind and name of the interface the package file ``path`` (POSIX) defines, or None.

    rosidl's adapter takes the kind of a ``.msg``, ``.srv`` or ``.action`` file from its suffix
    and flattens its folders (``msg/motion/Twist.msg`` is ``msg/Twist``), so such files count
    anywhere under the three kind folders; an ``.idl`` file counts directly inside one.
    """
    folder, _, name = path.rpartition("/")
    top = folder.split("/", 1)[0]
    stem, dot, suffix = name.rpartition(".")
    if top not in _KINDS or not dot or not stem:
        return None
    if f".{suffix}" in _SUFFIX_KINDS:
        return _SUFFIX_KINDS[f".{suffix}"], stem
    return (folder, stem) if suffix == "idl" and folder == top else None


def _index_depth(name: str) -> int:
    """How many folder levels below the top-level folder ``name`` the index reads: interface
    folders to :data:`_DEPTH`, ``src`` to its Python packages' ``__init__.py``, a Python
    package to its own ``__init__.py``; nothing else."""
    if name in _KINDS:
        return _DEPTH
    if name == "src":
        return 2
    return 1 if name.isidentifier() and name not in _NOT_MODULES else 0


def lists_files_of(folder: str) -> bool:
    """True when the index lists the files of the package's top-level ``folder`` (so a file
    not listed there is no file of the package)."""
    return _index_depth(folder) >= 1


def manifest_name(manifest: str) -> str | None:
    """The ``<name>`` a package.xml's text gives (an old manifest kept in a comment names
    nothing), or None."""
    if "<!--" in manifest:
        manifest = _COMMENT.sub("", manifest)
    found = _NAME.search(manifest)
    return found.group(1) if found else None


def read_workspace_package(root: Path, files: Iterable[str] | None = None) -> WorkspacePackage:
    """Name (package.xml, else the folder), interfaces and Python packages of ``root``.

    ``files`` are the package's files as :func:`~pkgtool.model.files.list_files` lists them,
    when the caller has them: the result is the same, without listing folders again.
    """
    base = os.fspath(root)
    setup = functools.cache(lambda: setup_texts(base))  # read once, if at all
    manifest = _read(os.path.join(base, "package.xml"))
    name = (manifest_name(manifest) if manifest is not None else None) or \
        (_setup_name(*setup()) if manifest is None else None) or root.name
    kinds: dict[str, set[str]] = {}
    modules: set[str] = set()
    defined: dict[tuple[str, str], str | None] = {}
    described: set[str] = set()
    cmake = None
    listed = tuple(list_files(root, _index_depth) if files is None else files)
    for path in listed:
        parts = path.split("/")
        if parts[-1] == "__init__.py" and _is_module(parts[:-1]):
            modules.add(parts[-2])
        elif path == f"{name}.py":  # py_modules=['<name>']: a module named like the package
            modules.add(name)
        elif parts[0] in _KINDS and len(parts) <= _DEPTH + 1:
            kind_and_stem = interface_file(path)
            if kind_and_stem is not None:
                kinds.setdefault(kind_and_stem[0], set()).add(kind_and_stem[1])
                # two files of one interface (msg/a/X.msg, msg/b/X.msg): neither is known
                defined[kind_and_stem] = None if kind_and_stem in defined or \
                    path.endswith(".idl") else path
        elif path == "CMakeLists.txt":
            cmake = _read(os.path.join(base, path))
        elif len(parts) == 2 and path.endswith(DESCRIPTION_SUFFIXES) and \
                lists_files_of(parts[0]):
            described.add(path)
    folders = {kind: frozenset(names) for kind, names in kinds.items()}
    if cmake is not None:
        cmake = with_included(cmake, lambda path: _read(os.path.join(base, path)))
        modules |= installed_python_packages(cmake)
    interfaces = with_listed(folders, cmake, listed) or {}
    setup_digest = _setup_digest(manifest, listed, setup, base)
    executables = installed_executables(cmake) if cmake is not None and not setup_digest and \
        _build_type(manifest) in CMAKE_BUILD_TYPES else None
    return WorkspacePackage(name, interfaces, frozenset(modules),
                            _messages(base, name, interfaces, defined), base, setup_digest,
                            _depends(manifest), executables, manifest is not None,
                            frozenset(described))


_DEPEND = lazy_pattern(r"<(?:depend|exec_depend|run_depend|build_depend|build_export_depend|"
                       r"buildtool_depend)(?:\s[^>]*)?>\s*([^<\s]+)\s*</")


def _depends(manifest: str | None) -> frozenset[str]:
    """The build and run dependencies a package.xml's text (without comments) declares."""
    return frozenset(_DEPEND.findall(manifest)) if manifest else frozenset()


_BUILD_TYPE = lazy_pattern(r"<build_type>\s*([^<\s]+)\s*</build_type>")
_COMMENT = lazy_pattern(r"<!--.*?-->", re.DOTALL)
_ANY_DEPEND = lazy_pattern(r"<(?:\w+_)?depend(?:\s[^>]*)?>\s*([^<\s]+)\s*</")
"""A dependency tag of any kind (``<test_depend>`` too) and the name it declares."""


def commented_dependencies(manifest: str) -> frozenset[str]:
    """The packages a package.xml's text declares only inside comments
    (``<!-- <exec_depend>x</exec_depend> -->``)."""
    return frozenset(name for comment in _COMMENT.findall(manifest) if "depend" in comment
                     for name in _ANY_DEPEND.findall(comment))


def _setup_digest(manifest: str | None, listed: tuple[str, ...],
                  setup: Callable[[], tuple[str | None, str | None]], base: str) -> str:
    """:attr:`WorkspacePackage.setup_digest` of the package in ``base`` with files ``listed``,
    whose setup.py and setup.cfg texts ``setup`` reads (a pyproject.toml of tool settings
    only is part of the digest: it adds no executable, but may come to)."""
    project = _read(os.path.join(base, "pyproject.toml")) if "pyproject.toml" in listed \
        else None
    if "setup.py" not in listed or pyproject_may_add_scripts(project):
        return ""
    build_type = _build_type(manifest)
    if (build_type != "ament_python") if build_type else "CMakeLists.txt" in listed:
        return ""
    return text_digest(*setup(), *(() if project is None else (project,)))


def _build_type(manifest: str | None) -> str | None:
    """The ``<build_type>`` a package.xml's text declares (comments aside), or None."""
    found = _BUILD_TYPE.search(_COMMENT.sub("", manifest or ""))
    return found.group(1) if found else None


def _setup_name(setup_text: str | None, cfg_text: str | None) -> str | None:
    """The name colcon gives a Python project without package.xml: setup.py's ``name=``, else
    setup.cfg's ``[metadata] name`` (not its folder's name)."""
    from pkgtool.model.setup_cfg import SetupCfg, parse_setup_cfg
    from pkgtool.model.setup_py import SetupPy, parse_setup_py

    setup = parse_setup_py("setup.py", setup_text, None) if setup_text is not None else None
    if isinstance(setup, SetupPy) and setup.name is not None and \
            isinstance(setup.name.value, str) and setup.name.value:
        return setup.name.value
    cfg = parse_setup_cfg("setup.cfg", cfg_text) if cfg_text is not None else None
    option = cfg.get("metadata", "name") if isinstance(cfg, SetupCfg) else None
    return option.value.strip() or None if option is not None else None


def setup_texts(base: str) -> tuple[str | None, str | None]:
    """The texts of setup.py and setup.cfg of the package at ``base`` (None: missing or
    unreadable)."""
    return _read(os.path.join(base, "setup.py")), _read(os.path.join(base, "setup.cfg"))


def _messages(base: str, name: str, interfaces: Mapping[str, frozenset[str]],
              defined: Mapping[tuple[str, str], str | None]) -> dict[str, str]:
    """The message classes of the package's interfaces that one file of its own defines."""
    found: dict[str, str] = {}
    for (kind, stem), path in sorted(defined.items(), key=lambda item: item[0]):
        if path is None or stem not in interfaces.get(kind, ()):
            continue
        text = _read(os.path.join(base, path))
        if text is not None:
            found.update(definitions(name, kind, stem, text))
    return found


def _is_module(folders: list[str]) -> bool:
    """True for the folders of a Python package's ``__init__.py``: one at the package's root,
    or in its ``src`` folder (``package_dir={'': 'src'}``)."""
    if len(folders) == 2 and folders[0] == "src":
        folders = folders[1:]
    return len(folders) == 1 and folders[0].isidentifier() and folders[0] not in _NOT_MODULES


def _read(path: str) -> str | None:
    """The text of the file at ``path``, or None when it cannot be read (not a regular file,
    over the size limit: :func:`~pkgtool.model.files.read_bytes`)."""
    try:
        data = read_bytes(path)
    except OSError:
        return None
    return None if isinstance(data, int) else data.decode("utf-8", errors="replace")


def colcon_src(root: Path) -> Path | None:
    """The ``src`` folder of the colcon workspace ``root`` is in, if any."""
    for folder in root.parents:
        if folder.name == "src" and folder.is_dir():
            return folder
    return None


def workspace_index(roots: Iterable[Path], searched: Iterable[Path] = (),
                    files: Mapping[Path, Iterable[str]] | None = None,
                    known: Mapping[Path, WorkspacePackage] | None = None
                    ) -> dict[Path, WorkspacePackage]:
    """Every package of the workspace of the packages at ``roots`` (absolute) by folder: they
    and their neighbours.

    A colcon ``src`` folder inside one of the ``searched`` folders (those discovery already
    walked) is not walked again; ``files`` are the files of some packages, when the caller
    listed them already (see :func:`read_workspace_package`); ``known`` are packages the
    caller read already (the lint cache's, for packages whose files did not change).
    """
    from pkgtool.workspace import discover

    everything = set(roots)
    walked = tuple(searched)
    above = {root.parent: root for root in everything}  # siblings share their colcon src
    for source in {colcon_src(root) for root in above.values()} - {None}:
        assert source is not None
        if not any(source == top or top in source.parents for top in walked):
            everything.update(discover([str(source)], cwd=source).packages)
    listed, read = files or {}, known or {}
    return {root: read[root] if root in read else read_workspace_package(root, listed.get(root))
            for root in sorted(everything)}


def workspace_near(root: Path, index: Mapping[Path, WorkspacePackage]
                   ) -> Mapping[str, WorkspacePackage]:
    """The workspace the package at ``root`` sees, by name: a name several packages of the
    ``index`` share (two colcon workspaces linted in one run) is the package nearest ``root``
    (the deepest folder they share): its own workspace's, not another's. When several are
    equally near and differ (the name is in other workspaces only), only the name is known.
    """
    unique, shared = _names(index)
    if not shared:  # the usual case: every package sees the same (shared: do not change it)
        return unique
    near = dict(unique)
    for name, places in shared.items():
        depths = [(len(Path(os.path.commonpath((root, folder))).parts), package)
                  for folder, package in places]
        deepest = max(depth for depth, _ in depths)
        found = [package for depth, package in depths if depth == deepest]
        near[name] = found[0] if all(p == found[0] for p in found) else WorkspacePackage(name)
    return near


def context_for(root: Path, index: Mapping[Path, WorkspacePackage], distro: str,
                python: tuple[int, int] | None = None) -> Context:
    """The context of the package at ``root`` in a run whose workspace ``index`` it is in (and
    the Python its project declares, if any)."""
    return Context(distro, workspace_near(root, index), same_named(root, index), python)


def same_named(root: Path, index: Mapping[Path, WorkspacePackage]) -> tuple[str, ...]:
    """The other folders of the ``index`` that hold a package named as the one at ``root``
    that one colcon run crawls with it, relative to the workspace (the folder above ``src``):
    under the same colcon ``src`` folder (the outermost one), or one under ``ws/src`` and
    the other under ``ws`` in no ``src`` folder (colcon run in ``ws`` walks both). colcon
    refuses to build a workspace with two. Packages in no ``src`` folder have none otherwise:
    folders of one repository (a book's chapters) are often built one at a time."""
    own = index.get(root)
    places = _names(index)[1].get(own.name, []) if own is not None else []
    found = []
    for folder, _ in places:
        workspace = _shared_workspace(root, folder) if folder != root else None
        if workspace is not None:
            found.append(Path(os.path.relpath(folder, workspace)).as_posix())
    return tuple(sorted(found))


def _shared_workspace(first: Path, second: Path) -> Path | None:
    """The workspace folder (above its outermost ``src``) whose colcon run crawls both
    package folders, if any."""
    one, other = _outermost_src(first), _outermost_src(second)
    if one is not None and one == other:
        return one.parent
    source, alone = (one, second) if other is None else (other, first) if one is None \
        else (None, None)
    return source.parent if source is not None and alone is not None and \
        source.parent in alone.parents else None


def _outermost_src(root: Path) -> Path | None:
    """The outermost ``src`` folder above ``root``: colcon, run beside it, walks every folder
    below it, ``src`` folders of vendored workspaces included
    (``src/deps/driver/src/<package>``)."""
    return next((f for f in reversed(root.parents) if f.name == "src" and f.is_dir()), None)


@per_object(2)
def _names(index: Mapping[Path, WorkspacePackage]
           ) -> tuple[dict[str, WorkspacePackage], dict[str, list[tuple[Path, WorkspacePackage]]]]:
    """The packages of names one package holds, and the places of names several hold: worked
    out once per index, not once per package (a run looks every package's workspace up)."""
    names = Counter(package.name for package in index.values())
    unique: dict[str, WorkspacePackage] = {}
    shared: dict[str, list[tuple[Path, WorkspacePackage]]] = {}
    for folder, package in index.items():
        if names[package.name] == 1:
            unique[package.name] = package
        else:
            shared.setdefault(package.name, []).append((folder, package))
    return unique, shared
