"""Read launch files statically: Python through ``ast``, XML through lxml, YAML through PyYAML.

Nothing is executed. Substitutions that only resolve at launch time (``$(var x)``,
``LaunchConfiguration``) leave the affected field unknown (None) instead of guessed.
"""

from __future__ import annotations

import functools
import math
import re
from collections.abc import Iterator

from pkgtool.model.launch import (COMMAND_PACKAGES, PREFIX_PACKAGES, PROCESS_PACKAGES, FileRef,
                                  LaunchFile, NodeRef, PackageRef)
from pkgtool.model.launch_python import NAME_REMAPS, program_of, remapped_name
from pkgtool.model.span import ParseProblem, Span
from pkgtool.model.xml import XmlElement
from pkgtool.records import replace
from pkgtool.lazy_regex import lazy_pattern

_LOOKUP = lazy_pattern(r"\$\(\s*find-pkg-(share|prefix)\s+([A-Za-z0-9_]+)\s*\)")
_EXECUTABLE_IN = lazy_pattern(r"\$\(\s*exec-in-pkg\s+[\w.-]+\s+([A-Za-z0-9_]+)\s*\)")
"""``$(exec-in-pkg <executable> <package>)``: launch looks the package up in the ament index."""
_SHARE_WORD = lazy_pattern(r"(?<![^\s])\$\(\s*find-pkg-share\s+[A-Za-z0-9_]+\s*\)"
                           r"/[^\s$'\"]*(?=\s|$)")
"""A share path that is one whole word of a node's ``args`` (``-d $(find-pkg-share p)/a.rviz``)."""
VARIABLE_READ = lazy_pattern(r"\$\(var\s+([\w.-]+)\s*\)")
"""A ``$(var x)`` substitution of an XML or YAML launch file (reading the argument ``x``)."""
FRONTEND_DECLARED = (lazy_pattern(r"<(?:arg|let)\b[^>]*?\bname\s*=\s*[\"']([^\"']+)[\"']"),
                     lazy_pattern(r"^\s*-?\s*(?:arg|let):\s*\n\s+name:\s*[\"']?([\w.-]+)",
                                  re.M),
                     lazy_pattern(r"\b(?:arg|let):\s*\{[^}]*?\bname:\s*[\"']?([\w.-]+)"))
"""An XML (``<arg name="x">``, ``<let name="x">``) or YAML (``- arg:`` / ``name: x``, or
``- arg: {name: x, ...}``) launch file's declared or set arguments."""
_COMMAND = lazy_pattern(r"""\$\(\s*command\s+['"]?\s*([\w.-]+)""")
_SHARE_PATH = lazy_pattern(r"^\$\(\s*find-pkg-share\s+([A-Za-z0-9_]+)\s*\)(/[^$]*)$")
NODE_TAGS = {"node": ("exec", "executable"), "lifecycle_node": ("exec", "executable"),
             "node_container": ("exec", "executable"), "composable_node": ()}
"""Launch actions that start a node, and the attribute(s) naming its executable."""


def kind_of(path: str) -> str:
    """``python``, ``xml`` or ``yaml`` from the launch file's name (``.launch``: XML)."""
    if path.endswith(".py"):
        return "python"
    return "xml" if path.endswith((".xml", ".launch")) else "yaml"


def read_launch(path: str, text: str) -> LaunchFile:
    """Read one launch file; a file that does not parse carries a ``problem`` instead."""
    kind = kind_of(path)
    if kind == "python":
        return _python(path, text)
    reader = _xml if kind == "xml" else _yaml
    found = reader(path, text)
    if isinstance(found, ParseProblem):
        return LaunchFile(path, kind, (), (), (), problem=found)
    nodes, values, paths, commands = found
    packages, files = _substitutions(values)
    packages += tuple(PackageRef(_PROGRAMS[program], span) for program, span in
                      ((program_of(command), span) for command, span in commands)
                      if program in _PROGRAMS)
    return LaunchFile(path, kind, tuple(nodes), packages, files,
                      paths=tuple((p, span) for p, span in paths if _static(p)))


def _python(path: str, text: str) -> LaunchFile:
    from pkgtool.model.launch_python import read_python_launch
    from pkgtool.model.python_visitor import module_from_tree, parse_tree

    tree = parse_tree(path, text)
    if isinstance(tree, ParseProblem):
        from pkgtool.model.modules import PythonModule

        return LaunchFile(path, "python", (), (), (), PythonModule(path, (), frozenset(), tree),
                          tree)
    try:
        nodes, packages, files = read_python_launch(path, tree)
    except RecursionError:  # absurdly nested code: treat everything as unknown
        nodes, packages, files = (), (), ()
    return LaunchFile(path, "python", nodes, packages, files, module_from_tree(path, tree))


def _static(value: str | None) -> str | None:
    """An attribute value, or None when it holds a substitution or is empty."""
    return value if value and "$(" not in value else None


def _substitutions(values: list[tuple[str, Span]]) -> tuple[tuple[PackageRef, ...],
                                                            tuple[FileRef, ...]]:
    packages: list[PackageRef] = []
    files: list[FileRef] = []
    for value, span in values:
        packages.extend(PackageRef(m.group(2), span) for m in _LOOKUP.finditer(value))
        packages.extend(PackageRef(m.group(1), span) for m in _EXECUTABLE_IN.finditer(value))
        packages.extend(PackageRef(COMMAND_PACKAGES[m.group(1)], span)
                        for m in _COMMAND.finditer(value) if m.group(1) in COMMAND_PACKAGES)
        found = _share_file(value, span)
        if found:
            files.append(found)
    return tuple(packages), tuple(files)


def _share_file(value: str, span: Span) -> FileRef | None:
    """The share file a ``$(find-pkg-share pkg)/a/b`` value names, if it is that and static."""
    share = _SHARE_PATH.match(value.strip())
    if not share:
        return None
    parts = tuple(p for p in share.group(2).split("/") if p not in ("", "."))
    return FileRef(share.group(1), parts, span) if parts and ".." not in parts else None


_PROGRAMS = {**PROCESS_PACKAGES, **PREFIX_PACKAGES}
"""The package (rosdep key) of each program an ``executable`` action or a prefix starts."""


# XML -------------------------------------------------------------------------------------
_XML_FILES = {"include": "file", "set_parameters_from_file": "filename"}
"""XML launch actions naming a file, besides ``<param from=>``, and the attribute naming it."""
Read = tuple[list[NodeRef], list[tuple[str, Span]], list[tuple[str, Span]],
             list[tuple[str, Span]]]
"""What an XML or YAML launch file gives: its nodes, its attribute values, the file paths it
names (parameter files, included launch files), and the command lines of its ``executable``
actions (``<executable cmd="rviz2 -d ...">``), each where it is written."""


def _xml(path: str, text: str) -> Read | ParseProblem:
    from pkgtool.model.xml import parse_xml

    root = parse_xml(path, text)
    if isinstance(root, ParseProblem):
        return root
    nodes: list[NodeRef] = []
    values: list[tuple[str, Span]] = []
    paths: list[tuple[str, Span]] = []
    commands: list[tuple[str, Span]] = []
    top = {id(child) for child in root.children if not _conditional(child)}
    defaults = {e.attribute("name"): e.attribute("default") for e in _elements(root)
                if e.tag == "arg" and e.attribute("default")}
    for element in _elements(root):
        if element.tag == "executable" and element.attribute("cmd"):
            commands.append((element.attribute("cmd") or "", element.span))
        if element.attribute("launch-prefix") and not _conditional(element) and \
                (element.tag in NODE_TAGS or element.tag == "executable"):
            commands.append((element.attribute("launch-prefix") or "", element.span))
        named = element.attribute(_XML_FILES.get(element.tag, "from")) \
            if element.tag in _XML_FILES or element.tag == "param" else None
        if named is not None:
            paths.append((named, element.span))
        if element.tag in NODE_TAGS:
            executable = next((element.attribute(a) for a in NODE_TAGS[element.tag]
                               if element.attribute(a) is not None), None)
            froms = [(c.attribute("from") or "", c.span) for c in element.children
                     if c.tag == "param" and c.attribute("from") is not None]
            froms = _with_defaults(froms, defaults)
            remaps = [(c.attribute("from"), c.attribute("to"))
                      for c in element.children if c.tag == "remap"]
            arguments = [element.attribute(a) for a in ("args", "ros_args")]
            package = element.attribute("pkg")
            sourceless = tuple((c.span, tuple(k for k, _ in c.attributes))
                               for c in element.children if c.tag == "param" and
                               c.attribute("name") is None and c.attribute("from") is None)
            nodes.append(_named(NodeRef(
                _static(package), _static(executable), element.span,
                element.tag, tuple(k for k, _ in element.attributes),
                inline_parameters=tuple(_xml_parameters(element.children)),
                output=_static(element.attribute("output")),
                package_written=package if _static(package) is None else None,
                params_without_source=sourceless, always_started=id(element) in top),
                element.attribute("name"), element.attribute("namespace"), froms, remaps,
                arguments))
        values.extend((value, element.span) for _, value in element.attributes)
        if element.tag in NODE_TAGS:  # `args="-d $(find-pkg-share pkg)/view.rviz"`
            values.extend((m.group(0), element.span)
                          for m in _SHARE_WORD.finditer(element.attribute("args") or ""))
    return nodes, values, paths, commands


def _with_defaults(froms: list[tuple[str, Span]], defaults: dict[str, str | None]
                   ) -> list[tuple[str, Span]]:
    """A node's parameter files, and for each ``$(var x)`` among them the default of the
    argument ``x`` too (the file it gets unless another is given), where the ``$(var x)`` is."""
    return froms + [(defaults[found.group(1)] or "", span) for text, span in froms
                    for found in [VARIABLE_READ.fullmatch(text.strip())]
                    if found and found.group(1) in defaults]


def _xml_parameters(children: tuple[XmlElement, ...], prefix: str = ""
                    ) -> Iterator[tuple[str, Span, str | None]]:
    """The ``<param name= value=>`` children of an XML launch node (nested ones give dotted
    names), each with the source of the value launch gives the node (None when it is not
    static)."""
    for child in children:
        name = child.attribute("name")
        if child.tag != "param" or name is None or "$(" in name:
            continue
        value = child.attribute("value")
        if value is not None:
            yield f"{prefix}{name}", child.span, None if "$(" in value else _launch_value(value)
        else:
            yield from _xml_parameters(child.children, f"{prefix}{name}.")


def _launch_value(text: str) -> str | None:
    """The source of the value launch's XML and YAML front ends make of the attribute ``text``
    when no type is asked for (launch.frontend.type_utils: YAML's reading, tried as an int,
    a float, then kept as the text): ``'1'`` gives ``1``, ``'1.5'`` ``1.5``, ``'true'``
    ``True``, ``'fast'`` ``'fast'``. None for a value with no literal source (``.inf``)."""
    import yaml

    try:
        value = yaml.safe_load(text)
    except yaml.YAMLError:
        return repr(text)
    if isinstance(value, int):  # bool included, as launch's isinstance(value, int) test does
        return repr(value)
    try:
        number = float(value)
    except (TypeError, ValueError):
        return repr(text)
    return repr(number) if math.isfinite(number) else None


def _named(node: NodeRef, name: str | None, namespace: str | None,
           froms: list[tuple[str, Span]], remaps: list[tuple[str | None, str | None]],
           arguments: list[str | None]) -> NodeRef:
    """``node`` with the name, namespace and parameter files of an XML or YAML launch node.

    ``froms`` are its parameter files (``<param from=>``) where written, ``remaps`` its
    ``(from, to)`` remappings and ``arguments`` its ``args`` and ``ros_args`` values.
    """
    files = [_share_file(text, span) for text, span in froms]
    names: list[str | None] = [_static(name)] if name is not None else []
    names.extend(_static(to) if to else None for key, to in remaps
                 if key is None or "$(" in key or key in NAME_REMAPS)
    for text in (a for a in arguments if a):
        names.extend(_static(remapped_name(word)) for word in text.split()
                     if "$(" in word or remapped_name(word) is not None)
    known = [n for n in names if n is not None]
    return replace(node, parameter_files=tuple(f for f in files if f),
                   other_parameters=None in files, name=known[-1] if known else None,
                   namespace=_static(namespace), name_unknown=None in names)


def _conditional(element: XmlElement) -> bool:
    """True for an XML launch node that may not start, or may start in another namespace
    than its own: ``if``/``unless``, a ``__ns`` remapping."""
    return element.attribute("if") is not None or element.attribute("unless") is not None \
        or any("__ns" in value for _, value in element.attributes) \
        or any("__ns" in (c.attribute("from") or "") for c in element.children)


def _elements(root: XmlElement) -> Iterator[XmlElement]:
    stack = [root]
    while stack:
        element = stack.pop()
        yield element
        stack.extend(reversed(element.children))


# YAML ------------------------------------------------------------------------------------
@functools.lru_cache(maxsize=32)
def yaml_problem(path: str, text: str, *, documents: bool = True) -> object:
    """The composed YAML node (or, with ``documents``, the list of them), or a ParseProblem.

    Composing builds no Python object and runs no tag constructor: it only checks syntax.
    Cached for the last few files (the model checks every YAML file's syntax, and three
    rules read parameter files again): callers must treat the nodes as read-only.
    """
    import yaml

    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)  # libyaml when available: ~10x faster
    try:
        composed = list(yaml.compose_all(text, Loader=loader)) if documents else \
            yaml.compose(text, Loader=loader)
        looped = _holding_itself(composed if documents else [composed])
        if looped is not None:
            mark = looped.start_mark
            return ParseProblem("yaml-syntax", Span(path, mark.line + 1, mark.column + 1),
                                "an alias stands for a mapping or list that holds it: the "
                                "value never ends")
        return composed
    except yaml.MarkedYAMLError as error:
        mark = error.problem_mark or error.context_mark
        line, col = (mark.line + 1, mark.column + 1) if mark else (1, 1)
        return ParseProblem("yaml-syntax", Span(path, line, col), str(error.problem or error))
    except (yaml.YAMLError, RecursionError) as error:
        detail = str(error) or "the YAML is nested too deeply"
        return ParseProblem("yaml-syntax", Span(path, 1, 1), detail)


def _holding_itself(roots: list) -> object | None:
    """A collection node that holds itself through aliases (``a: &x {b: *x}``), or None."""
    done: set[int] = set()
    for root in roots:
        stack: list[tuple[object, bool]] = [(root, False)]
        open_now: set[int] = set()
        while stack:
            node, leaving = stack.pop()
            if leaving:
                open_now.discard(id(node))
                done.add(id(node))
                continue
            if id(node) in open_now:
                return node
            if id(node) in done or getattr(node, "id", "") not in ("mapping", "sequence"):
                continue
            open_now.add(id(node))
            stack.append((node, True))
            items = getattr(node, "value")
            children = [v for pair in items for v in pair] if node.id == "mapping" else items
            stack.extend((child, False) for child in children)
    return None


def _yaml(path: str, text: str) -> Read | ParseProblem:
    import yaml

    root = yaml_problem(path, text, documents=False)
    if isinstance(root, ParseProblem):
        return root
    nodes: list[NodeRef] = []
    values: list[tuple[str, Span]] = []
    paths: list[tuple[str, Span]] = []
    commands: list[tuple[str, Span]] = []
    walked = list(_yaml_walk(root))
    defaults = {fields["name"]: fields["default"] for node in walked
                if isinstance(node, yaml.MappingNode) for key, value in node.value
                if getattr(key, "value", None) == "arg" and isinstance(value, yaml.MappingNode)
                for fields in [{str(k.value): str(v.value) for k, v in value.value
                                if isinstance(k, yaml.ScalarNode) and
                                isinstance(v, yaml.ScalarNode)}]
                if "name" in fields and fields.get("default")}
    for node in walked:
        span = Span(path, node.start_mark.line + 1, node.start_mark.column + 1)
        if isinstance(node, yaml.ScalarNode):
            values.append((str(node.value), span))
        elif isinstance(node, yaml.MappingNode):
            for key, value in node.value:
                if isinstance(key, yaml.ScalarNode) and key.value in NODE_TAGS and \
                        isinstance(value, yaml.MappingNode):
                    nodes.append(_yaml_node(key, value, path, defaults))
                    paths.extend((str(p.value), _yaml_span(path, p))
                                 for p in _yaml_params(value))
                elif isinstance(key, yaml.ScalarNode) and key.value in _XML_FILES and \
                        isinstance(value, yaml.MappingNode):
                    paths.extend((str(v.value), _yaml_span(path, v)) for k, v in value.value
                                 if getattr(k, "value", None) == _XML_FILES[key.value] and
                                 isinstance(v, yaml.ScalarNode))
                if isinstance(key, yaml.ScalarNode) and (
                        key.value == "executable" or key.value in NODE_TAGS) and \
                        isinstance(value, yaml.MappingNode):
                    commands.extend((str(v.value), _yaml_span(path, v)) for k, v in value.value
                                    if getattr(k, "value", None) in ("cmd", "launch-prefix")
                                    and isinstance(v, yaml.ScalarNode))
    nodes.sort(key=lambda n: (n.span.line, n.span.col))
    return nodes, values, paths, commands


def _yaml_walk(root: object) -> Iterator[object]:
    """Every node of a composed YAML document once (aliases share nodes: no billion
    laughs), mappings before what they hold."""
    import yaml

    seen: set[int] = set()
    stack = [root] if root is not None else []
    while stack:
        node = stack.pop()
        if id(node) in seen:
            continue
        seen.add(id(node))
        yield node
        if isinstance(node, yaml.MappingNode):
            for key, value in node.value:
                stack.extend((value, key))
        elif isinstance(node, yaml.SequenceNode):
            stack.extend(reversed(node.value))


def _yaml_span(path: str, node: object) -> Span:
    mark = getattr(node, "start_mark")
    return Span(path, mark.line + 1, mark.column + 1)


def _yaml_params(mapping: object) -> list[object]:
    """The scalar ``from:`` values of the ``param:`` entries of a YAML launch node."""
    import yaml

    return [p["from"] for p in _yaml_entries(mapping, "param")
            if isinstance(p.get("from"), yaml.ScalarNode)]


def _yaml_node(tag: object, mapping: object, path: str, defaults: dict[str, str | None]
               ) -> NodeRef:
    """A ``node:`` (or similar) mapping of a YAML launch file; ``tag`` is its key node;
    ``defaults`` the file's argument defaults (a ``from: $(var x)`` parameter file is also
    ``x``'s default, as in XML)."""
    import yaml

    assert isinstance(tag, yaml.ScalarNode) and isinstance(mapping, yaml.MappingNode)
    scalars = {k.value: v for k, v in mapping.value
               if isinstance(k, yaml.ScalarNode) and isinstance(v, yaml.ScalarNode)}
    fields = {key: value.value for key, value in scalars.items()}
    key = next((a for a in NODE_TAGS[tag.value] if a in fields), None)

    def span(node: yaml.Node) -> Span:
        return _yaml_span(path, node)

    names = tuple(str(k.value) for k, _ in mapping.value if isinstance(k, yaml.ScalarNode))
    node = NodeRef(_static(fields.get("pkg")), _static(fields[key] if key else None), span(tag),
                   str(tag.value), names, span(scalars["pkg"]) if "pkg" in scalars else None,
                   span(scalars[key]) if key else None, output=_static(fields.get("output")))
    params = _yaml_params(mapping)
    remaps = [(r.get("from"), r.get("to")) for r in _yaml_entries(mapping, "remap")]
    froms = [(str(p.value), span(p)) for p in params if isinstance(p, yaml.ScalarNode)]
    named = _named(node, fields.get("name"), fields.get("namespace"),
                   _with_defaults(froms, defaults),
                   [tuple(_text(v) for v in pair) for pair in remaps],  # type: ignore[misc]
                   [fields.get("args"), fields.get("ros_args")])
    return replace(named, inline_parameters=tuple(_yaml_parameters(mapping, path)))


def _yaml_parameters(mapping: object, path: str) -> Iterator[tuple[str, Span, str | None]]:
    """The ``param:`` entries of a YAML launch node with a ``name:`` and a scalar ``value:``,
    each with the source of the value launch gives the node (None when it is not static, or
    quoted: launch may read a quoted text as a number again)."""
    import yaml

    for entry in _yaml_entries(mapping, "param"):
        name, value = entry.get("name"), entry.get("value")
        if isinstance(name, yaml.ScalarNode) and isinstance(value, yaml.ScalarNode) and \
                "$(" not in str(name.value):
            text = str(value.value)
            yield str(name.value), _yaml_span(path, name), \
                None if value.style or "$(" in text else _launch_value(text)


def _text(node: object) -> str | None:
    return str(getattr(node, "value")) if getattr(node, "id", "") == "scalar" else None


def _yaml_entries(mapping: object, key: str) -> list[dict[str, object]]:
    """The entries of a YAML launch node's ``param:`` or ``remap:`` list: field name -> YAML
    value node (an entry that is not a mapping has no fields)."""
    import yaml

    assert isinstance(mapping, yaml.MappingNode)
    found: list[dict[str, object]] = []
    for k, entries in mapping.value:
        if isinstance(k, yaml.ScalarNode) and k.value == key and \
                isinstance(entries, yaml.SequenceNode):
            found.extend({str(f.value): v for f, v in
                          (e.value if isinstance(e, yaml.MappingNode) else ())
                          if isinstance(f, yaml.ScalarNode)} for e in entries.value)
    return found
