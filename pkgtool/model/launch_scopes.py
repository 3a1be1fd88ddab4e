"""Names a Python launch file binds: per scope for the evaluator, and what its imports bind."""

from __future__ import annotations

import ast
from collections.abc import Iterable

from pkgtool.model.ast_nodes import (child_nodes, descendants, last_name, nodes_of_class,
                                     opens_to_write, subtree)


def bindings(nodes: list[ast.AST], params: ast.arguments | None
             ) -> dict[str, ast.expr | None]:
    """Names bound in one scope (``nodes``, its :func:`scope_nodes`): the single assigned
    expression, or None when ambiguous."""
    found: dict[str, ast.expr | None] = {}
    if params is not None:
        for arg in (*params.posonlyargs, *params.args, *params.kwonlyargs,
                    params.vararg, params.kwarg):
            if arg is not None:
                found[arg.arg] = None
    simple: set[int] = set()  # the targets of simple assignments (each comes after its own)
    for node in nodes:
        if isinstance(node, ast.Name):
            if not isinstance(node.ctx, ast.Load) and id(node) not in simple:
                found[node.id] = None
        elif simple_assignment(node):
            target = node.targets[0]  # type: ignore[attr-defined]
            simple.add(id(target))
            found[target.id] = None if target.id in found else node.value  # type: ignore
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            found[node.name] = None
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            found.update({(a.asname or a.name).split(".")[0]: None for a in node.names})
        elif isinstance(node, (ast.Global, ast.Nonlocal)):
            found.update({name: None for name in node.names})
    return found


def simple_assignment(node: ast.AST) -> bool:
    return (isinstance(node, ast.Assign) and len(node.targets) == 1
            and isinstance(node.targets[0], ast.Name))


def scope_nodes(body: list[ast.stmt]) -> list[ast.AST]:
    """Every node of ``body`` that belongs to this scope (nested defs appear, not their body)."""
    result: list[ast.AST] = []
    stack: list[ast.AST] = list(reversed(body))
    while stack:
        node = stack.pop()
        result.append(node)
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, ast.Lambda)):
            continue
        children = child_nodes(node)
        children.reverse()
        stack += children
    return result


SCOPE_READERS = frozenset({"locals", "vars", "eval", "exec"})
"""Calls that may read any local name of the function making them."""
PATH_VALUES = (ast.Call, ast.BinOp, ast.JoinedStr)
"""The expressions that build a path (``join(...)``, ``share + '/a.yaml'``, an f-string)."""


def unread_values(function: ast.FunctionDef | ast.AsyncFunctionDef, nodes: list[ast.AST]
                  ) -> set[ast.expr]:
    """Path-building values (:data:`PATH_VALUES`) of assignments to a local name ``function``
    never reads: no load of the name anywhere in it (nested functions included), no ``del``,
    no ``global`` or ``nonlocal`` declaration, no ``locals()``, ``vars()``, ``eval`` or
    ``exec`` in it, and no ``:=`` inside the value (the value it names may be read).
    ``nodes`` are the :func:`scope_nodes` of its body. Also the calls of a tuple
    so assigned (``unused = Node(...),``: a trailing comma makes a tuple of the action)."""
    read = _read_names(function)
    if read is None:
        return set()
    found = {node.value for node in nodes  # type: ignore[attr-defined]
             if _names_path(node) and node.targets[0].id not in read}
    for node in nodes:
        if simple_assignment(node) and isinstance(node.value, ast.Tuple) and \
                node.targets[0].id not in read:  # type: ignore[attr-defined]
            found.update(item for item in node.value.elts  # type: ignore[attr-defined]
                         if isinstance(item, ast.Call))
    return found


def _read_names(function: ast.FunctionDef | ast.AsyncFunctionDef) -> set[str] | None:
    """The names ``function`` reads anywhere (nested functions included, ``global`` and
    ``nonlocal`` declarations too); None when it may read any (``locals()``, ``eval``). An
    event handler's ``target_action=name`` is not a read: it watches the action, it does not
    start it (a node named only there never runs)."""
    read: set[str] = set()
    watched = {id(node.value) for node in subtree(function)
               if isinstance(node, ast.keyword) and node.arg == "target_action"}
    for node in subtree(function):
        if isinstance(node, ast.Name) and not isinstance(node.ctx, ast.Store):
            if id(node) not in watched:
                read.add(node.id)
        elif isinstance(node, (ast.Global, ast.Nonlocal)):
            read.update(node.names)
        elif isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and \
                node.func.id in SCOPE_READERS:
            return None
    return read


def _names_path(node: ast.AST) -> bool:
    """True for ``name = value`` with a path-building value (:data:`PATH_VALUES`) holding no
    ``:=`` (the value it names may be read)."""
    return simple_assignment(node) and isinstance(node.value, PATH_VALUES) and \
        not any(isinstance(n, ast.NamedExpr) for n in descendants(node.value))


def unread_module_values(tree: ast.Module, exported: frozenset[str]) -> set[ast.expr]:
    """Path-building values (:data:`PATH_VALUES`) of module-level ``name = value`` statements
    whose name nothing in the module reads (nor declares ``global``, nor lists in
    ``__all__``) and that is not among the ``exported`` names other modules import; none
    when the module may read its names indirectly (``globals()``, ``vars()``, ``eval``)."""
    read = set(exported)
    texts: dict[str, list[ast.Constant]] = {}
    for node in nodes_of_class(tree, ast.Name, ast.Global, ast.Nonlocal, ast.Call, ast.Constant):
        if isinstance(node, ast.Name) and not isinstance(node.ctx, ast.Store):
            read.add(node.id)
        elif isinstance(node, (ast.Global, ast.Nonlocal)):
            read.update(node.names)
        elif isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and \
                node.func.id in SCOPE_READERS | {"globals"}:
            return set()
        elif isinstance(node, ast.Constant) and isinstance(node.value, str):
            texts.setdefault(node.value, []).append(node)  # `__all__ = ['CONFIG']`,
            # getattr(module, 'CONFIG'); not a text of the value itself (`camera =
            # Node(executable='camera')`)
    return {node.value for node in tree.body  # type: ignore[attr-defined]
            if _names_path(node) and node.targets[0].id not in read and
            not _named_elsewhere(texts.get(node.targets[0].id, ()), node.value)}


def _named_elsewhere(texts: Iterable[ast.Constant], value: ast.expr) -> bool:
    """True when one of ``texts`` lies outside ``value``."""
    inside = {id(n) for n in subtree(value)}
    return any(id(text) not in inside for text in texts)


def overwritten_values(function: ast.FunctionDef | ast.AsyncFunctionDef, nodes: list[ast.AST]
                       ) -> set[ast.expr]:
    """Path-building values (:data:`PATH_VALUES`) of assignments to a local name which the
    next statement of the same block naming it binds again without reading it (``path =
    join(...)`` then ``path = '/opt/x'``), or, in the function's own body, which no later
    statement names (``node = Node(...)`` after the description was built): values never
    used. Names a nested function reads,
    and functions that may read their own scope (``locals()``...), are left out. ``nodes``
    are the :func:`scope_nodes` of its body."""
    held: set[str] = set()  # read by a nested scope, or declared global or nonlocal
    for node in nodes:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda, ast.ClassDef)):
            for inner in subtree(node):
                if isinstance(inner, ast.Name):
                    held.add(inner.id)
                elif isinstance(inner, (ast.Global, ast.Nonlocal)):
                    held.update(inner.names)
        elif isinstance(node, (ast.Global, ast.Nonlocal)):
            held.update(node.names)
        elif isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and \
                node.func.id in SCOPE_READERS:
            return set()
    named: dict[int, set[str]] = {}

    def names(statement: ast.AST) -> set[str]:
        if id(statement) not in named:
            named[id(statement)] = {n.id for n in descendants(statement)
                                    if isinstance(n, ast.Name)}
        return named[id(statement)]

    found: set[ast.expr] = set()
    for block in _blocks(function, nodes):
        for at, statement in enumerate(block):
            if not _names_path(statement) or \
                    statement.targets[0].id in held:  # type: ignore[attr-defined]
                continue
            name = statement.targets[0].id  # type: ignore[attr-defined]
            later = next((s for s in block[at + 1:] if name in names(s)), None)
            if later is None and block is function.body or \
                    simple_assignment(later) and name not in names(later.value):
                found.add(statement.value)
    return found


def _blocks(function: ast.FunctionDef | ast.AsyncFunctionDef, nodes: list[ast.AST]
            ) -> list[list[ast.stmt]]:
    """The statement lists of one function scope: its body and the blocks inside it."""
    blocks = [function.body]
    for node in nodes:
        if not isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            blocks += [block for block in (getattr(node, field, None)
                                           for field in ("body", "orelse", "finalbody"))
                       if isinstance(block, list) and block and isinstance(block[0], ast.stmt)]
    return blocks


def unread_attribute_values(tree: ast.Module) -> set[ast.expr]:
    """Path-building values (:data:`PATH_VALUES`) of ``self.x = ...`` where the module never
    reads an attribute ``x`` (nor names a function ``x``, nor reads ``getattr(..., 'x')`` or
    ``__dict__``): values stored and never used."""
    read: set[str] = set()
    stores: list[ast.Assign] = []
    for node in nodes_of_class(tree, ast.Attribute, ast.Assign, ast.Call, ast.FunctionDef,
                               ast.AsyncFunctionDef):
        if isinstance(node, ast.Attribute) and not isinstance(node.ctx, ast.Store):
            read.add(node.attr)
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            read.add(node.name)
        elif isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and \
                node.func.id in ("getattr", "hasattr"):
            read.update(a.value for a in node.args[1:2]
                        if isinstance(a, ast.Constant) and isinstance(a.value, str))
        elif isinstance(node, ast.Assign) and len(node.targets) == 1 and \
                isinstance(node.value, PATH_VALUES) and _on_self(node.targets[0]):
            stores.append(node)
    if "__dict__" in read:
        return set()
    return {node.value for node in stores
            if node.targets[0].attr not in read}  # type: ignore[attr-defined]


def _on_self(target: ast.expr) -> bool:
    return isinstance(target, ast.Attribute) and isinstance(target.value, ast.Name) and \
        target.value.id == "self"


def written_paths(tree: ast.Module) -> set[ast.expr]:
    """Paths the module opens to write (``open(path, 'w')``): the expression given, and the
    values of the names so opened (``urdf = join(share, 'robot.urdf')``, ``open(urdf, 'w')``,
    then ``arguments=[urdf]``: the launch file makes the file it passes on). A file written
    is made by the code, never read from the package."""
    found: set[ast.expr] = set()
    written_names: set[str] = set()
    for call in nodes_of_class(tree, ast.Call):
        if isinstance(call, ast.Call) and isinstance(call.func, ast.Name) and \
                call.func.id == "open" and call.args and opens_to_write(call):
            found.add(call.args[0])
            if isinstance(call.args[0], ast.Name):
                written_names.add(call.args[0].id)
    outputs = _command_outputs(tree)
    named = written_names | {value.id for value in outputs if isinstance(value, ast.Name)}
    found.update(outputs)
    found.update(node.value for node in nodes_of_class(tree, ast.Assign)
                 if simple_assignment(node) and node.targets[0].id in named)  # type: ignore
    return found


def unread_argument_defaults(tree: ast.Module) -> set[ast.expr]:
    """The default values of launch arguments nothing reads: ``DeclareLaunchArgument('model',
    default_value=str(sdf))`` where no other text of the file is ``'model'`` (no
    ``LaunchConfiguration('model')`` but one assigned to a name nothing reads, no
    ``context.launch_configurations['model']``) and the
    file includes no launch file (which could read it); with the values of the names such a
    default alone reads (``sdf = share / 'sdf' / 'robot.sdf'``)."""
    calls = nodes_of_class(tree, ast.Call)
    if any(last_name(call.func) == "IncludeLaunchDescription" for call in calls):
        return set()
    texts: dict[str, int] = {}
    unused = _unused_configurations(tree)
    for constant in nodes_of_class(tree, ast.Constant):
        if isinstance(constant.value, str) and id(constant) not in unused:  # type: ignore
            texts[constant.value] = texts.get(constant.value, 0) + 1  # type: ignore
    found: set[ast.expr] = set()
    for call in calls:
        if last_name(call.func) != "DeclareLaunchArgument":
            continue
        given = {k.arg: k.value for k in call.keywords}  # type: ignore[attr-defined]
        name = call.args[0] if call.args else given.get("name")  # type: ignore[attr-defined]
        default = given.get("default_value")
        if isinstance(name, ast.Constant) and texts.get(name.value) == 1 and default is not None:
            found.add(default)
            found.update(_values_read_only_in(tree, default))
    return found


def _unused_configurations(tree: ast.Module) -> set[int]:
    """The ids of the names in ``x = LaunchConfiguration('name')`` assignments to a name ``x``
    the module never reads: such a configuration is read by nothing."""
    loaded = {n.id for n in nodes_of_class(tree, ast.Name)  # type: ignore[attr-defined]
              if isinstance(n.ctx, ast.Load)}  # type: ignore[attr-defined]
    return {id(node.value.args[0]) for node in nodes_of_class(tree, ast.Assign)  # type: ignore
            if simple_assignment(node) and node.targets[0].id not in loaded  # type: ignore
            and isinstance(node.value, ast.Call) and node.value.args  # type: ignore
            and last_name(node.value.func) == "LaunchConfiguration"}  # type: ignore


def _values_read_only_in(tree: ast.Module, part: ast.expr) -> list[ast.expr]:
    """The values assigned to the names ``part`` reads that nothing else in ``tree`` reads."""
    inside = {n.id for n in descendants(part) if isinstance(n, ast.Name)}
    reads: dict[str, int] = {}
    for node in nodes_of_class(tree, ast.Name):
        if node.id in inside and not isinstance(node.ctx, ast.Store):  # type: ignore
            reads[node.id] = reads.get(node.id, 0) + 1  # type: ignore[attr-defined]
    once = {name for name in inside if reads.get(name) == 1}
    return [node.value for node in nodes_of_class(tree, ast.Assign)  # type: ignore
            if simple_assignment(node) and node.targets[0].id in once]  # type: ignore


_OUTPUT_OPTIONS = frozenset({"-o", "--output", "--out", "--output-file"})
"""Options of command lines naming the file the command writes (``xacro in.xacro -o out``)."""


def _command_outputs(tree: ast.Module) -> list[ast.expr]:
    """The values command list literals give after an output option (``['xacro', src, '-o',
    urdf]``): the file is made by the launch file, whatever else then reads it."""
    return [value for listed in nodes_of_class(tree, ast.List, ast.Tuple)
            for option, value in zip(listed.elts, listed.elts[1:])  # type: ignore[attr-defined]
            if isinstance(option, ast.Constant) and option.value in _OUTPUT_OPTIONS]


def import_origins(tree: ast.Module) -> dict[str, set[str]]:
    """Each name any import of the file binds, with the dotted names it was imported as."""
    origins: dict[str, set[str]] = {}
    for node in nodes_of_class(tree, ast.Import, ast.ImportFrom):
        if isinstance(node, ast.Import):
            for alias in node.names:
                local = alias.asname or alias.name.split(".")[0]
                origins.setdefault(local, set()).add(alias.name if alias.asname else local)
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            for alias in node.names:
                origins.setdefault(alias.asname or alias.name, set()).add(
                    f"{node.module}.{alias.name}")
    return origins


_FED_VALUES = (*PATH_VALUES, ast.Dict, ast.List, ast.Tuple)


def read_only_by(function: ast.FunctionDef | ast.AsyncFunctionDef, nodes: list[ast.AST],
                 dead: set[ast.expr]) -> set[ast.expr]:
    """Path-building values (and dicts, lists and tuples: ``{'robot_description': cmd}``) of
    assignments to a local name whose every read is inside one of the ``dead`` calls (node
    actions never started), and so on for the names those feed: the values never used.
    ``nodes`` are the :func:`scope_nodes` of its body."""
    found: set[ast.expr] = set()
    inside = {id(n) for call in dead for n in descendants(call)}
    while True:
        reads: dict[str, bool] = {}  # name -> every read is inside a dead call
        for node in subtree(function):
            if isinstance(node, ast.Name) and not isinstance(node.ctx, ast.Store):
                reads[node.id] = reads.get(node.id, True) and id(node) in inside
        more = {node.value for node in nodes
                if simple_assignment(node) and isinstance(node.value, _FED_VALUES)
                and reads.get(node.targets[0].id)  # type: ignore[attr-defined]
                and node.value not in found}
        if not more:
            return found
        found |= more
        inside |= {id(n) for call in more for n in descendants(call)}
