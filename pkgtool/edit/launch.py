"""Edits of launch files: start one more node (Python, XML or YAML launch file).

Python: a ``Node(...)`` joins the list literal given to ``LaunchDescription([...])`` in
``generate_launch_description``, laid out and parameterised like the nodes already there.
XML: a ``<node/>`` after the last action of ``<launch>``. YAML: a ``- node:`` item at the end
of the ``launch:`` list. A launch file built another way is refused.
"""

from __future__ import annotations

import ast

from pkgtool.safe_xml import xml_text
from pkgtool.edit.core import Edit, EditError
from pkgtool.edit.pysource import PyDoc
from pkgtool.edit.source import Source
from pkgtool.edit.xml_scan import insert_after, scan
from pkgtool.model.launch import parse_launch


def starts(source: Source, package: str, executable: str) -> bool:
    """True when the launch file already starts ``package``'s ``executable``."""
    launch = parse_launch(source.path, source.text)
    return any(n.package == package and n.executable == executable for n in launch.nodes)


def add_node(source: Source, package: str, executable: str) -> list[Edit]:
    """Edits making the launch file start ``executable`` of ``package`` (named alike)."""
    if starts(source, package, executable):
        return []
    if source.path.endswith(".py"):
        return _python(source, package, executable)
    if source.path.endswith(".xml"):
        return _xml(source, package, executable)
    return _yaml(source, package, executable)


def _refusal(source: Source, how: str) -> EditError:
    return EditError(f"`{source.path}` {how}, which pkgtool does not edit: add the node to it "
                     "by hand.")


def _python(source: Source, package: str, executable: str) -> list[Edit]:
    doc = PyDoc(source)
    function = next((n for n in doc.tree.body if isinstance(n, ast.FunctionDef)
                     and n.name == "generate_launch_description"), None)
    if function is None:
        raise _refusal(source, "has no module-level `generate_launch_description()`")
    actions = next((node.args[0] for node in ast.walk(function)
                    if isinstance(node, ast.Call) and _called(node) == "LaunchDescription"
                    and node.args and isinstance(node.args[0], ast.List)), None)
    if not isinstance(actions, ast.List):
        raise _refusal(source, "builds its launch description without a `LaunchDescription([...])`"
                       " list")
    items = [(doc.start(e), doc.end(e)) for e in actions.elts]
    siblings = [e for e in actions.elts if isinstance(e, ast.Call) and _called(e) == "Node"]
    callee = doc.segment(siblings[0].func) if siblings else "Node"
    edits = [] if siblings else doc.add_imports([("launch_ros.actions", "Node")])
    keywords = [("package", doc.string(package)), ("executable", doc.string(executable)),
                ("name", doc.string(executable))]
    shared = _shared_parameters(doc, siblings)
    if shared:
        keywords.append(("parameters", shared))
    indent = doc.item_indent(actions, items)
    inner = indent + doc.indent_unit()
    newline = source.newline
    call = (f"{callee}(" + "".join(f"{newline}{inner}{key}={value}," for key, value in keywords)
            + f"{newline}{indent})")
    return doc.insert_item(actions, items, call) + edits


def _called(node: ast.Call) -> str:
    func = node.func
    return func.id if isinstance(func, ast.Name) else getattr(func, "attr", "")


def _shared_parameters(doc: PyDoc, siblings: list[ast.Call]) -> str | None:
    """The ``parameters=`` source every sibling node passes alike (a shared params file)."""
    found = {doc.segment(k.value) for node in siblings for k in node.keywords
             if k.arg == "parameters"}
    every = all(any(k.arg == "parameters" for k in node.keywords) for node in siblings)
    return found.pop() if siblings and every and len(found) == 1 else None


def _xml(source: Source, package: str, executable: str) -> list[Edit]:
    root = scan(source.text)
    if root is None or root.local != "launch":
        raise _refusal(source, "has no `<launch>` root")
    element = (f'<node pkg="{xml_text(package)}" exec="{xml_text(executable)}" '
               f'name="{xml_text(executable)}"/>')
    if root.children:
        return [insert_after(source, root.children[-1], element)]
    if root.inner_start == root.end:
        raise _refusal(source, "is an empty `<launch/>`")
    indent = (source.indent_at(root.start) or "") + "  "
    at = source.line_start(root.inner_end) if source.indent_at(root.inner_end) is not None \
        else root.inner_end
    return [Edit(source.path, at, at, indent + element + source.newline)]


def _yaml(source: Source, package: str, executable: str) -> list[Edit]:
    from pkgtool.model.launch_reader import yaml_problem

    import yaml

    root = yaml_problem(source.path, source.text, documents=False)
    actions = None
    if isinstance(root, yaml.MappingNode):
        actions = next((v for k, v in root.value if getattr(k, "value", None) == "launch"), None)
    if not isinstance(actions, yaml.SequenceNode) or actions.flow_style or not actions.value:
        raise _refusal(source, "has no block list under `launch:`")
    last = actions.value[-1]
    dash = source.text.rfind("-", 0, last.start_mark.index)
    column = dash - source.line_start(dash)
    step = last.start_mark.column - column
    end = _last_scalar(last).end_mark.index
    pad, inner = " " * column, " " * (column + step * 2)
    lines = [f"{pad}- node:", f"{inner}pkg: {package}", f"{inner}exec: {executable}",
             f"{inner}name: {executable}"]
    newline = source.newline
    return [Edit(source.path, end, end, newline + newline.join(lines))]


def _last_scalar(node: object) -> object:
    """The last scalar inside ``node``: its end mark is exact (a collection's runs on)."""
    import yaml

    while isinstance(node, (yaml.MappingNode, yaml.SequenceNode)) and node.value:
        last = node.value[-1]
        node = last[1] if isinstance(node, yaml.MappingNode) else last
    return node
