"""PYC064: an attribute read on an instance of one of the package's own classes that has none
of that name (``self.processor.proces(image)``)."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import typo_of
from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._assignments import (annotated_name, assigned_values, is_none,
                                               parameter_annotation)
from pkgtool.rules.python._attribute_guards import guarded, probed_names
from pkgtool.rules.python._own_callees import rebound_around
from pkgtool.rules.python._package_modules import (imported_from_package, module_names,
                                                   modules_by_name)
from pkgtool.rules.python._value_types import attribute_stores
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import scope_bindings
from pkgtool.rules.syntax_trees import FUNCTIONS, Index, installed_trees

_OPENING = frozenset({"__getattr__", "__getattribute__"})
"""Methods through which a class may have any attribute."""
_DECORATORS = frozenset({"dataclass", "dataclasses.dataclass", "unique", "enum.unique"})
"""Class decorators that add no attribute a user reads (a dataclass's fields are its own)."""
ENUMS = frozenset({"enum.Enum", "enum.Flag"})
"""Bases whose classes get their members from their own body (``IntEnum`` and ``StrEnum``
members have every method of ``int`` and ``str`` too: left alone)."""
ENUM_ATTRIBUTES = frozenset({"name", "value"})
"""What an enum member has besides its class's body (names starting with ``_`` aside)."""
_DEPTH = 8
"""How many bases deep a class is followed."""


@per_package
def _classes(package: Package) -> dict[str, tuple[ast.ClassDef, Index]]:
    """The top-level classes of the installed modules, bound once in their module, by dotted
    name (``my_pkg.vision.Processor``), each with its module's index."""
    found: dict[str, tuple[ast.ClassDef, Index]] = {}
    for module, (tree, index) in modules_by_name(package).items():
        bound = scope_bindings(tree)
        for node in tree.body:
            if isinstance(node, ast.ClassDef) and bound[node.name] == 1:
                found[f"{module}.{node.name}"] = (node, index)
    return found


def _resolved(name: str, index: Index, package: Package) -> str | None:
    """The dotted name of the package class the name ``name`` of the module of ``index``
    stands for: a class it defines, or one it imports (absolutely or relatively) once."""
    classes, where = _classes(package), module_names(package).get(id(index))
    if where is None:
        return None
    if f"{where[0]}.{name}" in classes:
        return f"{where[0]}.{name}"
    tree = modules_by_name(package)[where[0]][0]
    found = imported_from_package(name, tree, index, package)
    return ".".join(found) if found and ".".join(found) in classes else None


def _closed(dotted: str, package: Package, depth: int = 0) -> bool:
    """True when every attribute of the class's instances comes from its body, its bases (all
    closed classes of the package, or ``object``) or stores the package makes."""
    cls, index = _classes(package)[dotted]
    decorators = {ast.unparse(d.func if isinstance(d, ast.Call) else d)
                  for d in cls.decorator_list}
    if depth > _DEPTH or cls.keywords or decorators - _DECORATORS or \
            any(isinstance(s, FUNCTIONS) and s.name in _OPENING for s in cls.body):
        return False
    for base in cls.bases:
        if isinstance(base, ast.Name) and base.id == "object" or \
                isinstance(base, (ast.Name, ast.Attribute)) and index.qualified(base) in ENUMS:
            continue
        found = _resolved(base.id, index, package) if isinstance(base, ast.Name) else None
        if found is None or not _closed(found, package, depth + 1):
            return False
    return True


def _attributes(dotted: str, package: Package) -> set[str]:
    """The names the class body and its bases' bodies bind (and an enum's ``name`` and
    ``value``)."""
    cls, index = _classes(package)[dotted]
    found = set(scope_bindings(cls)) | ENUM_ATTRIBUTES
    for base in cls.bases:
        named = _resolved(base.id, index, package) if isinstance(base, ast.Name) else None
        found |= _attributes(named, package) if named else set()
    return found


def _instance_of(value: ast.expr, package: Package, tree: ast.Module, index: Index
                 ) -> str | None:
    """The closed package class every value assigned to ``value`` (a local name or
    ``self.x``) is made by, ``None`` placeholders aside; or that a parameter is annotated
    with, when nothing rebinds it."""
    assigned_all = assigned_values(value, package, tree, index)
    if assigned_all is None and isinstance(value, ast.Name):
        found = _annotated(value, index, package)
    else:
        made = {_resolved(v.func.id, i, package)
                if isinstance(v, ast.Call) and isinstance(v.func, ast.Name) else None
                for v, i in assigned_all or () if not is_none(v)}
        found = next(iter(made)) if len(made) == 1 else None
    return found if found and _closed(found, package) and \
        "__new__" not in _attributes(found, package) else None  # __new__ may make another


def _annotated(name: ast.Name, index: Index, package: Package) -> str | None:
    """The package class a parameter is annotated with (``grid: Grid``), when the function
    around ``name`` never rebinds it."""
    function = index.enclosing_function(name, through_lambdas=False)
    if function is not None and not _in_body(name, function, index):
        return None  # a decorator, default or annotation: read where the function is defined
    named = annotated_name(parameter_annotation(function, name.id)) if function else None
    return _resolved(named, index, package) if named else None


def _in_body(node: ast.AST, function: ast.FunctionDef | ast.AsyncFunctionDef, index: Index
             ) -> bool:
    """True when ``node`` lies in the body of ``function`` (its own scope), not in its
    decorators, defaults or annotations (``@payload.setter`` above ``def payload(self,
    payload: Payload)`` reads the property of the class body)."""
    child: ast.AST = node
    while (parent := index.parents.get(id(child))) is not None and parent is not function:
        child = parent
    return parent is function and any(child is statement for statement in function.body)


def _class_read(target: ast.expr, node: ast.Attribute, index: Index, package: Package
                ) -> str | None:
    """The closed package class ``target`` names (``Outcome`` in ``Outcome.DONE``), when no
    scope around the read rebinds the name."""
    if not isinstance(target, ast.Name) or rebound_around(node, target.id, index):
        return None
    found = _resolved(target.id, index, package)
    return found if found and _closed(found, package) else None


def _instance_target(target: ast.expr, index: Index) -> bool:
    """True for a read on ``<name>.x`` or on a name (not ``self``, not an import) that may hold
    an instance."""
    if isinstance(target, ast.Attribute):
        return isinstance(target.value, ast.Name)
    return isinstance(target, ast.Name) and target.id not in ("self", "cls") and \
        target.id not in index.aliases


@rule("PYC064", "undefined-instance-attribute", Severity.ERROR,
      fix="Use the attribute the class defines (check the spelling)")
def undefined_instance_attribute(package: Package) -> Iterator[Hit]:
    """Code reads an attribute that one of the package's own classes, or its instance, lacks.

    ## What it does
    In installed modules, reports `x.name` read where `x` is a class of the package
    (`Outcome.DONE`; defined in the module or imported from another module of the package,
    the name rebound nowhere around the read), or a local name, a parameter or `self.x`
    that always holds an instance of one (every assignment of it is `x = Processor(...)`,
    `None` placeholders aside, or the parameter is annotated `x: Processor` and never
    rebound), when the class and its bases bind no `name` and nothing in the package defines
    or stores an attribute `name` anywhere. Only classes whose attributes come from their own
    body, their bases and stores alone are checked: bases from outside the package (`Node`,
    `Exception`, `IntEnum`; `Enum` and `Flag` are fine), a metaclass, class decorators other
    than `@dataclass` and `@unique`, `__getattr__`, and modules storing attributes in ways
    not written as `x.name = ...` (`setattr`, `__dict__`, `__slots__`) leave a class alone;
    so do instances of a class with `__new__` (it may make another), names starting with `_`
    read on a class, names the module probes with `hasattr`/`getattr` and reads inside a
    `try` that catches `AttributeError`. Node classes are PYC023's.

    ## Why is this bad?
    The read raises `AttributeError` when it runs, which in a node usually means in a
    callback: the node logs a traceback on its first message or tick and stops doing its job.

    ## Example
    ```python
    self.processor = ImageProcessor()
    edges = self.processor.detect_edge(image)  # the method is detect_edges
    ```

    ## Use instead
    ```python
    self.processor = ImageProcessor()
    edges = self.processor.detect_edges(image)
    ```
    """
    if not any(not any((index.qualified(b) or "").startswith("rclpy.") for b in cls.bases)
               for _, _, index in installed_trees(package) for cls in index.classes) or \
            not any(_closed(dotted, package) for dotted in _classes(package)):
        return  # no class whose instances' attributes are all known (node classes only)
    everywhere = attribute_stores(package)
    if everywhere is None:
        return
    for module, tree, index in installed_trees(package):
        probed: frozenset[str] | None = None
        for node in index.attributes:
            target = node.value
            if node.attr in everywhere or node.attr.startswith("__"):
                continue
            cls = _class_read(target, node, index, package)
            if cls is None and not _instance_target(target, index):
                continue
            dotted = cls or _instance_of(target, package, tree, index)
            probed = probed_names(index) if probed is None else probed
            if dotted is None or guarded(node, index, probed) or \
                    cls is not None and node.attr.startswith("_") or \
                    node.attr in _attributes(dotted, package):
                continue
            name = dotted.rpartition(".")[2]
            meant = typo_of(node.attr, _attributes(dotted, package))
            hint = f" (did you mean `{meant}`?)" if meant else ""
            what = f"the package's class `{name}`" if cls else \
                f"an instance of the package's class `{name}`"
            yield Hit(Span(module.path, node.end_lineno or node.lineno,
                           (node.end_col_offset or 0) - len(node.attr) + 1),
                      f"`{ast.unparse(target)}` is {what} (`{dotted}`), which has no attribute "
                      f"`{node.attr}`{hint}: nothing defines or stores it, so reading it "
                      "raises AttributeError", f"Write `{meant}`" if meant else None)
