"""PYC087: a node's ``__init__`` reads ``self.x`` before anything has assigned it."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rclpy_node import NODE_ATTRIBUTES
from pkgtool.model.ast_nodes import descendants, is_super_init, nodes_of_class, subtree
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import derives_from_node_alone
from pkgtool.rules.python._attribute_guards import dynamic_attributes
from pkgtool.rules.python._certain_code import certain, certain_parts
from pkgtool.rules.python._message_instances import method_receiver
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import FUNCTIONS, Index, base_names, installed_trees

_PARAMETER_CALLBACKS = frozenset({"add_on_set_parameters_callback",
                                  "add_pre_set_parameters_callback",
                                  "add_post_set_parameters_callback"})
"""Node methods registering code that later Node calls (``declare_parameter``) run."""


@rule("PYC087", "attribute-read-too-early", Severity.ERROR,
      fix="Assign the attribute (or call `super().__init__()`) before the line that reads it")
def attribute_read_too_early(package: Package) -> Iterator[Hit]:
    """A node's (or helper class's) `__init__` reads an attribute of `self` before anything
    has set it.

    ## What it does
    Follows the statements of the `__init__` of a class deriving from rclpy's `Node` alone,
    or from nothing (`object`: a helper class of the package), with no decorator, no
    metaclass and not extended by another class of the package, in order, and
    reports a read of `self.x` that certainly runs (not in a branch, a loop body, a `try`, a
    `with`, a lambda or the right of `and`/`or`) before any statement has assigned
    `self.x`, when `x` is not a class attribute, a method or a property of the class, nor an
    attribute of rclpy's `Node`. Also reports a call of one of the Node's methods
    (`self.get_logger()`, `self.declare_parameter(...)`) before the statement calling
    `super().__init__(...)`. The walk stops at the first statement that may run code of the
    package able to set attributes: a call of one of the class's own methods, `self` handed
    to anything (`helper(self)`, `rclpy.spin_once(self)`), a method, local function or lambda
    handed to anything but the node's own `create_*` methods (a thread's target), or a
    parameter callback registered (declaring a parameter runs it). Modules that make
    attributes dynamically (`setattr`, `__getattr__`, `__dict__`) are left alone.

    ## Why is this bad?
    Python creates an instance attribute when it is first assigned, so reading it earlier
    raises `AttributeError: 'Talker' object has no attribute 'period'` and the node dies as
    it is created; a Node's own attributes exist only once `Node.__init__` has run. The
    usual cause is statements moved around: the timer made before the period it uses is
    stored.

    ## Example
    ```python
    class Talker(Node):
        def __init__(self):
            super().__init__('talker')
            self.timer = self.create_timer(self.period, self.tick)
            self.period = 0.5
    ```

    ## Use instead
    ```python
    class Talker(Node):
        def __init__(self):
            super().__init__('talker')
            self.period = 0.5
            self.timer = self.create_timer(self.period, self.tick)
    ```
    """
    extended = base_names(package)
    set_outside: dict[str, set[str]] | None = None
    for module, tree, index in installed_trees(package):
        classes = [c for c in index.classes if (derives_from_node_alone(c, index) or
                                                _plain(c, index))
                   and not c.decorator_list and c.name not in extended]
        if not classes or dynamic_attributes(tree):
            continue
        set_outside = _stored_on_names(package) if set_outside is None else set_outside
        for cls in classes:
            init = _init_of(cls)
            methods = {s.name for s in cls.body if isinstance(s, FUNCTIONS)}
            inherited = frozenset() if _plain(cls, index) else NODE_ATTRIBUTES
            if init is None or method_receiver(init) != "self" or "__new__" in methods or \
                    methods & inherited - {"destroy_node"} or \
                    ANY_NAME in set_outside.get(cls.name, ()):
                continue  # rclpy's Node calls its methods overridden: the package's code runs
            walk = _Walk(cls, init, methods, set_outside.get(cls.name, set()), index,
                         cls.name in set_outside.get(_MADE, ()), inherited)
            for node, message in walk.early_reads():
                yield Hit(Span(module.path, node.lineno, node.col_offset + 1), message)


ANY_NAME = "*"
"""Stands for every attribute: ``setattr(Talker, name, value)`` may make any."""
_MADE = "()"
"""The key of the names of the classes the installed modules call (make instances of)."""


def _stored_on_names(package: Package) -> dict[str, set[str]]:
    """The attributes the installed modules store on a class named so (``Talker.period =
    0.5``, also through an import alias or a module: a class attribute made outside the
    class), by the class's name; :data:`ANY_NAME` for a ``setattr`` on it; under
    :data:`_MADE`, the names of the classes called."""
    stored: dict[str, set[str]] = {}
    for _, tree, index in installed_trees(package):
        for node in nodes_of_class(tree, ast.Attribute):
            assert isinstance(node, ast.Attribute)
            name = _class_name(node.value, index) if not isinstance(node.ctx, ast.Load) \
                else None
            if name is not None:
                stored.setdefault(name, set()).add(node.attr)
        for call in index.calls:
            called = _class_name(call.func, index)
            if called == "setattr" and call.args:
                stored.setdefault(_class_name(call.args[0], index) or "", set()).add(ANY_NAME)
            elif called is not None:
                stored.setdefault(_MADE, set()).add(called)
    return stored


def _class_name(value: ast.expr, index: Index) -> str | None:
    """The last name of what ``value`` names (``Talker`` for ``talker.Talker`` or an alias
    of it), or None for another expression."""
    if isinstance(value, ast.Name):
        return index.aliases.get(value.id, value.id).rpartition(".")[2]
    return value.attr if isinstance(value, ast.Attribute) else None


def _plain(cls: ast.ClassDef, index: Index) -> bool:
    """True for a class deriving from nothing (or ``object``) alone, with no metaclass."""
    return not cls.keywords and (not cls.bases or len(cls.bases) == 1 and isinstance(
        cls.bases[0], ast.Name) and cls.bases[0].id == "object" and "object" not in index.bound)


def _init_of(cls: ast.ClassDef) -> ast.FunctionDef | None:
    """The class's one ``__init__`` (None when it has none, or defines it more than once)."""
    found = [s for s in cls.body if isinstance(s, FUNCTIONS) and s.name == "__init__"]
    return found[0] if len(found) == 1 and isinstance(found[0], ast.FunctionDef) else None


def _class_names(cls: ast.ClassDef) -> set[str]:
    """The names the class body binds (class attributes, methods, properties, imports; not
    an annotation alone), and those its methods store on the class (``cls.x = ...`` in a
    classmethod, ``type(self).x``, ``self.__class__.x``)."""
    names: set[str] = set()
    for statement in cls.body:
        if isinstance(statement, (*FUNCTIONS, ast.ClassDef)):
            names.add(statement.name)
            names.update(node.attr for node in subtree(statement)
                         if isinstance(node, ast.Attribute) and _on_the_class(node.value)
                         and not isinstance(node.ctx, ast.Load))
            continue
        if isinstance(statement, ast.AnnAssign) and statement.value is None:
            continue
        for node in descendants(statement):
            if isinstance(node, ast.Name) and not isinstance(node.ctx, ast.Load):
                names.add(node.id)
            elif isinstance(node, ast.alias):
                names.add((node.asname or node.name).split(".")[0])
    return names


def _on_the_class(value: ast.expr) -> bool:
    """True for ``cls``, ``type(...)`` and ``....__class__``: the class, not an instance."""
    return isinstance(value, ast.Name) and value.id == "cls" or \
        isinstance(value, ast.Call) and isinstance(value.func, ast.Name) and \
        value.func.id == "type" or isinstance(value, ast.Attribute) and value.attr == "__class__"


def _other_super_call(node: ast.AST) -> bool:
    """True for ``super().m(...)`` or ``super(C, self).m(...)`` of a method ``m`` other than
    ``__init__`` (:func:`~pkgtool.model.ast_nodes.is_super_init`)."""
    return isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and \
        isinstance(node.func.value, ast.Call) and isinstance(node.func.value.func, ast.Name) \
        and node.func.value.func.id == "super" and not is_super_init(node)


class _Walk:
    """The walk of one ``__init__``: what the class defines, what the method stored so far."""

    def __init__(self, cls: ast.ClassDef, init: ast.FunctionDef, methods: set[str],
                 set_outside: set[str], index: Index, made: bool,
                 inherited: frozenset[str]) -> None:
        self.init = init
        self.inherited = inherited  # the attributes of its base: rclpy's Node's, or none
        self.cls = cls
        self.index = index
        self.made = made
        self.own = _class_names(cls) | set_outside
        self.methods = methods
        self.assigned = _first_stores(cls, init)
        inside = subtree(init)
        self.local_functions = {n.name for n in inside
                                if isinstance(n, FUNCTIONS) and n is not init} | {
            t.id for n in inside if isinstance(n, ast.Assign)
            and isinstance(n.value, ast.Lambda) for t in n.targets if isinstance(t, ast.Name)}
        self.parents = index.parents

    def early_reads(self) -> Iterator[tuple[ast.AST, str]]:
        """Each certain read before its attribute is assigned, with its message."""
        stored: set[str] = set()
        later = self._super_init_index()
        for number, statement in enumerate(self.init.body):
            stops = self._may_run_package_code(statement)
            for read in self._arguments_first(statement) if stops else certain_parts(statement):
                name = _self_attribute(read)
                if name is None:
                    continue
                if name in self.inherited and name not in self.own:
                    if later is not None and number < later and not name.startswith("_") \
                            and self._called(read):
                        yield read, (f"`self.{name}()` is called before `super().__init__()` "
                                     "has set the Node up: AttributeError")
                elif name not in stored and name not in self.own and name in self.assigned \
                        and (self.assigned[name][1] or self.made):
                    made = "the node is" if self.inherited else f"`{self.cls.name}` is"
                    yield read, (f"`self.{name}` is read before it is assigned ("
                                 f"{self.assigned[name][0]}): AttributeError when {made} "
                                 "created")
            if stops:
                return
            stored.update(node.attr for node in _store_nodes(statement))

    def _arguments_first(self, statement: ast.stmt) -> list[ast.AST]:
        """The nodes certainly evaluated before the call a statement makes (``self.load(path,
        self.logger)``, ``x = f(self.y)``) when none of its arguments may run the package's
        code: they run before the called code could set anything."""
        value = statement.value if isinstance(statement, (ast.Expr, ast.Assign)) else None
        if not isinstance(value, ast.Call):
            return []
        given = [*value.args, *(k.value for k in value.keywords)]
        if any(self._may_run_package_code(ast.Expr(value=part)) for part in given):
            return []
        return [node for part in given for node in certain(part)]

    def _super_init_index(self) -> int | None:
        """The number of the top-level statement of ``__init__`` calling the base's
        ``__init__`` (None when no top-level statement does)."""
        return next((number for number, statement in enumerate(self.init.body)
                     if isinstance(statement, ast.Expr) and (
                         is_super_init(statement.value) or
                         self._base_init(statement.value))), None)

    def _base_init(self, node: ast.AST) -> bool:
        """True for ``Node.__init__(self, ...)``: the base's ``__init__`` called by name."""
        return isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and \
            node.func.attr == "__init__" and bool(self.cls.bases) and \
            ast.dump(node.func.value) == ast.dump(self.cls.bases[0])

    def _called(self, node: ast.AST) -> bool:
        parent = self.parents.get(id(node))
        return isinstance(parent, ast.Call) and parent.func is node

    def _may_run_package_code(self, statement: ast.stmt) -> bool:
        """True when ``statement`` may run code of the package that sets attributes of
        ``self``, now or on another thread."""
        for node in descendants(statement):
            if _other_super_call(node):
                return True
            if isinstance(node, ast.Name) and node.id == "self" and \
                    not self._receiver(node) and not self._in_super(node):
                return True
            if (isinstance(node, ast.Lambda) or isinstance(node, ast.Name) and
                    node.id in self.local_functions and isinstance(node.ctx, ast.Load)) and \
                    not self._given_to_the_node(node):
                return True
            name = _self_attribute(node)
            if name is not None and self._runs_or_hands_on(node, name):
                return True
        return False

    def _runs_or_hands_on(self, node: ast.Attribute, name: str) -> bool:
        """True when ``self.name`` (``node``) registers a parameter callback, calls a method
        of the class or one rclpy's Node lacks, or hands a method of the class to anything
        but the node's own rclpy methods."""
        if name in _PARAMETER_CALLBACKS:
            return True
        if name in self.methods:
            return self._called(node) or not self._given_to_the_node(node)
        return self._called(node) and (name in self.own or name not in self.inherited)

    def _receiver(self, name: ast.Name) -> bool:
        parent = self.parents.get(id(name))
        return isinstance(parent, ast.Attribute) and parent.value is name

    def _in_super(self, name: ast.Name) -> bool:
        """True for ``self`` given to ``super(C, self)`` or first to ``Node.__init__``."""
        parent = self.parents.get(id(name))
        return isinstance(parent, ast.Call) and (
            isinstance(parent.func, ast.Name) and parent.func.id == "super" or
            self._base_init(parent) and parent.args[:1] == [name])

    def _given_to_the_node(self, node: ast.AST) -> bool:
        """True when ``node`` is an argument of a call of one of the node's own rclpy
        methods (``self.create_timer(1.0, self.tick)``), which stores it for later."""
        parent = self.parents.get(id(node))
        if isinstance(parent, ast.keyword):
            parent = self.parents.get(id(parent))
        if not isinstance(parent, ast.Call) or parent.func is node:
            return False
        name = _self_attribute(parent.func)
        return name is not None and name in self.inherited and name not in self.own and \
            name not in _PARAMETER_CALLBACKS


def _self_attribute(node: ast.AST) -> str | None:
    """``x`` for ``self.x`` (read, stored or called), else None."""
    if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and \
            node.value.id == "self":
        return node.attr
    return None


def _store_nodes(node: ast.AST) -> list[ast.Attribute]:
    """The stores of attributes of ``self`` anywhere in ``node`` (not an annotation alone,
    ``self.x: int``, which stores nothing)."""
    found: list[ast.Attribute] = []
    bare: set[int] = set()
    for child in (subtree(node) if isinstance(node, FUNCTIONS) else descendants(node)):
        if isinstance(child, ast.AnnAssign) and child.value is None:
            bare.add(id(child.target))
        elif isinstance(child, ast.Attribute) and isinstance(child.ctx, ast.Store) and \
                _self_attribute(child) is not None:
            found.append(child)
    return [n for n in found if id(n) not in bare]


def _first_stores(cls: ast.ClassDef, init: ast.FunctionDef) -> dict[str, tuple[str, bool]]:
    """Where the class's methods first assign each attribute of ``self``: a line of
    ``__init__`` (True), else the method (False: an attribute only another method assigns,
    in a class the package never makes, may be one its subclasses elsewhere give; those no
    method assigns are PYC023's; ``x += 1`` reads first, so it assigns nothing new)."""
    found: dict[str, tuple[str, bool]] = {}
    lines: dict[str, int] = {}
    for method in cls.body:
        if not isinstance(method, FUNCTIONS):
            continue
        skipped = {id(n.target) for n in subtree(method) if isinstance(n, ast.AugAssign)} \
            if method is init else set()
        for node in _store_nodes(method):
            if method is init and id(node) not in skipped:
                lines[node.attr] = min(lines.get(node.attr, node.lineno), node.lineno)
            elif method is not init:
                found.setdefault(node.attr, (f"in `{method.name}`, which has not run yet", False))
    found.update({name: (f"line {line}", True) for name, line in lines.items()})
    return found
