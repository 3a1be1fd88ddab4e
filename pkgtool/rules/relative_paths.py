"""Which file of a package a path relative to some working folder names (LCH012, DAT017), and
the one value a name holding a path is given (DAT017, DAT023)."""

from __future__ import annotations

import ast
import posixpath

from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.package import Package
from pkgtool.rules.scopes import scope_bindings, single_assignments
from pkgtool.rules.syntax_trees import Index


def package_file_named(text: str, package: Package, *, absent: bool = False
                       ) -> tuple[str, bool] | None:
    """The file of ``package`` a relative path names, and whether it is written from a
    workspace's or a repository's folder (``src/<name>/config/x.yaml``,
    ``<name>/config/x.yaml``, ``ws/src/<name>/...``, ``robots/<name>/...``) rather than
    from the package's own (``config/x.yaml``); None for an absolute path or one naming no
    file of the package. With ``absent``, a path through
    a workspace's ``src/<name>/`` names a file of the package even when the package lacks it
    (a model kept out of git: the path still reads the source tree)."""
    if not text or posixpath.isabs(text) or text.startswith(("~", "$")):
        return None
    path = posixpath.normpath(text)
    if package.has_file(path):
        return path, False
    parts = path.split("/")
    for at in range(len(parts) - 1):
        if parts[at] != package.name:
            continue
        inside = "/".join(parts[at + 1:])
        if package.has_file(inside) or absent and at > 0 and parts[at - 1] == "src":
            return inside, True
    return None


def assigned_value(value: ast.expr, index: Index) -> ast.expr:
    """What ``value`` certainly holds: for a name, the one value it is bound to (in the
    innermost function around that binds it, else in the module); for ``self.x`` in a
    method (``self`` its first parameter), the one value every store of ``.x`` in the module
    assigns, all to ``self.x`` in methods of one class; else ``value``."""
    if isinstance(value, ast.Name):
        scopes = [f for f in index.functions_around(value) if scope_bindings(f)[value.id]]
        scope = scopes[0] if scopes else index.module_of(value)
        return single_assignments(scope).get(value.id, value)
    if isinstance(value, ast.Attribute) and _of_self(value, index):
        values = _stored(value, index)
        return values[0] if len(values) == 1 else value
    return value


def _of_self(attribute: ast.Attribute, index: Index) -> bool:
    """True for ``self.x`` in a method of a class, ``self`` being its first parameter."""
    receiver = attribute.value
    method = index.enclosing_function(attribute, through_lambdas=False)
    arguments = [*method.args.posonlyargs, *method.args.args] if method is not None else []
    return isinstance(receiver, ast.Name) and bool(arguments) and \
        arguments[0].arg == receiver.id and index.enclosing_class(method) is not None


def _stored(value: ast.Attribute, index: Index) -> list[ast.expr]:
    """The values of every store of ``.x`` in the module when each is a plain assignment to
    ``self.x`` in a method of the class whose method reads ``self.x`` (else none)."""
    cls = index.enclosing_class(value)
    found: list[ast.expr] = []
    for store in nodes_of_class(index.module_of(value), ast.Attribute):
        assert isinstance(store, ast.Attribute)
        if store.attr != value.attr or isinstance(store.ctx, ast.Load):
            continue
        parent = index.parents.get(id(store))
        if cls is None or not (isinstance(parent, ast.Assign) and parent.targets == [store]) or \
                index.enclosing_class(store) is not cls or not _of_self(store, index):
            return []
        found.append(parent.value)
    return found
