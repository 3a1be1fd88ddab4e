"""PYC023: a Node subclass reads ``self.x`` that nothing ever defines."""

from __future__ import annotations

import ast
from collections.abc import Iterator
from difflib import get_close_matches

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rclpy_node import (LIFECYCLE_NODE_ATTRIBUTES, LIFECYCLE_NODES,
                                          NODE_ATTRIBUTES)
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.records import record
from pkgtool.rules.node_api import derives_from_node_alone
from pkgtool.rules.python._attribute_guards import dynamic_attributes, guarded, probed_names
from pkgtool.rules.python._assignments import (annotated_name, assigned_values, is_none,
                                               parameter_annotation, receiver_store)
from pkgtool.rules.python._message_instances import (attributes_taken, known_messages,
                                                     method_receiver)
from pkgtool.rules.python._messages import message_instances
from pkgtool.rules.python._never_called import never_called
from pkgtool.rules.python._own_callees import defined_once
from pkgtool.rules.python._package_modules import imported_from_package, modules_by_name
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import scope_bindings
from pkgtool.rules.syntax_trees import Index, base_names, installed_trees

_OBJECT_NAMES = frozenset({
    "__class__", "__del__", "__delattr__", "__dict__", "__dir__", "__doc__", "__enter__",
    "__eq__", "__exit__", "__format__", "__ge__", "__getattribute__", "__getstate__", "__gt__",
    "__hash__", "__init__", "__init_subclass__", "__le__", "__lt__", "__module__", "__ne__",
    "__new__", "__reduce__", "__reduce_ex__", "__repr__", "__setattr__", "__sizeof__",
    "__str__", "__subclasshook__", "__weakref__"})
"""What every class has from ``object`` (Python 3.10-3.13), and the context manager methods
rclpy's newer nodes add."""


def _augmented(tree: ast.Module) -> set[int]:
    """The ids of the targets of the module's augmented assignments (``x.n += 1``), which
    read the attribute before they store it, so they do not create it."""
    return {id(n.target) for n in nodes_of_class(tree, ast.AugAssign)
            if isinstance(n, ast.AugAssign)}


@record
class _Stores:
    """The attribute names the installed modules store or delete: on the receiver of a plain
    method of a class (``self.x = ...`` in ``def m(self)``), by id of that class, else on
    anything (``node.x = ...``, which may set any class's)."""

    anywhere: set[str]
    by_class: dict[int, set[str]]

    def of(self, cls: ast.ClassDef) -> set[str]:
        """The names that may be stored on an instance of ``cls`` (a class no class of the
        package extends: another class's ``self`` is never one)."""
        return self.anywhere | self.by_class.get(id(cls), set())


def _message_fields(package: Package, tree: ast.Module, index: Index) -> set[int]:
    """The ids of the attributes taken on known messages in ``tree`` (``goal.pose``)."""
    return {id(use) for instance in message_instances(package, tree, index,
                                                      known_messages(package, index))
            for use in instance.uses}


def _on_message(node: ast.Attribute, fields: set[int]) -> bool:
    """True when ``node`` (``goal.pose.header.frame_id``) stores a field of a known message,
    never an attribute of a node."""
    current: ast.expr = node
    while isinstance(current, ast.Attribute):
        if id(current) in fields:
            return True
        current = current.value
    return False


@per_package
def _package_facts(package: Package) -> tuple[_Stores, frozenset[str]]:
    """What the installed modules store, and the names any class of the package derives
    from."""
    stores = _Stores(set(), {})
    for _, tree, index in installed_trees(package):
        augmented = _augmented(tree)
        fields: set[int] | None = None
        for node in nodes_of_class(tree, ast.Attribute):
            assert isinstance(node, ast.Attribute)
            if isinstance(node.ctx, ast.Load) or id(node) in augmented:
                continue
            fields = _message_fields(package, tree, index) if fields is None else fields
            if _on_message(node, fields):
                continue
            cls = receiver_store(node, index)
            if cls is not None:
                stores.by_class.setdefault(id(cls), set()).add(node.attr)
            else:
                stores.anywhere.add(node.attr)
    return stores, base_names(package)


def _node_classes(package: Package, tree: ast.Module, index: Index, bases: frozenset[str]
                  ) -> Iterator[tuple[ast.ClassDef, str, frozenset[str]]]:
    """Plain classes deriving from rclpy's Node (or LifecycleNode) alone, directly or through
    plain classes of the package (:func:`_lineage`), that no class of the package extends,
    each with the name of rclpy's base and the attributes the bases have."""
    for cls in index.classes:
        if cls.decorator_list or cls.name in bases:
            continue
        found = _lineage(package, cls, tree, index)
        if found is not None:
            yield cls, *found


def _lineage(package: Package, cls: ast.ClassDef, tree: ast.Module, index: Index,
             depth: int = 0) -> tuple[str, frozenset[str]] | None:
    """rclpy's node class ``cls`` derives from through one base at each step, and what its
    bases have: rclpy's attributes, and each package base's names and the attributes it
    stores on ``self`` (a base of the module, or imported from an installed module of the
    package; plain: one base, no decorator, no metaclass, no dynamic attributes)."""
    if len(cls.bases) != 1 or cls.keywords or depth > 4:
        return None
    if derives_from_node_alone(cls, index):
        return "Node", NODE_ATTRIBUTES
    if index.qualified(cls.bases[0]) in LIFECYCLE_NODES:
        return "LifecycleNode", LIFECYCLE_NODE_ATTRIBUTES
    base = cls.bases[0]
    if not isinstance(base, ast.Name) or not depth and not isinstance(
            index.parents.get(id(cls)), ast.Module):
        return None
    parent: ast.AST | None = defined_once(tree, base.id, ast.ClassDef)
    imported = imported_from_package(base.id, tree, index, package) if parent is None else None
    if imported is not None:
        tree, index = modules_by_name(package)[imported[0]]
        parent = defined_once(tree, imported[1], ast.ClassDef)
    if not isinstance(parent, ast.ClassDef) or parent.decorator_list or dynamic_attributes(tree):
        return None
    found = _lineage(package, parent, tree, index, depth + 1)
    if found is None:
        return None
    stored = _package_facts(package)[0].by_class.get(id(parent), set())
    return found[0], found[1] | frozenset(scope_bindings(parent)) | frozenset(stored)


def _suggestion(attr: str, known: set[str]) -> str:
    """`` (did you mean `x`?)`` for the known attribute spelled most like ``attr`` (the
    node's own ``<attr>_node``, as ``destroy_node`` for ``destroy``, first)."""
    if f"{attr}_node" in known:
        return f" (did you mean `{attr}_node`?)"
    close = get_close_matches(attr, sorted(known - NODE_ATTRIBUTES | {
        a for a in NODE_ATTRIBUTES if not a.startswith("_")}), n=1)
    return f" (did you mean `{close[0]}`?)" if close else ""


def _instances(package: Package, tree: ast.Module, index: Index,
               classes: dict[str, ast.ClassDef]
               ) -> Iterator[tuple[ast.FunctionDef | ast.AsyncFunctionDef, str, ast.ClassDef]]:
    """(function, name, class) for each local name that holds an instance of one of
    ``classes``: every assignment of it in its function is ``node = Talker()`` (or None as a
    placeholder), or it is a parameter annotated with the class and never rebound."""
    module_bound = scope_bindings(tree)
    for statement in nodes_of_class(tree, ast.Assign):
        assert isinstance(statement, ast.Assign)
        made, target = statement.value, statement.targets[0]
        cls = classes.get(made.func.id) if isinstance(made, ast.Call) and \
            isinstance(made.func, ast.Name) and module_bound[made.func.id] == 1 and \
            len(statement.targets) == 1 and isinstance(target, ast.Name) else None
        function = index.enclosing_function(statement) if cls is not None else None
        if function is None:
            continue
        assert cls is not None and isinstance(target, ast.Name)
        values = assigned_values(target, package, tree, index)
        if values and all(is_none(v) or isinstance(v, ast.Call) and
                          ast.unparse(v.func) == cls.name for v, _ in values):
            yield function, target.id, cls
    for function in index.functions:
        arguments = function.args
        for parameter in (*arguments.posonlyargs, *arguments.args, *arguments.kwonlyargs):
            cls = classes.get(annotated_name(parameter.annotation) or "")
            if cls is not None and module_bound[cls.name] == 1 and \
                    parameter_annotation(function, parameter.arg) is not None:
                yield function, parameter.arg, cls


def _instance_reads(package: Package, path: str, tree: ast.Module, index: Index,
                    bases: frozenset[str], stored: _Stores, probed: frozenset[str]
                    ) -> Iterator[Hit]:
    """Attributes read on a local name that holds an instance of one of the module's node
    classes (:func:`_instances`) that neither the class nor rclpy's Node (or LifecycleNode)
    has and nothing stores."""
    found = list(_node_classes(package, tree, index, bases))
    kinds = {cls.name: (base, inherited) for cls, base, inherited in found}
    classes = {cls.name: cls for cls, _, _ in found}
    if not classes:
        return
    for function, name, cls in _instances(package, tree, index, classes):
        base, inherited = kinds[cls.name]
        known = set(scope_bindings(cls)) | stored.of(cls) | inherited
        reads: dict[str, list[Span]] = {}
        for node in attributes_taken(function, name):
            if isinstance(node.ctx, ast.Load) and not node.attr.startswith("__") and \
                    node.attr not in known and not guarded(node, index, probed):
                reads.setdefault(node.attr, []).append(Span(
                    path, node.end_lineno or node.lineno,
                    (node.end_col_offset or 0) - len(node.attr) + 1))
        for attr, spans in reads.items():
            yield Hit(spans[0], f"`{name}` is a `{cls.name}`, which has no attribute "
                      f"`{attr}`{_suggestion(attr, known)}: nothing assigns it and "
                      f"rclpy's {base} has none, so reading it raises AttributeError",
                      related=tuple(spans[1:]))


@rule("PYC023", "undefined-node-attribute", Severity.ERROR,
      fix="Use the attribute the class assigns (check the spelling), or assign it in "
          "`__init__`")
def undefined_node_attribute(package: Package) -> Iterator[Hit]:
    """A `Node` subclass reads an attribute of `self` that nothing ever defines.

    ## What it does
    In installed modules, looks at the classes deriving from `rclpy.node.Node` or
    `rclpy.lifecycle.Node` alone (no other base, no decorator, no metaclass, extended by no
    class of the package), directly or through such plain classes of the package (`class
    Avoider(ScanAgent)`, `ScanAgent` deriving from `Node` in the module or another installed
    module), and reports `self.x` read in their plain methods when `x` is not a method or
    class attribute of the class or of its package bases, nor stored on `self` by them, not
    an attribute of rclpy's `Node` or
    `LifecycleNode` (any of Humble to Rolling), and nothing may
    assign or delete it on an instance of the class: neither the class's own methods through
    `self`, nor any installed module of the package through anything but a method's `self`
    (`self.x = ...` in another class's method stores on that class's instances only, and
    `goal.pose.header.frame_id = ...` on a message a field). An
    augmented assignment, `self.x += 1`, reads `x` first, so it counts as a read. Modules
    using `setattr`, `delattr`, `exec`, `vars`, `__dict__`, `__getattr__`, `__setattr__` or
    `__slots__`, names they pass to `hasattr`/`getattr`, and reads inside a `try` that
    catches `AttributeError` are left alone. The same goes for `node.x` read on a local name
    that holds an instance of such a class (`node = Talker()`, None as a placeholder aside,
    or a parameter annotated `node: Talker` and never rebound): `node.destroy()` for
    `node.destroy_node()`. So does `super().x` in those classes' methods when neither their
    bases nor `object` have `x` (`super().__int__('talker')`, `super().spin()`). Reads in a
    method nothing in the package names, even with a typo (no call, no bound method handed
    to a timer, no `getattr` string: its caller commented out, copied from another node),
    that overrides nothing of rclpy's nodes and has no decorator, never run. Typical
    causes: a misspelt callback
    (`self.timer_calback`), a publisher stored as `self.publisher_` and used as
    `self.publisher`, a method renamed but not its uses.

    ## Why is this bad?
    The read raises `AttributeError` when it runs: at start-up for a callback passed to
    `create_timer` or `create_subscription`, or inside a callback, where the node dies on
    its first message or tick.

    ## Example
    ```python
    self.publisher_ = self.create_publisher(String, 'chatter', 10)
    self.timer = self.create_timer(0.5, self.timer_calback)

    def timer_callback(self):
        self.publisher.publish(String(data='hi'))
    ```

    ## Use instead
    ```python
    self.publisher_ = self.create_publisher(String, 'chatter', 10)
    self.timer = self.create_timer(0.5, self.timer_callback)

    def timer_callback(self):
        self.publisher_.publish(String(data='hi'))
    ```
    """
    facts: tuple[_Stores, frozenset[str]] | None = None
    for module, tree, index in installed_trees(package):
        if not any(i.top_level == "rclpy" for i in module.imports) and \
                not any(cls.bases for cls in index.classes) or dynamic_attributes(tree):
            continue  # neither rclpy's classes nor subclasses of the package's
        facts = facts or _package_facts(package)
        stored, bases = facts
        probed = probed_names(index)
        augmented = _augmented(tree)
        yield from _instance_reads(package, module.path, tree, index, bases, stored, probed)
        for cls, base, inherited in _node_classes(package, tree, index, bases):
            known = set(scope_bindings(cls)) | stored.of(cls) | inherited
            reads: dict[str, list[ast.Attribute]] = {}
            for method in cls.body:
                receiver = method_receiver(method)
                for node in attributes_taken(method, receiver) if receiver else ():
                    if (isinstance(node.ctx, ast.Load) or id(node) in augmented) and \
                            not node.attr.startswith("__") and node.attr not in known and \
                            not guarded(node, index, probed) and \
                            not never_called(package, node, index):
                        reads.setdefault(node.attr, []).append(node)
            for attr, nodes in reads.items():
                spans = [Span(module.path, n.end_lineno or n.lineno,
                              (n.end_col_offset or 0) - len(attr) + 1) for n in nodes]
                if any(attr in names for names in stored.by_class.values()):
                    yield Hit(spans[0], f"`{cls.name}` never assigns `self.{attr}` (another "
                              "class of the package does, for its own instances) and rclpy's "
                              f"{base} has none, so reading it raises AttributeError",
                              f"Assign `self.{attr}` in `{cls.name}.__init__`",
                              related=tuple(spans[1:]))
                    continue
                hint = _suggestion(attr, known)
                yield Hit(spans[0], f"`{cls.name}` has no attribute `{attr}`{hint}: nothing "
                          f"assigns `self.{attr}` and rclpy's {base} has none, so reading it "
                          "raises AttributeError", related=tuple(spans[1:]))
            yield from _super_reads(module.path, cls, base, inherited, index)


def _super_reads(path: str, cls: ast.ClassDef, base: str, inherited: frozenset[str],
                 index: Index) -> Iterator[Hit]:
    """``super().x`` in the class's methods where neither its bases nor ``object`` have
    ``x`` (``super().__int__('talker')``); not in a class defined inside a method, whose
    ``super()`` is its own."""
    known = inherited | _OBJECT_NAMES
    methods = [m for m in cls.body if isinstance(m, (ast.FunctionDef, ast.AsyncFunctionDef))]
    for node in (n for m in methods for n in nodes_of_class(m, ast.Attribute)):
        assert isinstance(node, ast.Attribute)
        call = node.value
        if isinstance(call, ast.Call) and isinstance(call.func, ast.Name) and \
                call.func.id == "super" and not call.args and node.attr not in known and \
                index.enclosing_class(node) is cls:
            hint = _suggestion(node.attr, set(known))
            yield Hit(Span(path, node.end_lineno or node.lineno,
                           (node.end_col_offset or 0) - len(node.attr) + 1),
                      f"`super().{node.attr}`: no base of `{cls.name}` (rclpy's {base} and "
                      f"the package's) has `{node.attr}`{hint}, so reading it raises "
                      "AttributeError")
