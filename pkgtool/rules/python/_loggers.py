"""rclpy loggers in a module: ``self.get_logger()``, ``rclpy.logging.get_logger(...)`` and the
names and attributes only ever bound to one, and the calls of their methods."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.memo import per_package
from pkgtool.model.package import Package
from pkgtool.rules.node_api import not_from_rclpy
from pkgtool.rules.python._message_instances import method_receiver
from pkgtool.rules.syntax_trees import FUNCTIONS, Index, base_name, installed_trees

LEVELS = frozenset({"debug", "info", "warning", "warn", "error", "fatal"})
"""The methods of rclpy's logger taking ``(message, **options)``."""
MESSAGE = "message"
"""The name of those methods' one parameter, which a call may also pass by keyword."""
GETTERS = frozenset({"rclpy.logging.get_logger"})


def is_logger_call(node: ast.AST, index: Index, own: frozenset[str] = frozenset()) -> bool:
    """True for ``<x>.get_logger()`` or ``rclpy.logging.get_logger(...)``; not for
    ``self.get_logger()`` in a method of a class named in ``own``
    (:func:`own_logger_classes`), nor for ``<x>.get_logger(name)`` on anything but
    ``rclpy.logging`` (a node's takes no argument: another library's logger factory), nor
    on a name an import binds that is not rclpy's (a module's ``get_logger`` function)."""
    if not isinstance(node, ast.Call):
        return False
    func = node.func
    if index.qualified(func) in GETTERS:
        return True
    if isinstance(func, ast.Attribute) and func.attr == "get_logger":
        return not node.args and not node.keywords and \
            not not_from_rclpy(func.value, index) and \
            (not own or not _own_getter(func.value, index, own))
    return False


def _own_getter(receiver: ast.expr, index: Index, own: frozenset[str]) -> bool:
    """True when ``receiver`` is ``self`` in a plain method of a class named in ``own``."""
    method = index.enclosing_function(receiver, through_lambdas=False)
    cls = index.parents.get(id(method))
    return isinstance(cls, ast.ClassDef) and cls.name in own and \
        isinstance(receiver, ast.Name) and method_receiver(method) == receiver.id


@per_package
def own_logger_classes(package: Package) -> frozenset[str]:
    """The names of the package's classes with a ``get_logger`` of their own (a behaviour
    tree's nodes, a task manager: not rclpy's logger), and of the classes deriving from
    them, by name."""
    classes = [cls for _, _, index in installed_trees(package) for cls in index.classes]
    own = {cls.name for cls in classes if any(
        isinstance(s, FUNCTIONS) and s.name == "get_logger" for s in cls.body)}
    grew = bool(own)
    while grew:
        more = {cls.name for cls in classes if cls.name not in own and any(
            base_name(b) in own for b in cls.bases)}
        own |= more
        grew = bool(more)
    return frozenset(own)


def _logger_names(tree: ast.Module, index: Index, own: frozenset[str]) -> set[str]:
    """Names and ``self.x`` attributes that every binding in the module (assignments, imports,
    parameters) binds to a logger."""
    assigned: dict[str, list[ast.AST]] = {name: [tree] for name in index.aliases}
    for node in nodes_of_class(tree, ast.arg, ast.Assign, ast.AnnAssign, ast.AugAssign, ast.For):
        if isinstance(node, ast.arg):  # a parameter may be any logger
            assigned.setdefault(node.arg, []).append(node)
        targets = node.targets if isinstance(node, ast.Assign) else \
            [node.target] if isinstance(node, (ast.AnnAssign, ast.AugAssign, ast.For)) else []
        value = getattr(node, "value", None) if isinstance(node, (ast.Assign, ast.AnnAssign)) \
            else None
        for target in targets:
            key = _key(target)
            if key is not None:
                assigned.setdefault(key, []).append(value if value is not None else target)
    return {key for key, values in assigned.items()
            if all(is_logger_call(value, index, own) for value in values)}


def _key(node: ast.expr) -> str | None:
    """``x`` for a name, ``.x`` for an attribute of any object (``self.logger``)."""
    if isinstance(node, ast.Name):
        return node.id
    return f".{node.attr}" if isinstance(node, ast.Attribute) else None


def logger_method_calls(tree: ast.Module, index: Index, package: Package
                        ) -> Iterator[tuple[ast.Call, ast.Attribute]]:
    """Each call of a method of an rclpy logger in ``tree`` (``self.get_logger().info(...)``,
    ``self.logger.err(...)``) with its ``func``; dunder methods left out."""
    loggers: set[str] | None = None
    own = own_logger_classes(package)
    for call in index.calls:
        func = call.func
        if not isinstance(func, ast.Attribute) or func.attr.startswith("__"):
            continue
        if not is_logger_call(func.value, index, own):
            if loggers is None:
                loggers = _logger_names(tree, index, own)
            if _key(func.value) not in loggers:
                continue
        yield call, func


def logged_message(call: ast.Call) -> ast.expr | None:
    """The message a logging method call passes, by position or as ``message=``."""
    if call.args:
        return call.args[0]
    return next((k.value for k in call.keywords if k.arg == MESSAGE), None)
