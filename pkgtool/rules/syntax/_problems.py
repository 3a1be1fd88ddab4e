"""What the SYN rules share: the model's parse problems of some kinds, as hits."""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping

from pkgtool.findings import Hit
from pkgtool.model.installed import installed_data, installed_files, is_ament_python
from pkgtool.model.launch import kept_aside
from pkgtool.model.package import Package
from pkgtool.model.span import ParseProblem
from pkgtool.rules.test_modules import test_files

BUILD_FILES = frozenset({"package.xml", "setup.py", "setup.cfg"})
"""Files no real package has beyond pkgtool's read limit: one that large is an error (SYN002),
any other file that large a note that it was not checked (SYN004)."""


def is_oversized_build_file(problem: ParseProblem) -> bool:
    """True for a ``too-large`` problem of package.xml, setup.py or setup.cfg."""
    return problem.kind == "too-large" and problem.span.path in BUILD_FILES


def problem_hits(package: Package, labels: Mapping[str, str],
                 keep: Callable[[ParseProblem], bool] = lambda _: True) -> Iterator[Hit]:
    """A hit for each problem whose kind ``labels`` names and that ``keep`` accepts, the label
    before the detail."""
    for problem in package.problems:
        if problem.kind in labels and keep(problem):
            yield Hit(problem.span, f"{labels[problem.kind]}: {problem.detail}")


def set_aside(package: Package, path: str) -> bool:
    """True for a Python file kept aside (in ``backup/``, ``old/``..., or named as a copy) that
    the package neither installs nor has pytest collect: nothing builds, runs or imports it."""
    return path.endswith(".py") and kept_aside(path) and \
        path not in installed_files(package) and path not in test_files(package)


def stray_yaml(package: Package, problem: ParseProblem) -> bool:
    """True for a YAML file of an ament_python package that data_files does not install and
    no other file of the package names (a log or a numpy dump with a ``.yaml`` suffix, an
    old copy): nothing builds, installs or reads it."""
    path = problem.span.path
    installed = installed_data(package) if problem.kind == "yaml-syntax" and \
        is_ament_python(package) else None
    if installed is None or path in installed.values() or \
            any(launch.path == path for launch in package.launch_files):
        return False
    name = path.rpartition("/")[2]
    return not any(name in text for other, text in package.texts.items() if other != path)
