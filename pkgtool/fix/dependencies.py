"""Fixers that declare what code imports (the rosdep key as the right ``*_depend``), and
import interfaces from the module of their kind."""

from __future__ import annotations

import ast
import re
from collections.abc import Iterable, Iterator

from pkgtool.edit.core import Edit, Fix
from pkgtool.edit.manifest import ManifestDoc
from pkgtool.findings import Finding
from pkgtool.fix.common import WRITE_NAME, child_at, manifest_doc, offer, python_nodes
from pkgtool.fix.registry import Refusal, fixer
from pkgtool.knowledge.rosdistro import is_known_dependency
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.knowledge.interfaces import kind_in
from pkgtool.rules.interface_types import interfaces_for
from pkgtool.rules.launch._python_launch import launch_tests
from pkgtool.rules.dependencies.sibling_import import installed_name
from pkgtool.rules.dependencies.unknown_interface_import import written_import
from pkgtool.rules.package_lookups import commented_out
from pkgtool.rules.imports import (BUILD_ONLY, Need, declared, is_test_launch, needs,
                                   test_code, unmet_runtime_needs)
from pkgtool.lazy_regex import lazy_pattern


def _declare(package: Package, findings: list[Finding], found: Iterable[Need], tag: str
             ) -> Iterator[Fix | Refusal]:
    doc = manifest_doc(package)
    if doc is None:
        return
    wanted = {_at(f.span) for f in findings}
    keys: list[str] = []
    for need in found:
        if need.kind != "unknown" and _at(need.imported.span) in wanted \
                and need.key not in keys and _resolves(package, need.key):
            keys.append(need.key)
    for key in keys:
        yield from _add(doc, tag, key)


_NAMED = lazy_pattern(r"`([^`]+)` is used by a launch file")
"""The package an LCH002 finding names."""


def _resolves(package: Package, name: str) -> bool:
    """True for a released package or rosdep key of the target distribution, or a workspace
    package with a package.xml: an unknown name may be misspelled or live elsewhere, and
    declaring it would only turn the finding into MAN021/MAN022; a Python project without
    package.xml is a name rosdep cannot resolve (the user chooses); a name package.xml has in
    a comment may be left out on purpose (the user chooses)."""
    context = package.context
    owner = context.workspace.get(name)
    if name in commented_out(package):
        return False  # left out in a comment: maybe on purpose (a cycle), the user decides
    return owner.manifest if owner is not None else is_known_dependency(name, context.distro)


def _at(span: Span) -> tuple[str, int, int]:
    return (span.path, span.line, span.col)


def _add(doc: ManifestDoc, tag: str, key: str) -> Iterator[Fix | Refusal]:
    return offer(f"Add `<{tag}>{key}</{tag}>`", lambda: doc.add(tag, key))


@fixer("DEP001", "Add an `<exec_depend>` with the rosdep key; spell a misspelt package right")
def undeclared(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    """Declare each import's rosdep key for run time, and write the package a ``from``
    import misspells as the one the finding names (``from sensors_msgs.msg import Imu``
    becomes ``from sensor_msgs.msg import Imu``). Safe: that import raised. ``import
    sensors_msgs.msg``, whose uses would change too, needs the user."""
    misspelt = [f for f in findings if WRITE_NAME.fullmatch(f.fix or "")]
    yield from _declare(package, [f for f in findings if f not in misspelt],
                        unmet_runtime_needs(package), "exec_depend")
    for doc, finding, nodes in python_nodes(package, misspelt):
        meant = WRITE_NAME.fullmatch(finding.fix or "")
        statement = next((n for n in nodes if isinstance(n, ast.ImportFrom)), None)
        if meant is None or statement is None or statement.level or not statement.module:
            continue
        wrong = statement.module.split(".")[0]
        written = re.match(rf"from\s+({re.escape(wrong)})\b", doc.text[doc.start(statement):])
        if written:
            at = doc.start(statement) + written.start(1)
            yield Fix(f"Import from `{meant[1]}`",
                      (Edit(doc.source.path, at, at + len(wrong), meant[1]),))


@fixer("DEP002", "Make the build-only dependency `<depend>`, or add an `<exec_depend>`")
def build_only(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    """A ``<build_depend>`` becomes ``<depend>`` (build, export and run); a key declared only
    as ``<buildtool_depend>`` or ``<build_export_depend>`` keeps it and gains an
    ``<exec_depend>``. Safe: the key was declared already, the fix only adds run time."""
    doc = manifest_doc(package)
    if doc is None:
        return
    wanted = {_at(f.span) for f in findings}
    only = declared(package, BUILD_ONLY)
    found = (next((k for k in need.keys if k in only), None)
             for need in unmet_runtime_needs(package) if _at(need.imported.span) in wanted)
    for key in dict.fromkeys(k for k in found if k is not None):
        dependency = only[key]
        element = child_at(doc, dependency.span.line)
        if dependency.tag == "build_depend" and element is not None and \
                element.local == "build_depend" and doc.text_of(element) == key:
            yield Fix(f"Change `<build_depend>{key}</build_depend>` to `<depend>`",
                      tuple(doc.retag(element, "depend")))
        else:
            yield from _add(doc, "exec_depend", key)


@fixer("DEP003", "Add a `<test_depend>` with the rosdep key")
def undeclared_test(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    """Declare each test import's rosdep key for tests."""
    found = (need for module in test_code(package) for need in needs(package, module))
    yield from _declare(package, findings, found, "test_depend")


@fixer("LCH003", "Add an `<exec_depend>` for what the launch file imports")
def launch_import(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    """Declare each launch-file import's rosdep key for run time."""
    found = (need for launch in package.launch_files if launch.python is not None
             for need in needs(package, launch.python))
    yield from _declare(package, findings, found, "exec_depend")


@fixer("LCH002", "Add an `<exec_depend>` for the package the launch file uses")
def launch_package(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    """Declare each ROS package a launch file starts or includes (the name is its key), as a
    ``<test_depend>`` for a launch file of the tests or a ``launch_testing`` test.

    Only the package each finding names (an XML tag may use several, its own among them), and
    only names that resolve, as for every key these fixers add (see :func:`_resolves`).
    """
    doc = manifest_doc(package)
    if doc is None:
        return
    wanted = {(_at(f.span), named.group(1)) for f in findings
              if (named := _NAMED.match(f.message)) is not None}
    names: dict[str, str] = {}
    tests = launch_tests(package)
    for launch in (*package.launch_files, *tests):
        tag = "test_depend" if launch in tests or is_test_launch(launch.path) else "exec_depend"
        used = [(n.package, n.package_span or n.span) for n in launch.nodes if n.package] + [
            (p.package, p.span) for p in launch.packages]
        names.update((name, tag) for name, span in used if (_at(span), name) in wanted and
                     name not in names and name != package.name and _resolves(package, name))
    for name, tag in names.items():
        yield from _add(doc, tag, name)


_LOOKED_UP = lazy_pattern(r"`([^`]+)` is used by the package's code")
"""The package a DEP011 finding names."""


_DESCRIBED = lazy_pattern(r"`([^`]+)` is used by the installed file")
"""The package a DEP012 finding names."""


@fixer("DEP011", "Add an `<exec_depend>` for the package the code looks up")
def looked_up_package(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    """Declare each package whose share folder or prefix installed code looks up (the name is
    its key), for names that resolve (see :func:`_resolves`)."""
    yield from _declare_named(package, findings, _LOOKED_UP)


@fixer("DEP012", "Add an `<exec_depend>` for the package the description file names")
def described_package(package: Package, findings: list[Finding]) -> Iterator[Fix | Refusal]:
    """Declare each package an installed robot description, world or RViz file names (the
    name is its key), for names that resolve (see :func:`_resolves`)."""
    yield from _declare_named(package, findings, _DESCRIBED)


def _declare_named(package: Package, findings: list[Finding], pattern: re.Pattern[str]
                   ) -> Iterator[Fix | Refusal]:
    """An ``<exec_depend>`` for each package a finding's message names by ``pattern``."""
    doc = manifest_doc(package)
    names = dict.fromkeys(named.group(1) for f in findings
                          if (named := pattern.match(f.message)) is not None)
    for name in names if doc is not None else ():
        if name != package.name and _resolves(package, name):
            yield from _add(doc, "exec_depend", name)


@fixer("DEP007", "Import the module through its package")
def sibling_module(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Write the installed name of a module imported by its bare name: ``from helpers import
    x`` becomes ``from my_pkg.helpers import x``, ``import helpers`` ``from my_pkg import
    helpers`` (the same name is bound), ``from filters.low_pass import f`` inside
    ``my_pkg/filters/`` ``from my_pkg.filters.low_pass import f``. Safe: installed, the import
    raised ModuleNotFoundError (running the file as a script, ``python3 node.py``, no longer
    works, as ``ros2 run`` never does that). ``import a.b`` and imports of several modules
    in one statement need the user."""
    for doc, finding, nodes in python_nodes(package, findings):
        names = installed_name(finding.message, finding.fix)
        statement = next((n for n in nodes if isinstance(n, (ast.Import, ast.ImportFrom))),
                         None)
        if names is None or statement is None:
            continue
        top, full = names
        start, path = doc.start(statement), doc.source.path
        if isinstance(statement, ast.ImportFrom) and not statement.level and \
                (statement.module or "").split(".")[0] == top:
            written = re.match(rf"from\s+({re.escape(top)})\b", doc.text[start:])
            if written:
                at = start + written.start(1)
                yield Fix(f"Import from `{full}`", (Edit(path, at, at + len(top), full),))
        elif isinstance(statement, ast.Import) and [a.name for a in statement.names] == [top]:
            written = re.match(rf"import(\s+){re.escape(top)}\b", doc.text[start:])
            if written:
                yield Fix(f"Import `{top}` from `{full.rpartition('.')[0]}`", (Edit(
                    path, start, start + written.end(), f"from {full.rpartition('.')[0]} "
                    f"import{written[1]}{top}"),))


@fixer("DEP008", "Import the interface from the module of its kind")
def interface_module(package: Package, findings: list[Finding]) -> Iterator[Fix]:
    """Write the module the rule names into the ``from ... import`` statement when it imports
    the same names (``from std_msgs import String`` becomes ``from std_msgs.msg import
    String``, ``std_srvs.msg`` ``std_srvs.srv``, ``std_msgs.msgs`` ``std_msgs.msg``), or
    interfaces of that one kind (``from sensor_msgs import Image, CameraInfo``). Safe:
    the import raised. A misspelt interface name, an ``import pkg.msgs`` whose uses would
    change too, and imports of several names that need several statements need the user."""
    for doc, finding, nodes in python_nodes(package, findings):
        wanted = written_import(finding.fix)
        statement = next((n for n in nodes if isinstance(n, ast.ImportFrom)), None)
        if wanted is None or statement is None or statement.level or \
                not _same_names(package, statement, *wanted):
            continue
        written = re.match(rf"from\s+({re.escape(statement.module or '')})\s+import\b",
                           doc.text[doc.start(statement):])
        if written and written[1] != wanted[0]:
            at = doc.start(statement) + written.start(1)
            yield Fix(f"Import from `{wanted[0]}`",
                      (Edit(doc.source.path, at, at + len(written[1]), wanted[0]),))


def _same_names(package: Package, statement: ast.ImportFrom, module: str,
                names: tuple[str, ...]) -> bool:
    """True when ``statement`` imports ``names``, or (``from pkg import A, B`` for
    ``pkg.msg``) only interfaces of that kind of ``pkg``."""
    taken = tuple(a.name for a in statement.names)
    if taken == names:
        return True
    package_name, _, kind = module.partition(".")
    known = interfaces_for(package, package_name) if statement.module == package_name else None
    return bool(known) and all(kind_in(known, name) == kind for name in taken)
