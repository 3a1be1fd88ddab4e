"""Launch files (Python, XML, YAML) read statically: what packages, executables, files they use."""

from __future__ import annotations

import re

from pkgtool.model.modules import PythonModule
from pkgtool.model.span import ParseProblem, Span
from pkgtool.records import record
from pkgtool.lazy_regex import lazy_pattern

LAUNCH_SUFFIXES = (".launch.py", "_launch.py", ".launch.xml", "_launch.xml", ".launch.yaml",
                   "_launch.yaml", ".launch.yml", "_launch.yml")
LAUNCH_FILE_NAME = lazy_pattern(r"(?:^|[._-])launch\.(?:py|xml|ya?ml)$")
"""The names ROS 2 gives launch files (``bringup_launch.py``, ``robot.launch.xml``): never
an executable's."""


@record
class FileRef:
    """A file the launch file reads from a package's share folder, e.g. ('config', 'p.yaml').

    ``package`` is the package whose share folder is used (None if unknown); ``parts`` are the
    static path components after the share folder. ``checked``: the file asks whether this
    path (or a folder above it) exists (``os.path.exists``), or asks so of a path it cannot
    work out: the file may be missing on purpose.
    """

    package: str | None
    parts: tuple[str, ...]
    span: Span
    checked: bool = False


@record
class NodeRef:
    """A node the launch file starts: ``Node(package=, executable=)`` or ``<node pkg= exec=>``.

    A field is None when it was absent or not a static string (substitutions, variables that
    do not resolve). ``action`` is the action's class or tag (``Node``, ``node``);
    ``arguments`` names the keywords or attributes given (``**`` for a ``**kwargs``, ``*`` for
    ``*args``); ``package_span`` and ``executable_span`` are where those two values are
    written, when known. ``optional`` marks a node started only after the launch file checked
    that its package is installed (``if 'x' in get_packages_with_prefixes():``).
    ``parameter_files`` are the share files given as its parameters (``parameters=[path]``,
    ``<param from=...>``), where the path is static. ``other_distros`` marks a node inside a
    branch of a test on the ROS distribution (``if os.environ['ROS_DISTRO'] < 'foxy':``): it
    may be written for distributions other than the target. ``name`` and ``namespace`` are
    the static node name (``name=``, ``<node name=>``, a ``__node:=`` remapping) and
    namespace; ``name_unknown`` marks a name given in a way not read statically (a
    substitution, remappings or arguments that are not literals). ``other_parameters``
    marks ``parameters`` holding something besides dicts and static share files (a launch
    argument): any file may reach the node through it. ``parameters_not_list`` is where a Python
    ``parameters=`` gives a value that is certainly no list (a path, a string, a tuple, a
    dict), None otherwise. ``unused`` marks a Python action that is never started: its call
    (or one it is part of) is the whole value of an assignment to a local name its function
    never reads (``rviz = Node(...)`` left out of the LaunchDescription). The call itself
    still runs when the file does. ``remappings_not_pairs`` is where a Python ``remappings=``
    certainly is no list of pairs (:mod:`pkgtool.model.launch_remaps`), None otherwise.
    ``inline_parameters`` are the names a Python ``parameters=[{...}]`` dict display sets
    with literal keys (nested dicts give dotted names) and its literal ``-p name:=value``
    arguments, or an XML node's ``<param name= value=>`` children, each where its key is
    written, with the source of its value when that is a literal (``1.0``, ``'fast'``; for
    XML, the value launch makes of the text; for ``-p``, the value rcl reads), else None.
    ``output`` is the static ``output=`` (``'screen'``), when given; ``not_text`` is where a
    Python ``arguments=``, ``ros_arguments=`` or ``remappings=`` display holds a number or
    bool literal (launch takes text and substitutions only), with the keyword;
    ``joined_words`` is (where, keyword, text) of the first item of a Python ``arguments=`` or
    ``ros_arguments=`` list that holds an option and its value, or a word and an option, in one
    string (``'-r in:=/image_raw'``, ``'serial --dev /dev/ttyACM0'``); ``text_not_list`` is
    where a Python ``arguments=`` or ``ros_arguments=`` is certainly one
    string instead of a list (launch iterates it: one argument per character, or a
    TypeError), with the keyword. ``remapped``
    are the names a Python ``remappings=[(from, to), ...]`` display remaps, when written as
    literals, each where it is written. ``package_written`` is an XML node's ``pkg`` as
    written when it is not static (``$(find-pkg-share x)``); ``params_without_source`` are
    its ``<param>`` children with neither ``name`` nor ``from``, each with its attributes
    (``<param file=...>``, ROS 1's rosparam habit). ``always_started`` marks a node the
    launch file starts every time, in no namespace but its own (:mod:`launch_started`; an XML
    node directly under ``<launch>`` with no ``if``/``unless``).
    """

    package: str | None
    executable: str | None
    span: Span
    action: str = ""
    arguments: tuple[str, ...] = ()
    package_span: Span | None = None
    executable_span: Span | None = None
    optional: bool = False
    parameter_files: tuple[FileRef, ...] = ()
    other_distros: bool = False
    name: str | None = None
    namespace: str | None = None
    name_unknown: bool = False
    other_parameters: bool = False
    parameters_not_list: Span | None = None
    unused: bool = False
    remappings_not_pairs: Span | None = None
    inline_parameters: tuple[tuple[str, Span, str | None], ...] = ()
    text_not_list: tuple[Span, str] | None = None
    joined_words: tuple[Span, str, str] | None = None
    output: str | None = None
    not_text: tuple[Span, str] | None = None
    remapped: tuple[tuple[str, Span], ...] = ()
    package_written: str | None = None
    params_without_source: tuple[tuple[Span, tuple[str, ...]], ...] = ()
    always_started: bool = False

    @property
    def composable(self) -> bool:
        """A component a container loads (``ComposableNode``, ``<composable_node>``): launch_ros
        reads its parameter files itself instead of passing them to rcl."""
        return self.action in COMPOSABLE_ACTIONS


COMPOSABLE_ACTIONS = frozenset({"ComposableNode", "composable_node"})
"""The actions (Python classes, XML and YAML tags) of components loaded into a container."""


COMMAND_PACKAGES = {"xacro": "xacro"}
"""Executables a launch file runs through a command substitution (``Command(['xacro ',
...])``, ``$(command 'xacro ...')``), by the package that installs each."""
PROCESS_PACKAGES = {**COMMAND_PACKAGES, "rviz2": "rviz2"}
"""Programs of ROS packages a launch file starts as processes (``ExecuteProcess(cmd=['rviz2',
'-d', config])``), by the package that installs each."""
KEYED_TERMINALS = ("xterm", "gnome-terminal", "konsole", "terminator", "tmux")
"""Terminals that are rosdep keys of their own name."""
TERMINALS = (*KEYED_TERMINALS, "screen", "x-terminal-emulator", "kitty", "alacritty", "tilix")
"""Programs that give what they run a terminal (``prefix='xterm -e'``)."""
PREFIX_PACKAGES = {name: name for name in (*KEYED_TERMINALS, "valgrind")}
"""Programs a launch file runs a node inside (``prefix='xterm -e'``, ``launch-prefix=``), by
the rosdep key that installs each."""


@record
class PackageRef:
    """A package named by get_package_share_directory, FindPackageShare, $(find-pkg-share),
    ExecutableInPackage or $(exec-in-pkg), or whose executable a command substitution runs
    (:data:`COMMAND_PACKAGES`).

    ``optional`` as for :class:`NodeRef`; ``unused`` marks a substitution
    (``FindPackageShare``) inside an action that is never started (:class:`NodeRef`): it is
    never performed.
    """

    package: str
    span: Span
    optional: bool = False
    unused: bool = False


@record
class LaunchFile:
    """A launch file. ``python`` is the parsed module for Python launch files (its imports).
    ``paths`` are the file paths an XML or YAML launch file names with no substitution (a
    parameter file, ``<param from=>``; an included launch file, ``<include file=>``), each
    where it is written."""

    path: str
    kind: str
    nodes: tuple[NodeRef, ...]
    packages: tuple[PackageRef, ...]
    files: tuple[FileRef, ...]
    python: PythonModule | None = None
    problem: ParseProblem | None = None
    paths: tuple[tuple[str, Span], ...] = ()


EXISTENCE_CHECKS = frozenset({"exists", "isfile", "is_file", "isdir", "is_dir", "lexists"})
"""``os.path.exists``, ``os.path.isfile``, ``Path.is_dir()``...: calls asking whether a path
exists."""
NOT_LAUNCH_FOLDERS = frozenset({"test", "tests", "example", "examples", "sample", "samples",
                                "doc", "docs"})
"""Top-level folders of test and documentation material: a launch-like name there is not enough."""
TEMPLATE_FOLDERS = frozenset({"template", "templates"})
"""Top-level folders of templates a script copies into a package it generates (a new robot's
configuration): their launch files are that package's, never this one's."""


def is_template(path: str) -> bool:
    """True for a package file under a top-level ``templates/`` (or ``template/``) folder."""
    return path.split("/", 1)[0] in TEMPLATE_FOLDERS and "/" in path


KEPT_ASIDE = lazy_pattern(r"(?i)(?:^|[_.\- (\[])(?:old|orig|original|copy|backup|backups|bak|"
                          r"unused|deprecated|discarded|obsolete|legacy)(?:[_.\- )\]]|\d|$)")
"""A copy kept aside by its name (``flow.launch_original.py``, ``ctrl_launch-Copy1.py``,
``controller_launch(discarded).py``) or its folder's (``backup/``, ``old_launch/``)."""


def kept_aside(path: str) -> bool:
    """True for a file named as a copy kept aside, or kept in a folder so named, and for a
    hidden file (:func:`hidden`): nobody runs it, and a whole installed folder carries it
    along."""
    name = path.rpartition("/")[2]
    return in_folder_kept_aside(path) or hidden(path) or \
        KEPT_ASIDE.search(name.rsplit(".", 1)[0]) is not None


def hidden(path: str) -> bool:
    """True for a hidden file (``.old_launch.py``): an editor's or a user's copy, which the
    globs of data_files never match."""
    return path.rpartition("/")[2].startswith(".")


def in_folder_kept_aside(path: str) -> bool:
    """True for a file below a folder named as kept aside (``backup/``, ``old_launch/``)."""
    return any(KEPT_ASIDE.search(part) for part in path.split("/")[:-1])


def is_launch_file(path: str, python_folders: frozenset[str] = frozenset(),
                   nested: frozenset[str] = frozenset(), package: str = "") -> bool:
    """True for a file with a launch file name that the package keeps as a launch file.

    Files under ``templates/`` never are (:func:`is_template`). Anything named like a launch
    file in a ``launch`` folder is one. Elsewhere the name is not enough: a module inside a
    Python package folder (``python_folders``: folders holding an ``__init__.py``; it is
    installed as code), a test (``test_*``) and files under ``test/``, ``examples/``,
    ``samples/`` or ``doc/`` (run by pytest, by ``main()`` with a ``LaunchService``, or by
    path from that folder, next to its data) are not launch files, unless that folder is
    the Python package named like the ``package`` (a package called ``example``). Nor are
    those below a ``nested`` folder (:func:`nested_packages`): they are that package's. Nor
    are those of a folder kept aside (``backup/``, ``old/``: :func:`kept_aside`), nor
    :func:`hidden` files.
    """
    folder, _, name = path.rpartition("/")
    if not name.endswith(LAUNCH_SUFFIXES) or hidden(path) or is_template(path) or \
            below(path, nested) or in_folder_kept_aside(path):
        return False
    parts = folder.split("/") if folder else []
    if "launch" in parts:
        return True
    return not (name.startswith("test_") or folder in python_folders or parts and (
        parts[0] in NOT_LAUNCH_FOLDERS and not (parts[0] == package and
                                                parts[0] in python_folders)))


LAUNCH_YAML = lazy_pattern(r"^launch\s*:", re.M)
"""The top-level ``launch:`` key of a YAML launch file."""


def named_like_launch_only(path: str, text: str | None) -> bool:
    """True for a file named like a launch file that is something else: a YAML file with no
    ``launch:`` key at its top (a Docker Compose file, ``docker-compose.launch.yaml``), or a
    Python script outside a ``launch`` folder, run by its ``if __name__ == '__main__':``
    block, that defines no ``generate_launch_description`` (one writing launch files,
    ``generate_static_tf_launch.py``)."""
    if text is None:
        return False
    if path.endswith((".yaml", ".yml")):
        return LAUNCH_YAML.search(text) is None
    return path.endswith(".py") and "launch" not in path.split("/")[:-1] and \
        _MAIN_BLOCK.search(text) is not None and _LAUNCH_FUNCTION.search(text) is None


_MAIN_BLOCK = lazy_pattern(r"^if\s+__name__\s*==\s*['\"]__main__['\"]\s*:", re.M)
"""A script's top-level ``if __name__ == '__main__':``."""


def is_launch_test(path: str, text: str | None) -> bool:
    """True for a Python file named like a launch file that is a ``launch_testing`` test: it
    defines ``generate_test_description`` and no ``generate_launch_description`` (``ros2
    launch`` cannot run it; ``launch_test`` or pytest does)."""
    return path.endswith(".py") and text is not None and \
        "def generate_test_description" in text and "def generate_launch_description" not in text


_LAUNCH_FUNCTION = lazy_pattern(r"^def generate_launch_description\s*\(", re.M)


def runs_as_launch_file(path: str, text: str) -> bool:
    """True for Python defining ``generate_launch_description()`` at top level, and not a
    ``launch_testing`` test: a file ``ros2 launch`` can run, whatever its name."""
    return _LAUNCH_FUNCTION.search(text) is not None and not is_launch_test(path, text)


def in_launch_folder(path: str, nested: frozenset[str]) -> bool:
    """True for a file inside a folder named ``launch``, not a template's nor one of a package
    nested in this one (``nested``: :func:`nested_packages`)."""
    return "launch" in path.split("/")[:-1] and not is_template(path) and \
        not below(path, nested)


def below(path: str, folders: frozenset[str]) -> bool:
    """True when ``path`` is inside one of ``folders`` (:func:`nested_packages`)."""
    return any(path.startswith(f"{folder}/") for folder in folders)


def nested_packages(files: tuple[str, ...] | list[str]) -> frozenset[str]:
    """Sub-folders holding a package.xml of their own (kept in the package's files when they
    are Python packages of it too): their launch files are not this package's."""
    return frozenset(p[:-len("/package.xml")] for p in files if p.endswith("/package.xml"))


def python_folders(files: tuple[str, ...] | list[str]) -> frozenset[str]:
    """Folders holding an ``__init__.py``."""
    return frozenset(p.rpartition("/")[0] for p in files if p.rpartition("/")[2] == "__init__.py")


def parse_launch(path: str, text: str) -> LaunchFile:
    """Read a launch file statically; unparsable files carry a ``problem``."""
    from pkgtool.model.launch_reader import read_launch

    return read_launch(path, text)
