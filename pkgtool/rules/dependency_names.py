"""What MAN021-MAN023 and DEP001 share: dependency keys that rosdep cannot resolve for the target.

A ``*_depend`` key resolves when it is a ROS package released for the target distribution, a
rosdep key, or a package of the same workspace. Keys that MAN018 already explains (pip and
ROS 1 names, build types, standard library modules), keys whose REP 149 condition is false
(or not understood) for the target, and ROS 1 (catkin) manifests are left out.
"""

from __future__ import annotations

import re

from pkgtool.knowledge import rosdistro
from pkgtool.knowledge.interfaces import packages_with
from pkgtool.knowledge.rosdep import NOT_PACKAGES, ROS1_PACKAGES, suggested_key
from pkgtool.knowledge.tables import DISTROS
from pkgtool.model.condition import applies
from pkgtool.model.description_files import described_packages
from pkgtool.model.installed import is_ament_python
from pkgtool.model.manifest import Dependency
from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.records import record
from pkgtool.lazy_regex import lazy_pattern

_KEY = lazy_pattern(r"[A-Za-z0-9][A-Za-z0-9._+-]*")
_NOT_CHECKED = frozenset({"group_depend", "conflict", "replace"})


@record
class Unknown:
    """A dependency nothing provides: distros that release it, else the nearest known name."""

    dependency: Dependency
    close: str | None
    elsewhere: tuple[str, ...]
    module: str | None = None
    """The imported module whose key ``close`` is, when the name misspells that module's."""

    def describe(self, distro: str) -> str:
        """`key` is not ... (the first half of a message)."""
        text = (f"`{self.dependency.name}` is not a ROS package released for {distro}, a rosdep "
                "key or a package of this workspace")
        if self.elsewhere:
            text += f" (it is released for {', '.join(self.elsewhere)})"
        return text


def checked_dependencies(package: Package) -> list[Dependency]:
    """The package's dependency keys that apply to the target distribution."""
    manifest = package.manifest
    if manifest is None or manifest.is_ros1:
        return []
    found = []
    for dependency in manifest.dependencies:
        name = dependency.name
        if (dependency.tag in _NOT_CHECKED or not _KEY.fullmatch(name or "")
                or not applies(dependency.condition, package.context.distro)):
            continue
        if name in NOT_PACKAGES or name in ROS1_PACKAGES or \
                key_instead(name, package.context.distro, dependency.tag) or \
                names_a_file(name, package.context.distro) or \
                interface_named(name, package.context.distro):
            continue  # MAN018's
        found.append(dependency)
    return found


_FILE_SUFFIXES = (".py", ".launch", ".xml", ".yaml", ".yml", ".json", ".msg", ".srv", ".action",
                  ".urdf", ".xacro", ".txt", ".cfg", ".rviz", ".sdf", ".world", ".sh", ".csv")
"""Suffixes of files a dependency tag sometimes names by mistake (a launch file, a parameter
file)."""


_KINDS = {"msg": "a message", "srv": "a service", "action": "an action"}


def interface_named(key: str, distro: str) -> tuple[str, str] | None:
    """(``a message``, its package) when ``key`` is the name of one interface of one known
    package (``PoseStamped``): package names are lower case (REP 144), so it is no package."""
    if not key[:1].isupper() or rosdistro.is_rosdep_key(key):
        return None
    found = {(_KINDS[kind], owner) for kind in _KINDS
             for owner in packages_with(kind, key, distro)}
    return found.pop() if len(found) == 1 else None


def names_a_file(name: str, distro: str) -> bool:
    """True for a declared name that is a file name (``robot.launch.py``, ``params.yaml``):
    no released package is named so, and the rosdep keys that are (``python3-ruamel.yaml``)
    are not."""
    return name.endswith(_FILE_SUFFIXES) and not rosdistro.is_rosdep_key(name) and \
        not rosdistro.is_released_package(name, distro)


_PYTHON3 = "python3-"


def key_instead(name: str, distro: str, tag: str) -> str | None:
    """The rosdep key to write for a declared ``name`` that is no key but a pip or ROS 1 name
    (:func:`~pkgtool.knowledge.rosdep.suggested_key`) or, but in a ``<doc_depend>`` (rosdoc2
    mocks the modules it names: ``lark``), the import name of a module rosdep's data knows
    (``dlib``: ``python3-dlib-pip``), ``python3-`` and a pip name whose key is named otherwise
    (``python3-pillow``: ``python3-pil``; not ``python3-dlib``, which a private rosdep source
    may define), or an Ubuntu package's name (``libyaml-cpp-dev``: ``yaml-cpp``), or an
    import's dotted path (``RPi.GPIO``, ``google.protobuf``: the key of its top-level
    module); None for a key, a released package or a name nothing knows."""
    known = suggested_key(name)
    if known is not None or tag == "doc_depend":
        return known
    if rosdistro.is_known_dependency(name, distro):
        return None
    prefixed = suggested_key(name[len(_PYTHON3):]) if name.startswith(_PYTHON3) and \
        not any(rosdistro.is_known_dependency(name, other) for other in DISTROS) else None
    if prefixed is not None and prefixed != name:
        return prefixed  # ``python3-`` before a pip name: ``python3-pillow`` is ``python3-pil``
    keys = rosdistro.keys_for_import(name, distro) or _dotted_keys(name, distro)
    return keys[0] if keys else rosdistro.key_of_ubuntu_package(name)


def _dotted_keys(name: str, distro: str) -> tuple[str, ...]:
    """The keys of the top-level module of an import's dotted path (``RPi.GPIO``) that name
    its last part too (``python-rpi.gpio-pip``): a namespace package's top (``google``) has
    keys of other distributions than ``google.generativeai``."""
    parts = name.split(".")
    if len(parts) < 2 or not all(part.isidentifier() for part in parts):
        return ()
    last = parts[-1].lower()
    return tuple(key for key in rosdistro.keys_for_import(parts[0], distro)
                 if last in key.lower())


def is_local(package: Package, name: str) -> bool:
    """True when ``name`` is the package itself or a package of its workspace (looked up, not
    copied: a copy of the workspace's names per package grows a run with the square of its
    size), or names a git submodule of its repository that is not checked out."""
    return name == package.name or name in package.context.workspace or \
        name in package.submodules


def neighbours(package: Package) -> frozenset[str]:
    """The other packages of its workspace: the names a misspelt key may have meant (the
    package itself is MAN014's, never a near miss)."""
    return frozenset(package.context.workspace) - {package.name}


_AFFIXES = lazy_pattern(r"^(python3?-)|(-pip-shim|-pip|-python3?)$")


def names_module(key: str, module: str) -> bool:
    """True when ``key`` is written for the Python module ``module``: ``python3-torch``,
    ``python3-torch-pip-shim`` and ``torch`` for ``torch`` (``-`` and ``_`` alike)."""
    bare = _AFFIXES.sub("", _AFFIXES.sub("", key.lower()))
    return bare.replace("-", "_") == module.lower()


def _same_module(package: Package, key: str, close: str) -> bool:
    """False when ``key`` is written for a module the package's code imports and ``close`` is
    not (``python3-pcl`` for ``import pcl`` is no misspelt ``python3-pil``: a key of its own
    that rosdep lacks), or is a package its launch, robot description, world or RViz files
    name and ``close`` is not; ``cv-bridge`` and ``cv_bridge`` both name ``cv_bridge``."""
    if any(names_module(key, imported.top_level) and not names_module(close, imported.top_level)
           for module in package.modules for imported in module.imports):
        return False
    for named in (launched_packages, described_packages):
        if key in named(package) and close not in named(package):
            return False
    return True


def _declared_beside(dependency: Dependency, close: str, package: Package) -> bool:
    """True when package.xml already declares ``close`` for what ``dependency`` declares (the
    same tag, or a ``<depend>`` on either side) and ``key`` is more than one slip away from
    it: the key names another package, built from source (``mir_description`` beside
    ``ur_description``), not a misspelling whose fix would declare ``close`` twice."""
    manifest = package.manifest
    if rosdistro.typo_distance(dependency.name, close, 1) <= 1:
        return False  # one slip (`sensor_msg` beside `sensor_msgs`): a misspelt duplicate
    tags = {dependency.tag, "depend"}
    return manifest is not None and any(
        other.name == close and (other.tag in tags or dependency.tag == "depend")
        for other in manifest.dependencies)


@per_package
def launched_packages(package: Package) -> frozenset[str]:
    """The packages the package's launch files start nodes of or look up (a declared key a
    launch file names, ``Node(package='navigation')``, is the package it means, built
    elsewhere, not a misspelling of a released one)."""
    return frozenset({node.package for launch in package.launch_files for node in launch.nodes
                      if node.package} |
                     {ref.package for launch in package.launch_files for ref in launch.packages})


@per_package
def unknown_dependencies(package: Package) -> list[Unknown]:
    """Dependencies of ``package`` that nothing provides for its target distribution, each
    with the known name it is spelled like (none when the key is written for an imported
    module that name does not provide)."""
    distro = package.context.distro
    stdlib = rosdistro.stdlib_modules(distro)
    found = []
    for dependency in checked_dependencies(package):
        name = dependency.name
        if is_local(package, name) or rosdistro.is_known_dependency(name, distro) \
                or name in stdlib:
            continue
        elsewhere = tuple(d for d in DISTROS if rosdistro.is_released_package(name, d))
        close = [] if elsewhere else rosdistro.close_names(name, distro, extra=neighbours(package))
        meant = close[0] if close and _same_module(package, name, close[0]) and \
            not _declared_beside(dependency, close[0], package) and \
            not cmake_finds(package, name) and \
            not _of_a_family(package, name, close[0]) and \
            not _version_of(name, close[0]) and \
            len(rosdistro.numbered_variants(name, distro)) < 2 else None
        module = _misspelt_import(package, name) if meant is None and not elsewhere else None
        found.append(Unknown(dependency, module[1] if module else meant, elsewhere,
                             module[0] if module else None))
    return found


def _misspelt_import(package: Package, name: str) -> tuple[str, str] | None:
    """(module, its rosdep key) when ``name`` is a typo of the name of a module the package
    imports that no declared key provides (``simpole_pid`` for ``import simple_pid``)."""
    distro = package.context.distro
    declared = {d.name for d in package.manifest.dependencies} if package.manifest else set()
    for module in package.modules:
        for imported in module.imports:
            top = imported.top_level
            keys = rosdistro.keys_for_import(top, distro) if top and top != name else ()
            if keys and not declared & set(keys) and \
                    rosdistro.is_typo(name.replace("-", "_").lower(), top.lower()):
                return top, keys[0]
    return None


_PARTS = lazy_pattern(r"[-_.]")


def cmake_finds(package: Package, name: str) -> bool:
    """True when the package's CMakeLists.txt calls ``find_package(name ...)``, or lists the
    name among a ``find_package(catkin COMPONENTS ...)``'s: a package built with it (from
    source beside it, when no release has that name), whatever its name looks like. Not in
    an ament_python package, whose build never runs a CMakeLists.txt."""
    cmake = package.texts.get("CMakeLists.txt")
    if cmake is None or is_ament_python(package):
        return False  # an ament_python build never runs a CMakeLists.txt left beside it
    return any(_finds(found, name) for found in _FIND_PACKAGE.finditer(cmake))


_FIND_PACKAGE = lazy_pattern(r"(?i:find_package)\s*\(\s*([\w.+-]+)([^)]*)\)")
"""A ``find_package(Name ...)`` call: the name, and the rest (``REQUIRED COMPONENTS a b``)."""


def _finds(found: re.Match[str], name: str) -> bool:
    """True when the ``find_package`` call ``found`` finds ``name``, or lists it among its
    components."""
    words = found.group(2).split()
    components = words[words.index("COMPONENTS") + 1:] if "COMPONENTS" in words else []
    return found.group(1) == name or name in components


def _version_of(key: str, close: str) -> bool:
    """True when ``key`` is ``close`` with a version number at its end (``gz-plugin3`` for
    ``gz-plugin``): a library's versions are named so, never a typo. The other way round
    (``rviz`` for ``rviz2``, ROS 1's name) stays a near miss."""
    bare = key.rstrip("0123456789")
    return bare != key and bare == close


def _of_a_family(package: Package, key: str, close: str) -> bool:
    """True when a part of ``key`` that differs from ``close`` (four characters or more)
    starts a part of another dependency that nothing provides either: ``libqnn-dev`` beside
    ``libqnn1`` is a vendor's family of keys rosdep lacks, not a misspelt ``libann-dev``."""
    changed = {part for part in _PARTS.split(key) if len(part) >= 4} - set(_PARTS.split(close))
    if not changed or package.manifest is None:
        return False
    distro = package.context.distro
    return any(other.name != key and any(part.startswith(tuple(changed))
                                         for part in _PARTS.split(other.name)) and
               not rosdistro.is_known_dependency(other.name, distro) and
               not is_local(package, other.name) and
               not _same_slip(other.name, key, close, distro)
               for other in package.manifest.dependencies if other.name)


def _same_slip(other: str, key: str, close: str, distro: str) -> bool:
    """True when ``other`` with the parts ``key`` misspells written as ``close`` has them is
    a known dependency: the same slip made twice (``join_state_publisher`` and
    ``join_state_publisher_gui``), not a family of keys."""
    ours, theirs = _PARTS.split(key), _PARTS.split(close)
    if len(ours) != len(theirs):
        return False
    fixed = dict(zip(ours, theirs))
    mended = other
    for part in _PARTS.split(other):
        if part in fixed and fixed[part] != part:
            mended = re.sub(rf"(?<![^\W_]){re.escape(part)}(?![^\W_])", fixed[part], mended)
    return mended != other and rosdistro.is_known_dependency(mended, distro)
