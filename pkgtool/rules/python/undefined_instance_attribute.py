"""PYC064: an attribute read on an instance of one of the package's own classes that has none
of that name (``self.processor.proces(image)``)."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import typo_of
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._assignments import (annotated_name, assigned_values, is_none,
                                               parameter_annotation)
from pkgtool.rules.python._attribute_guards import guarded, probed_names
from pkgtool.rules.python._message_instances import method_receiver
from pkgtool.rules.python._never_called import never_called
from pkgtool.rules.python._own_callees import rebound_around
from pkgtool.rules.python._package_classes import (attributes_of_class, closed_class,
                                                   package_class, package_classes)
from pkgtool.rules.python._value_types import attribute_stores
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, base_names, installed_trees


def _instance_of(value: ast.expr, package: Package, tree: ast.Module, index: Index
                 ) -> str | None:
    """The closed package class every value assigned to ``value`` (a local name or
    ``self.x``) is made by, ``None`` placeholders aside; or that a parameter is annotated
    with, when nothing rebinds it."""
    assigned_all = assigned_values(value, package, tree, index)
    if assigned_all is None and isinstance(value, ast.Name):
        found = _annotated(value, index, package)
    else:
        made = {package_class(v.func.id, i, package)
                if isinstance(v, ast.Call) and isinstance(v.func, ast.Name) else None
                for v, i in assigned_all or () if not is_none(v)}
        found = next(iter(made)) if len(made) == 1 else None
    return found if found and closed_class(found, package) and \
        "__new__" not in attributes_of_class(found, package) else None  # may make another


def _annotated(name: ast.Name, index: Index, package: Package) -> str | None:
    """The package class a parameter is annotated with (``grid: Grid``), when the function
    around ``name`` never rebinds it."""
    function = index.enclosing_function(name, through_lambdas=False)
    if function is not None and not _in_body(name, function, index):
        return None  # a decorator, default or annotation: read where the function is defined
    named = annotated_name(parameter_annotation(function, name.id)) if function else None
    return package_class(named, index, package) if named else None


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
    found = package_class(target.id, index, package)
    return found if found and closed_class(found, package) else None


def _own_class(target: ast.expr, node: ast.Attribute, index: Index, package: Package
               ) -> str | None:
    """The closed package class whose plain method reads ``self.x`` (``target`` is the
    method's receiver), when no class of the package derives from it (a subclass's
    instance may be the receiver)."""
    if not isinstance(target, ast.Name) or target.id != "self":
        return None
    method = index.enclosing_function(node, through_lambdas=False)
    cls = index.parents.get(id(method)) if method is not None else None
    if not isinstance(cls, ast.ClassDef) or method_receiver(method) != "self" or \
            cls.name in base_names(package):
        return None
    found = package_class(cls.name, index, package)
    return found if found and closed_class(found, package) and \
        package_classes(package).get(found, (None,))[0] is cls else None


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
    the name rebound nowhere around the read), `self` in a plain method of such a class that
    no class of the package derives from, or a local name, a parameter or `self.x`
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
    `try` that catches `AttributeError`, and reads in a method nothing in the package names
    (never run, as PYC023 says). Node classes are PYC023's.

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
            not any(closed_class(dotted, package) for dotted in package_classes(package)):
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
            own = _own_class(target, node, index, package) if cls is None else None
            if cls is None and own is None and not _instance_target(target, index):
                continue
            dotted = cls or own or _instance_of(target, package, tree, index)
            probed = probed_names(index) if probed is None else probed
            if dotted is None or guarded(node, index, probed) or \
                    cls is not None and node.attr.startswith("_") or \
                    node.attr in attributes_of_class(dotted, package) or \
                    never_called(package, node, index):
                continue
            name = dotted.rpartition(".")[2]
            meant = typo_of(node.attr, attributes_of_class(dotted, package))
            hint = f" (did you mean `{meant}`?)" if meant else ""
            what = f"the package's class `{name}`" if cls else \
                f"an instance of the package's class `{name}`"
            yield Hit(Span(module.path, node.end_lineno or node.lineno,
                           (node.end_col_offset or 0) - len(node.attr) + 1),
                      f"`{ast.unparse(target)}` is {what} (`{dotted}`), which has no attribute "
                      f"`{node.attr}`{hint}: nothing defines or stores it, so reading it "
                      "raises AttributeError", f"Write `{meant}`" if meant else None)
