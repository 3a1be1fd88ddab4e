"""Launch files (Python, XML, YAML) read statically: what packages, executables, files they use."""

from __future__ import annotations

from dataclasses import dataclass

from pkgtool.model.modules import PythonModule
from pkgtool.model.span import ParseProblem, Span

LAUNCH_SUFFIXES = (".launch.py", "_launch.py", ".launch.xml", "_launch.xml", ".launch.yaml",
                   "_launch.yaml", ".launch.yml", "_launch.yml")


@dataclass(frozen=True, slots=True)
class NodeRef:
    """A node the launch file starts: ``Node(package=, executable=)`` or ``<node pkg= exec=>``.

    A field is None when it was absent or not a static string (substitutions, variables that
    do not resolve). ``action`` is the action's class or tag (``Node``, ``node``);
    ``arguments`` names the keywords or attributes given (``**`` for a ``**kwargs``, ``*`` for
    ``*args``); ``package_span`` and ``executable_span`` are where those two values are
    written, when known.
    """

    package: str | None
    executable: str | None
    span: Span
    action: str = ""
    arguments: tuple[str, ...] = ()
    package_span: Span | None = None
    executable_span: Span | None = None


@dataclass(frozen=True, slots=True)
class PackageRef:
    """A package named by get_package_share_directory, FindPackageShare or $(find-pkg-share)."""

    package: str
    span: Span


@dataclass(frozen=True, slots=True)
class FileRef:
    """A file the launch file reads from a package's share folder, e.g. ('config', 'p.yaml').

    ``package`` is the package whose share folder is used (None if unknown); ``parts`` are the
    static path components after the share folder.
    """

    package: str | None
    parts: tuple[str, ...]
    span: Span


@dataclass(frozen=True, slots=True)
class LaunchFile:
    """A launch file. ``python`` is the parsed module for Python launch files (its imports)."""

    path: str
    kind: str
    nodes: tuple[NodeRef, ...]
    packages: tuple[PackageRef, ...]
    files: tuple[FileRef, ...]
    python: PythonModule | None = None
    problem: ParseProblem | None = None


def is_launch_file(path: str) -> bool:
    """True for the launch file names ros2 launch recognises."""
    name = path.rsplit("/", 1)[-1]
    return name.endswith(LAUNCH_SUFFIXES)


def parse_launch(path: str, text: str) -> LaunchFile:
    """Read a launch file statically; unparsable files carry a ``problem``."""
    from pkgtool.model.launch_reader import read_launch

    return read_launch(path, text)
