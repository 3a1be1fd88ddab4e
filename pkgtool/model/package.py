"""One immutable :class:`Package` built from a folder, reading each file once."""

from __future__ import annotations

import re
from collections.abc import Callable
from pathlib import Path

from pkgtool.model.cmake_install import installed_sources
from pkgtool.model.cmake_text import with_included
from pkgtool.model.context import Context, interface_file
from pkgtool.model.files import TextFile, list_files, read_text
from pkgtool.model.launch import (LAUNCH_SUFFIXES, LAUNCH_YAML, LaunchFile, hidden,
                                  in_launch_folder, is_launch_file, is_launch_test, is_template,
                                  kept_aside, nested_packages, named_like_launch_only,
                                  parse_launch, python_folders, runs_as_launch_file)
from pkgtool.model.launch_reader import yaml_problem
from pkgtool.model.manifest import Manifest, parse_manifest, read_past_late_declaration
from pkgtool.model.modules import PythonModule, parse_module
from pkgtool.model.python_visitor import forget_trees
from pkgtool.model.setup_cfg import SetupCfg, parse_setup_cfg
from pkgtool.model.setup_py import SetupPy, parse_setup_py
from pkgtool.model.span import ParseProblem
from pkgtool.model.submodules import (GitIgnore, gitignore_patterns, ignores_above,
                                      unfetched_names, unfetched_submodules)
from pkgtool.records import field, record
from pkgtool.lazy_regex import lazy_pattern

_PY_SUPPRESSION = lazy_pattern(r"#\s*pkgtool:\s*ignore(?:\[([A-Za-z0-9_,\s-]*)\])?")
_XML_SUPPRESSION = lazy_pattern(r"<!--\s*pkgtool:\s*ignore\b([A-Za-z0-9_,\s-]*)-->")
_FLAKE8_NOQA = lazy_pattern(r"#\s*noqa\s*:\s*([A-Z]+[0-9]+(?:[\s,]+[A-Z]+[0-9]+)*)")
_FLAKE8_TWINS = {"F821": "PYC001"}
"""flake8's codes whose ``# noqa`` silences the pkgtool rule that checks the same (an
undefined name a script gets from outside, as pyflakes is told)."""


@record
class Package:
    """A package folder: its files and everything parsed from them.

    ``files`` lists every file (POSIX, relative to ``root``). ``problems`` holds files that could
    not be read or parsed. ``suppressions`` maps (path, line) to the rule selectors silenced
    there as written (codes, names, ``ALL``), an empty set for a bare ``pkgtool: ignore``.
    ``context`` is the target distribution and the workspace.
    """

    root: Path
    files: tuple[str, ...]
    manifest: Manifest | None
    setup_py: SetupPy | None
    setup_cfg: SetupCfg | None
    modules: tuple[PythonModule, ...]
    launch_files: tuple[LaunchFile, ...]
    problems: tuple[ParseProblem, ...]
    suppressions: dict[tuple[str, int], frozenset[str]] = field(default_factory=dict)
    texts: dict[str, str] = field(default_factory=dict, repr=False)
    file_set: frozenset[str] = field(default=frozenset(), repr=False)
    context: Context = field(default_factory=Context, repr=False)
    unfetched: frozenset[str] = frozenset()
    """Folders of git submodules inside the package that are not checked out."""
    ignores: tuple[GitIgnore, ...] = ()
    """The patterns of the ``.gitignore`` files of the package and of the folders above it
    (see :mod:`pkgtool.model.submodules`)."""
    submodules: frozenset[str] = frozenset()
    """The folder names of the repository's git submodules that are not checked out (each
    may hold a package of that name once fetched)."""

    @property
    def name(self) -> str:
        """The package.xml name, else setup.py's, else the folder name."""
        if self.manifest and self.manifest.name and self.manifest.name.value:
            return self.manifest.name.value
        if self.setup_py and self.setup_py.name and isinstance(self.setup_py.name.value, str):
            return self.setup_py.name.value
        return self.root.name

    def module(self, path: str) -> PythonModule | None:
        """The parsed Python module at ``path``, if any."""
        return next((m for m in self.modules if m.path == path), None)

    def has_file(self, path: str) -> bool:
        """True when ``path`` (package-relative POSIX) is a file of the package."""
        return path in self.file_set

    def has_folder(self, path: str) -> bool:
        """True when ``path`` is a folder of the package: it holds files (git keeps no
        empty folder)."""
        prefix = path.rstrip("/") + "/"
        return any(f.startswith(prefix) for f in self.files)


def _ignores(root: Path, texts: dict[str, str]) -> tuple[GitIgnore, ...]:
    """The ``.gitignore`` patterns of the package's own files and of the folders above it."""
    own = tuple(GitIgnore(path.rpartition("/")[0], "", pattern) for path, text in texts.items()
                if path.rpartition("/")[2] == ".gitignore" for pattern in gitignore_patterns(text))
    return own + ignores_above(root)


def _suppressions(path: str, text: str) -> dict[tuple[str, int], frozenset[str]]:
    found: dict[tuple[str, int], frozenset[str]] = {}
    python = not path.endswith(".xml")
    twins = python and any(code in text for code in _FLAKE8_TWINS)
    if "pkgtool" not in text and not twins:  # what the patterns need (most files): no search
        return found
    pattern = _PY_SUPPRESSION if python else _XML_SUPPRESSION
    for number, line in enumerate(text.splitlines(), 1):
        match = pattern.search(line)
        noqa = _FLAKE8_NOQA.search(line) if twins and "noqa" in line else None
        twin = frozenset(_FLAKE8_TWINS[c] for c in re.split(r"[\s,]+", noqa.group(1))
                         if c in _FLAKE8_TWINS) if noqa else frozenset()
        if not match:
            if twin:
                found[(path, number)] = twin
            continue
        codes = frozenset(c for c in re.split(r"[\s,]+", match.group(1) or "") if c)
        codes = codes | twin if codes else codes  # an empty set already silences every rule
        found[(path, number)] = codes
        if path.endswith(".xml") and line.strip().startswith("<!--"):
            found[(path, number + 1)] = frozenset(codes)  # a comment line covers the next line
    return found


def load_package(root: Path, context: Context | None = None, *,
                 surroundings: Path | None = None) -> Package:
    """Read the package at ``root``; never raises for bad content, only records problems.

    ``context`` defaults to the default distribution and a workspace of this package alone.
    ``surroundings``: the folder whose repository (``.gitignore`` files and submodules above
    it) the package is in, when ``root`` is a copy of it (``lint --diff``); else ``root``.
    The syntax trees (and their facts) kept for the package loaded before are let go.
    """
    forget_trees()
    files = list_files(root)
    problems: list[ParseProblem] = []
    texts: dict[str, str] = {}

    unreadable: set[str] = set()

    def text_of(relpath: str, quiet: bool = False) -> str | None:
        """The file's text, read once; an unreadable file is recorded once (unless ``quiet``:
        a file no build or run tool reads as text, such as a README)."""
        if relpath in texts or relpath in unreadable:
            return texts.get(relpath)
        result = read_text(root, relpath)
        if isinstance(result, ParseProblem):
            if not quiet:
                problems.append(result)
            unreadable.add(relpath)
            return None
        assert isinstance(result, TextFile)
        texts[relpath] = result.text
        return result.text

    manifest = _parsed(problems, "package.xml", text_of, parse_manifest, files)
    if manifest is None and texts.get("package.xml"):  # SYN001 says why; the rest still runs
        manifest = read_past_late_declaration("package.xml", texts["package.xml"])
    setup_py = _parsed(problems, "setup.py", text_of,
                       lambda p, t: parse_setup_py(p, t, files), files)
    setup_cfg = _parsed(problems, "setup.cfg", text_of, parse_setup_cfg, files)
    modules: list[PythonModule] = []
    launches: list[LaunchFile] = []
    folders, nested = python_folders(files), nested_packages(files)
    shared = _shared_sources(setup_py) | _cmake_shared(files, text_of)
    ros1 = getattr(manifest, "is_ros1", False)  # roslaunch files: not ROS 2's to check
    own_name = manifest.name.value if manifest is not None and manifest.name else root.name
    for relpath in files:
        if not ros1 and ((is_launch_file(relpath, folders, nested, own_name) or
                          _installed_as_launch_file(relpath, shared)) and
                         not is_launch_test(relpath, text_of(relpath)) and
                         not named_like_launch_only(relpath, text_of(relpath)) or
                         _launch_by_content(relpath, text_of, nested, shared, folders)):
            text = text_of(relpath)
            if text is not None:
                launch = parse_launch(relpath, text)
                launches.append(launch)
                if launch.problem:
                    problems.append(launch.problem)
        elif relpath.endswith((".yaml", ".yml")):  # parameter files: only their syntax
            if is_test_yaml(relpath):
                continue  # test data, deliberately broken at times: not package files
            text = text_of(relpath)
            if text is not None and "{%" not in text and \
                    not _OPENCV_STORAGE.match(text):  # a Jinja template, OpenCV's own
                found = yaml_problem(relpath, text)
                if isinstance(found, ParseProblem):
                    problems.append(found)
        elif relpath.rpartition("/")[2] == ".gitignore":
            text_of(relpath, quiet=True)  # modules generated at build time: git reads bytes
        elif is_interface_definition(relpath):
            text_of(relpath)  # .msg, .srv, .action files
        elif relpath.endswith(".py") and relpath != "setup.py":
            text = text_of(relpath)
            if text is not None and (not _other_language(text) or _collected(relpath)):
                module = parse_module(relpath, text)
                modules.append(module)
                if module.syntax_error and not is_test_data(relpath):
                    problems.append(module.syntax_error)
    readers = [text for launch in launches if launch.kind == "python" and
               ".read" in (text := texts.get(launch.path, ""))]
    for relpath in files:  # xacro files a launch file may read raw (LCH025 looks inside)
        if relpath.endswith(".xacro") and \
                any(relpath.rpartition("/")[2] in text for text in readers):
            text_of(relpath, quiet=True)
    for other in ("README.md", "README.rst", "README.txt", "README"):  # `ros2 run ...`
        if other in files:
            text_of(other, quiet=True)  # documentation: in any encoding, nothing reads it
    for other in ("pytest.ini", ".pytest.ini", "pyproject.toml", "tox.ini",  # pytest's settings
                  "CMakeLists.txt"):  # the interfaces it generates
        if other in files:
            text_of(other)
    if "CMakeLists.txt" in texts:  # the CMake files it includes, read as it reads them
        with_included(texts["CMakeLists.txt"], lambda path: text_of(path) if path in files
                      else None)
    suppressions: dict[tuple[str, int], frozenset[str]] = {}
    for relpath, text in texts.items():
        suppressions.update(_suppressions(relpath, text))
    place = surroundings or root
    return Package(root, files, manifest, setup_py, setup_cfg, tuple(modules), tuple(launches),
                   tuple(problems), suppressions, texts, frozenset(files), context or Context(),
                   unfetched_submodules(place, files), _ignores(place, texts),
                   unfetched_names(place))


_LAUNCH_XML = lazy_pattern(r"\s*(?:<\?xml[^>]*\?>\s*)?(?:<!--.*?-->\s*)*<launch[\s>/]", re.S)
_ROS2_XML = lazy_pattern(r"<node\b[^>]*\sexec\s*=|\$\(find-pkg-(?:share|prefix)\s|<let\s|"
                         r"<set_parameter\s|<executable\s")
"""What only ROS 2's XML launch format has (a ``<node exec=...>``, ``$(find-pkg-share x)``):
a ``.launch`` file holding it is ROS 2's, not a roslaunch file."""
_OPENCV_STORAGE = lazy_pattern(r"\ufeff?%YAML(?::|[ \t]+1\.0\b)")
"""How OpenCV's ``FileStorage`` files start (``%YAML:1.0``, or ``%YAML 1.0``: a version no
YAML parser of ROS takes): a format of OpenCV's that YAML parsers refuse, read by
``cv2.FileStorage`` (ORB-SLAM's camera settings), never by ROS."""


def is_test_material(relpath: str) -> bool:
    """A file in a ``test`` or ``tests`` folder (also one inside the Python package)."""
    return any(part in ("test", "tests") for part in relpath.split("/")[:-1])


TEST_DATA_FOLDERS = frozenset({"test", "tests", "testdata", "test_data", "test_files",
                               "test_resources", "test_fixtures"})


def is_test_yaml(relpath: str) -> bool:
    """A YAML file of test material or test data (``test_data/broken.yaml``), which tests of
    error handling keep broken on purpose: never a parameter file the package runs with."""
    return relpath.endswith((".yaml", ".yml")) and \
        any(part in TEST_DATA_FOLDERS for part in relpath.split("/")[:-1])


def is_test_data(relpath: str) -> bool:
    """A Python file under ``test/`` that pytest does not collect (a fixture, sample input)."""
    name = relpath.rsplit("/", 1)[-1]
    collected = name.startswith("test_") or name.endswith("_test.py") or name == "conftest.py"
    return is_test_material(relpath) and not collected


def _collected(relpath: str) -> bool:
    """A test module pytest collects (``test/test_x.py``): parsed as Python whatever its
    ``#!`` line says, as pytest imports it (a bash script named so fails the test run)."""
    return is_test_material(relpath) and not is_test_data(relpath)


def is_interface_definition(relpath: str) -> bool:
    """A ``.msg``, ``.srv`` or ``.action`` file rosidl would generate an interface from (one
    under the ``msg``, ``srv`` or ``action`` folder)."""
    return relpath.endswith((".msg", ".srv", ".action")) and interface_file(relpath) is not None


def _other_language(text: str) -> bool:
    """True for a file whose ``#!`` line runs something other than Python (a bash script
    named ``start.py``): no module."""
    first = text.split("\n", 1)[0]
    return first.startswith("#!") and "python" not in first


def _installed_as_launch_file(relpath: str, shared: frozenset[str]) -> bool:
    """A file named like a launch file that data_files copies into ``share/`` wherever it
    lies (``example/example/chassis/line_tracking.launch.py``): ``ros2 launch`` runs it."""
    return relpath in shared and relpath.endswith(LAUNCH_SUFFIXES) and not is_template(relpath)


def _cmake_shared(files: tuple[str, ...], text_of: Callable[[str], str | None]
                  ) -> frozenset[str]:
    """The Python files of ``launch`` folders a CMakeLists.txt installs (``install(DIRECTORY
    launch ...)``): ``ros2 launch`` runs them whatever their names (``launch_mavros.py``)."""
    text = text_of("CMakeLists.txt") if "CMakeLists.txt" in files else None
    installed = installed_sources(text, files) if text else None
    if not installed:
        return frozenset()
    return frozenset(f for f in files if f.endswith(".py") and "launch" in f.split("/")[:-1]
                     and not kept_aside(f)
                     and (f in installed or any(f.startswith(f"{i}/") for i in installed)))


def _shared_sources(setup_py: SetupPy | ParseProblem | None) -> frozenset[str]:
    """The files data_files copies into ``share/``, as far as it was evaluated."""
    if not isinstance(setup_py, SetupPy):
        return frozenset()
    return frozenset(match for entry in setup_py.data_files or ()
                     if entry.destination.lstrip("/").startswith("share/")
                     and not entry.sources_is_text
                     for source in entry.sources for match in source.matches)


def _launch_by_content(relpath: str, text_of: Callable[[str], str | None],
                       nested: frozenset[str], shared: frozenset[str],
                       folders: frozenset[str] = frozenset()) -> bool:
    """A file in a ``launch`` folder (not a template) that is a launch file by its content,
    whatever its name: XML or YAML whose root is ``launch`` (a ``.launch`` file too, in ROS
    2's XML format), Python defining
    ``generate_launch_description`` that data_files installs in ``share/`` (``lab5-launch.py``;
    not a module beside the launch files, nor a copy kept aside: ``launch_old.py``) or that
    lies right in the package's ``launch/`` folder (``launch/slam.py``, installed or not).

    ``ros2 launch`` accepts any file name; only files in a folder named ``launch`` are read
    for this, so URDF, RViz and parameter files elsewhere cost nothing.
    """
    if not relpath.endswith((".xml", ".yaml", ".yml", ".py", ".launch")) or \
            not in_launch_folder(relpath, nested) or hidden(relpath):
        return False
    text = text_of(relpath)
    if text is None:
        return False
    if relpath.endswith(".py"):
        loose = relpath.split("/")[0] == "launch" and relpath.count("/") == 1 and \
            "launch" not in folders and not kept_aside(relpath)
        return (relpath in shared or loose) and runs_as_launch_file(relpath, text)
    if relpath.endswith(".xml"):
        return _LAUNCH_XML.match(text) is not None
    if relpath.endswith(".launch"):  # ROS 1's suffix, used by ROS 2 XML files at times
        return _LAUNCH_XML.match(text) is not None and _ROS2_XML.search(text) is not None
    return LAUNCH_YAML.search(text) is not None


def _parsed(problems, relpath, text_of, parse, files):  # type: ignore[no-untyped-def]
    """Parse one well-known file if present; a parse failure is recorded as a problem."""
    if relpath not in files:
        return None
    text = text_of(relpath)
    if text is None:
        return None
    result = parse(relpath, text)
    if isinstance(result, ParseProblem):
        problems.append(result)
        return None
    return result
