"""The package's own classes (PYC064, PYC072): the top-level classes of its installed modules,
what a name stands for among them, and whether every attribute of their instances is known."""

from __future__ import annotations

import ast

from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.rules.python._package_modules import (imported_from_package, module_names,
                                                   modules_by_name)
from pkgtool.rules.scopes import scope_bindings
from pkgtool.rules.syntax_trees import FUNCTIONS, Index

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
def package_classes(package: Package) -> dict[str, tuple[ast.ClassDef, Index]]:
    """The top-level classes of the installed modules, bound once in their module, by dotted
    name (``my_pkg.vision.Processor``), each with its module's index."""
    found: dict[str, tuple[ast.ClassDef, Index]] = {}
    for module, (tree, index) in modules_by_name(package).items():
        bound = scope_bindings(tree)
        for node in tree.body:
            if isinstance(node, ast.ClassDef) and bound[node.name] == 1:
                found[f"{module}.{node.name}"] = (node, index)
    return found


def package_class(name: str, index: Index, package: Package) -> str | None:
    """The dotted name of the package class the name ``name`` of the module of ``index``
    stands for: a class it defines, or one it imports (absolutely or relatively) once."""
    classes, where = package_classes(package), module_names(package).get(id(index))
    if where is None:
        return None
    if f"{where[0]}.{name}" in classes:
        return f"{where[0]}.{name}"
    tree = modules_by_name(package)[where[0]][0]
    found = imported_from_package(name, tree, index, package)
    return ".".join(found) if found and ".".join(found) in classes else None


def closed_class(dotted: str, package: Package, depth: int = 0) -> bool:
    """True when every attribute of the class's instances comes from its body, its bases (all
    closed classes of the package, or ``object``) or stores the package makes."""
    cls, index = package_classes(package)[dotted]
    decorators = {ast.unparse(d.func if isinstance(d, ast.Call) else d)
                  for d in cls.decorator_list}
    if depth > _DEPTH or cls.keywords or decorators - _DECORATORS or \
            any(isinstance(s, FUNCTIONS) and s.name in _OPENING for s in cls.body):
        return False
    for base in cls.bases:
        if isinstance(base, ast.Name) and base.id == "object" or \
                isinstance(base, (ast.Name, ast.Attribute)) and index.qualified(base) in ENUMS:
            continue
        found = package_class(base.id, index, package) if isinstance(base, ast.Name) else None
        if found is None or not closed_class(found, package, depth + 1):
            return False
    return True


def attributes_of_class(dotted: str, package: Package) -> set[str]:
    """The names the class body and its bases' bodies bind (and an enum's ``name`` and
    ``value``)."""
    cls, index = package_classes(package)[dotted]
    found = set(scope_bindings(cls)) | ENUM_ATTRIBUTES
    for base in cls.bases:
        named = package_class(base.id, index, package) if isinstance(base, ast.Name) else None
        found |= attributes_of_class(named, package) if named else set()
    return found
