"""The launch files of a package that include launch files of the same package, and the
arguments they hand on (LCH028; parameter files handed to such includes reach nodes pkgtool
sees)."""

from __future__ import annotations

import ast
import posixpath
import re
from collections.abc import Iterator

from pkgtool.lazy_regex import lazy_pattern
from pkgtool.model.installed import installed_data
from pkgtool.model.launch import FileRef, LaunchFile
from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.model.text_comments import without_comments
from pkgtool.records import record
from pkgtool.rules.scopes import single_assignments
from pkgtool.rules.syntax_trees import Index, launch_indexes

Handed = tuple[tuple[str, Span], ...]
"""The arguments an include hands on, each with where its name is written."""


def _python_includes(indexes: dict[str, Index], launches: dict[str, LaunchFile], name: str
                     ) -> Iterator[tuple[str, int, FileRef, list[tuple[str, Span]]]]:
    """(path, line, included file, arguments) of each ``IncludeLaunchDescription`` of the
    Python launch files naming one file of this package's share."""
    for path, index in indexes.items():
        refs = [ref for ref in launches[path].files if ref.package == name and ref.parts]
        for call in index.calls:
            if (index.qualified(call.func) or "") not in _INCLUDES:
                continue
            source = call.args[0] if call.args else _keyword(call, "launch_description_source")
            ref = _included(source, refs, index, call)
            given = _keyword(call, "launch_arguments") or (
                call.args[1] if len(call.args) > 1 else None)
            if ref is not None:
                yield path, call.lineno, ref, [(key, Span(path, node.lineno, node.col_offset + 1))
                                               for key, node in _handed(given)]


XML_INCLUDE = lazy_pattern(r"<include\b[^>]*?(?<!/)>(.*?)</include>", re.S)
"""An ``<include>`` element with children (not a self-closing one, which hands nothing on)."""
_XML_ARGUMENT = lazy_pattern(r"<arg\b[^>]*?\bname\s*=\s*[\"']([^\"']+)[\"']")


def _frontend_includes(package: Package, launches: dict[str, LaunchFile]
                       ) -> Iterator[tuple[str, int, FileRef, list[tuple[str, Span]]]]:
    """(path, line, included file, arguments) of each ``<include>`` of the XML launch files
    whose ``file`` is one file of this package's share, with the ``<arg>`` elements inside."""
    for path, launch in launches.items():
        text = package.texts.get(path)
        if launch.kind != "xml" or text is None:
            continue
        text = without_comments(text, "xml")
        for element in XML_INCLUDE.finditer(text):
            line = text.count("\n", 0, element.start()) + 1
            refs = {(ref.package, ref.parts): ref for ref in launch.files
                    if ref.span.line == line and ref.package == package.name and ref.parts}
            if len(refs) == 1:
                yield path, line, next(iter(refs.values())), [
                    (found.group(1), Span.of_offset(path, text, element.start(1) + found.start()))
                    for found in _XML_ARGUMENT.finditer(element.group(1))]


_INCLUDES = frozenset({"launch.actions.IncludeLaunchDescription",
                       "launch.actions.include_launch_description.IncludeLaunchDescription"})
"""Where ``IncludeLaunchDescription`` is imported from."""


@record
class Include:
    """A launch file (``path``) including a launch file of its own package (``target``, the
    package's file data_files installs where the include looks), at ``line``, handing it
    ``handed``."""

    path: str
    line: int
    target: str
    handed: Handed


@per_package
def own_includes(package: Package) -> tuple[Include, ...]:
    """Every include of a launch file of the package by another (or the same) of its launch
    files, when every launch file parses and data_files is known."""
    installed = installed_data(package)
    launches = {launch.path: launch for launch in package.launch_files}
    if not installed or any(launch.problem for launch in launches.values()):
        return ()
    indexes = dict(launch_indexes(package))
    share = f"share/{package.name}"
    found = []
    for path, line, ref, handed in [*_python_includes(indexes, launches, package.name),
                                    *_frontend_includes(package, launches)]:
        target = installed.get(posixpath.normpath(posixpath.join(share, *ref.parts)))
        if target in launches:
            found.append(Include(path, line, target, tuple(handed)))
    return tuple(found)


def _keyword(call: ast.Call, name: str) -> ast.expr | None:
    return next((k.value for k in call.keywords if k.arg == name), None)


def _included(source: ast.expr | None, refs: list[FileRef], index: Index, call: ast.Call
              ) -> FileRef | None:
    """The one file of the package's share that ``source`` (or the value of a name it uses,
    bound once in its function) names, else None."""
    if source is None:
        return None
    where = index.enclosing_function(call) or index.module_of(call)
    single = single_assignments(where)
    parts = [source] + [single[n.id] for n in ast.walk(source)
                        if isinstance(n, ast.Name) and n.id in single]
    found = {(ref.package, ref.parts) for ref in refs for part in parts if _inside(ref, part)}
    return next((ref for ref in refs if len(found) == 1 and (ref.package, ref.parts) in found),
                None)


def _inside(ref: FileRef, node: ast.expr) -> bool:
    """True when ``ref`` is written inside ``node``'s source range."""
    start = (node.lineno, node.col_offset + 1)
    end = (node.end_lineno or node.lineno, (node.end_col_offset or 0) + 1)
    return start <= (ref.span.line, ref.span.col) <= end


def _handed(value: ast.expr | None) -> Iterator[tuple[str, ast.expr]]:
    """(name, where written) of each argument ``launch_arguments=`` hands on with a literal
    name: a dict (or its ``.items()``), or a list or tuple of pairs."""
    if isinstance(value, ast.Call) and isinstance(value.func, ast.Attribute) and \
            value.func.attr == "items" and not value.args:
        value = value.func.value
    if isinstance(value, ast.Dict):
        keys = list(value.keys)
    elif isinstance(value, (ast.List, ast.Tuple)):
        keys = [item.elts[0] if isinstance(item, ast.Tuple) and len(item.elts) == 2 else None
                for item in value.elts]
    else:
        return
    for key in keys:
        if isinstance(key, ast.Constant) and isinstance(key.value, str):
            yield key.value, key
