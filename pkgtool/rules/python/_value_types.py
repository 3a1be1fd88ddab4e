"""The type a local name or a node's ``self.x`` certainly holds where it is read.

A name (or attribute) has a certain type when every binding of it gives a literal of one
type (``count = 0``) or the result of a builtin conversion (``int(x)``, ``len(x)``), or keeps
that type (``count += 1``: ``+``, ``-``, ``*`` of two ints, floats or strings), or every
binding is a node's ``self.get_parameter(...)`` (rclpy's ``Parameter`` object, not its
value), or the text of one (``str(self.get_parameter(...))``), or a parameter's value of
a known type: ``.get_parameter_value().double_value`` (and the other scalar fields), or
``self.get_parameter('x').value`` where the node class declares ``x`` once with a scalar
literal default, statically typed (rclpy then refuses a value of another type). Any other
binding (a parameter, a loop target, another call's result, an import, ``global``,
``setattr``) leaves it unknown. When a local name's assignments disagree, the one a read
certainly sees in straight-line code decides (``msg = String()``, then ``msg = 'hi'``, then
a read of ``msg``: a str; :mod:`._reaching`).
"""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.knowledge.rclpy_node import NODE_ATTRIBUTES
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.memo import per_package, per_tree
from pkgtool.model.package import Package
from pkgtool.rules.node_api import (INTERFACE, NODE_CLASSES, derives_from_node_alone,
                                    literal_type)
from pkgtool.rules.node_parameters import module_nodes
from pkgtool.rules.python._message_instances import binding_counts, method_receiver
from pkgtool.rules.python._reaching import reaching_store
from pkgtool.rules.syntax_trees import FUNCTIONS, Index, installed_tree_of, installed_trees
from pkgtool.lazy_regex import lazy_pattern

PARAMETER = "Parameter"
"""The type of what a node's ``get_parameter()`` returns (``rclpy.parameter.Parameter``)."""
PARAMETER_TEXT = "str (a Parameter object's repr)"
"""The type of ``str()`` of a node's ``self.get_parameter(...)``, or of an f-string formatting
one: a str, ``<rclpy.parameter.Parameter object at 0x...>``, not the parameter's value."""
_BUILTINS = {"int": "int", "float": "float", "str": "str", "bool": "bool", "len": "int",
             "list": "list", "dict": "dict", "set": "set", "tuple": "tuple",
             "frozenset": "frozenset"}
"""Builtins whose call always gives a value of one type, and that type."""
_WITHOUT_ARGUMENTS = frozenset(_BUILTINS) - {"len"}
"""The builtins of :data:`_BUILTINS` that may be called with no argument (``list()``)."""
_INTERFACE_CLASS = lazy_pattern(
    INTERFACE.pattern + r"(\.(Request|Response|Goal|Result|Feedback))?")
"""An imported message, service or action class, or one of the messages of the latter two."""
NUMBER_TYPES = frozenset({"int", "float", "bool"})
"""The certain types that are numbers (a bool adds and compares as one)."""
_UNKNOWN = "?"
_KEEPING = (ast.Add, ast.Sub, ast.Mult)
"""Augmented operators that give an int for two ints, a float for two floats (``/`` does
not) and a str for two strs (``+=`` of a list or tuple display keeps a list or tuple too)."""
_DYNAMIC = frozenset({"setattr", "vars", "__dict__", "__setattr__", "__slots__"})
"""Names whose use in a module means attributes may be stored unseen."""


def parameter_read(value: ast.expr | None) -> bool:
    """True for a call ``<x>.get_parameter(...)``."""
    return isinstance(value, ast.Call) and isinstance(value.func, ast.Attribute) and \
        value.func.attr == "get_parameter"


def receiver_class(name: ast.expr, index: Index) -> ast.ClassDef | None:
    """The class whose plain method ``name`` (a name) is the receiver of, ``self`` in
    ``self.x``, when that method is the function right around it (no lambda nearer)."""
    method = index.enclosing_function(name, through_lambdas=False)
    cls = index.parents.get(id(method)) if method is not None else None
    return cls if isinstance(cls, ast.ClassDef) and isinstance(name, ast.Name) and \
        method_receiver(method) == name.id else None


def _builtin_result(value: ast.expr, index: Index) -> str | None:
    """The type a call of one of :data:`_BUILTINS` with one argument (or none, but ``len``)
    gives, when the module binds its name nowhere; :data:`PARAMETER_TEXT` for ``str()`` of a
    node's ``get_parameter()``."""
    if not isinstance(value, ast.Call) or not isinstance(value.func, ast.Name) or \
            value.func.id not in _BUILTINS or value.func.id in index.bound or value.keywords \
            or len(value.args) > 1 or any(isinstance(a, ast.Starred) for a in value.args) or \
            not value.args and value.func.id not in _WITHOUT_ARGUMENTS:
        return None
    if value.args and value.func.id == "str" and _made_type(value.args[0], index) == PARAMETER:
        return PARAMETER_TEXT
    return _BUILTINS[value.func.id]


_ACCESSORS = {"bool_value": "bool", "integer_value": "int", "double_value": "float",
              "string_value": "str"}
"""The scalar fields of a ``ParameterValue`` and the Python type each holds."""
_DECLARED = {"BOOL": "bool", "INTEGER": "int", "DOUBLE": "float", "STRING": "str"}
"""Scalar parameter types and the Python type a parameter's ``.value`` then has."""


@per_package
def _declared_types(package: Package) -> dict[tuple[int, str, str], str]:
    """(id of a module's index, class name, parameter) -> the Python type of the parameter's
    value, for the scalar parameters a node class declares once, statically typed (rclpy
    refuses a value of another type, from a parameter file too)."""
    nodes = module_nodes(package)
    found: dict[tuple[int, str, str], str] = {}
    for module, _, index in installed_trees(package):
        for cls in nodes[module.path].classes if module.path in nodes else ():
            kinds: dict[str, set[str | None]] = {}
            for declared in cls.declared:
                kinds.setdefault(declared.name, set()).add(declared.type)
            found.update(((id(index), cls.name, name), _DECLARED[types.pop()])
                         for name, types in kinds.items()
                         if len(types) == 1 and next(iter(types)) in _DECLARED)
    return found


def _parameter_value_type(value: ast.expr, index: Index, package: Package | None
                          ) -> str | None:
    """The type of ``<x>.get_parameter(...).get_parameter_value().double_value`` (and the other
    scalar fields), and of ``self.get_parameter('name').value`` in a node class declaring
    ``name`` with a scalar default (``package`` given)."""
    if not isinstance(value, ast.Attribute):
        return None
    typed = value.value
    if value.attr in _ACCESSORS and isinstance(typed, ast.Call) and \
            isinstance(typed.func, ast.Attribute) and typed.func.attr == "get_parameter_value" \
            and parameter_read(typed.func.value):
        return _ACCESSORS[value.attr]
    if value.attr != "value" or package is None or not parameter_read(value.value):
        return None
    call = value.value
    assert isinstance(call, ast.Call) and isinstance(call.func, ast.Attribute)
    cls = receiver_class(call.func.value, index)
    name = call.args[0] if len(call.args) == 1 and not call.keywords else None
    if cls is None or not isinstance(name, ast.Constant) or not isinstance(name.value, str):
        return None
    return _declared_types(package).get((id(index), cls.name, name.value))


def _made_type(value: ast.expr, index: Index, package: Package | None = None) -> str | None:
    """The type of a literal or of a builtin conversion's result, ``type`` for an imported
    message, service or action class, or :data:`PARAMETER` for ``self.get_parameter(...)``
    in a method of a node class (in a module not defining a ``get_parameter`` of its own),
    :data:`PARAMETER_TEXT` for the text of one."""
    if isinstance(value, ast.JoinedStr) and any(
            isinstance(part, ast.FormattedValue) and part.format_spec is None and
            _made_type(part.value, index) == PARAMETER for part in value.values):
        return PARAMETER_TEXT
    found = literal_type(value) or _builtin_result(value, index) or \
        _parameter_value_type(value, index, package)
    if found is None and isinstance(value, (ast.Name, ast.Attribute)) and \
            _INTERFACE_CLASS.fullmatch(index.qualified(value) or ""):
        return "type"  # an imported message class itself (`String`, not `String()`)
    if found is not None or not parameter_read(value):
        return found
    cls = receiver_class(value.func.value, index)  # type: ignore[attr-defined]
    if cls is not None and any(index.qualified(b) in NODE_CLASSES for b in cls.bases) and \
            not index.defines_function("get_parameter"):
        return PARAMETER
    return None


def _bound_type(target: ast.expr, index: Index, package: Package | None = None) -> str:
    """The type the binding ``target`` (a name or attribute being stored) gives."""
    parent = index.parents.get(id(target))
    if isinstance(parent, ast.Assign) and any(t is target for t in parent.targets) or \
            isinstance(parent, ast.AnnAssign) and parent.target is target:
        return (_made_type(parent.value, index, package) if parent.value is not None
                else None) or \
            _UNKNOWN
    if isinstance(parent, ast.AugAssign) and parent.target is target and (
            isinstance(parent.op, _KEEPING) and literal_type(parent.value) in
            ("int", "float", "str") or isinstance(parent.op, ast.Add) and
            literal_type(parent.value) in ("list", "tuple")):
        return literal_type(parent.value) or _UNKNOWN
    return _UNKNOWN


def _one(types: set[str]) -> str | None:
    return next(iter(types)) if len(types) == 1 and _UNKNOWN not in types else None


def _targets(statement: ast.AST) -> list[ast.expr]:
    """What an assignment statement (``=``, annotated, augmented) assigns; [] for others."""
    return statement.targets if isinstance(statement, ast.Assign) else \
        [statement.target] if isinstance(statement, (ast.AnnAssign, ast.AugAssign)) else []


@per_tree
def _assigned_names(tree: ast.Module) -> dict[str, list[ast.Name]]:
    """The names assignment statements of ``tree`` bind directly (``n = ...``, ``n: int =
    ...``, ``n += ...``; not unpacked), by name."""
    found: dict[str, list[ast.Name]] = {}
    for statement in nodes_of_class(tree, ast.Assign, ast.AnnAssign, ast.AugAssign):
        for target in _targets(statement):
            if isinstance(target, ast.Name):
                found.setdefault(target.id, []).append(target)
    return found


def _local_type(name: ast.Name, tree: ast.Module, index: Index, package: Package | None = None
                ) -> str | None:
    """The type of a function's local ``name`` when all its bindings agree on one, or when
    they disagree, the type of the one the read certainly sees (:mod:`._reaching`)."""
    stores = _assigned_names(tree).get(name.id)
    function = index.enclosing_function(name, through_lambdas=False) if stores else None
    if function is None:
        return None
    start, end = function.lineno, function.end_lineno or function.lineno
    assigned = [n for n in stores or ()
                if start <= n.lineno <= end and
                index.enclosing_function(n, through_lambdas=False) is function]
    if not assigned or len(assigned) != binding_counts(function)[name.id] or \
            any(isinstance(n, ast.Nonlocal) and name.id in n.names
                for n in nodes_of_class(tree, ast.Nonlocal)):
        return None  # also a parameter, an import, a loop target, `global`, a nested scope
    found = _one({_bound_type(n, index, package) for n in assigned})
    if found is None and len(assigned) > 1:  # the bindings disagree: the one the read sees
        reaching = reaching_store(name, assigned, index)
        found = _one({_bound_type(reaching, index, package)}) if reaching is not None else None
    return found


def _dynamic(tree: ast.Module, index: Index) -> bool:
    """True when the module calls ``setattr``/``exec``/``vars``, defines ``__setattr__`` or
    assigns ``__slots__`` (``__dict__`` is looked for with the stores)."""
    return any(isinstance(c.func, ast.Name) and c.func.id in (*_DYNAMIC, "exec")
               for c in index.calls) \
        or any(f.name in _DYNAMIC for f in index.functions) or "__slots__" in \
        _assigned_names(tree)


def _class_attributes(cls: ast.ClassDef) -> Iterator[str]:
    """The names a class body assigns or defines at its top level."""
    for statement in cls.body:
        if isinstance(statement, (*FUNCTIONS, ast.ClassDef)):
            yield statement.name
        yield from (t.id for t in _targets(statement) if isinstance(t, ast.Name))


@per_package
def attribute_stores(package: Package) -> dict[str, list[tuple[ast.expr, Index]]] | None:
    """The attributes the installed modules store, by name, with the index of the module of
    each; a class body's attribute counts as a store of no known type. None when a module
    may store attributes unseen."""
    found: dict[str, list[tuple[ast.expr, Index]]] = {}
    for _, tree, index in installed_trees(package):
        if _dynamic(tree, index):
            return None
        for node in nodes_of_class(tree, ast.Attribute):
            if isinstance(node, ast.Attribute) and not isinstance(node.ctx, ast.Load):
                found.setdefault(node.attr, []).append((node, index))
            elif isinstance(node, ast.Attribute) and node.attr in _DYNAMIC:
                return None
        for cls in index.classes:
            for name in _class_attributes(cls):
                found.setdefault(name, []).append((cls, index))
    return found


@per_package
def _attribute_types(package: Package) -> dict[str, str | None]:
    """The type of each attribute name, filled as rules ask (every read of ``self.x`` would
    otherwise look at every store of ``x`` in the package again)."""
    return {}


def _attribute_type(package: Package, name: str) -> str | None:
    """The one type every store of an attribute ``name`` in the package gives, if any."""
    known = _attribute_types(package)
    if name not in known:
        stores = attribute_stores(package)
        known[name] = _one({_bound_type(node, index, package)
                            for node, index in stores.get(name, ())}) if stores else None
    return known[name]


def _node_attribute_type(value: ast.Attribute, package: Package, index: Index) -> str | None:
    """The type of ``self.x`` read in a method of a class deriving from rclpy's Node alone, in
    an installed module (:func:`attribute_stores` knows the stores of those only: a script
    kept in ``resource/`` or ``scripts/`` may store ``x`` otherwise)."""
    if value.attr in NODE_ATTRIBUTES or id(index) not in installed_tree_of(package):
        return None
    cls = receiver_class(value.value, index)
    if cls is None or not derives_from_node_alone(cls, index):
        return None
    return _attribute_type(package, value.attr)


def certain_type(value: ast.expr, package: Package, tree: ast.Module, index: Index, *,
                 texts: bool = False) -> str | None:
    """The type ``value`` certainly has: a literal's, :data:`PARAMETER` for a node's
    ``self.get_parameter(...)``, a local name's or a node attribute's all of whose bindings
    give that one type; None when not certain. The text of a ``Parameter`` is a ``str``, or
    with ``texts`` :data:`PARAMETER_TEXT`."""
    found = _made_type(value, index, package)
    if found is None and isinstance(value, ast.Name):
        found = _local_type(value, tree, index, package)
    elif found is None and isinstance(value, ast.Attribute) and isinstance(value.ctx, ast.Load):
        found = _node_attribute_type(value, package, index)
    return "str" if found == PARAMETER_TEXT and not texts else found
