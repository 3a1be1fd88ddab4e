"""PYC048: a call of a function, method or class of the package with arguments it cannot bind."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import bases_are_nodes
from pkgtool.rules.python._dataclass_init import dataclass_init
from pkgtool.rules.python._own_callees import (binding_error, defined_once, instance_method,
                                               may_run_own, own_definition, own_method,
                                               rebound_around)
from pkgtool.rules.python._package_modules import imported_from_package, modules_by_name
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, base_names, installed_trees


def _plain_class(cls: ast.ClassDef, index: Index) -> bool:
    """True for a class without decorators, metaclass or ``__new__``, deriving from nothing
    or from rclpy's node classes alone: its own ``__init__`` takes the constructor's
    arguments."""
    return not cls.decorator_list and not cls.keywords and bases_are_nodes(cls, index) and \
        not any(isinstance(s, ast.FunctionDef) and s.name == "__new__" for s in cls.body)


def _callee(call: ast.Call, index: Index, tree: ast.Module, package: Package
            ) -> tuple[ast.FunctionDef, int, str] | None:
    """The function ``call`` certainly runs, the receiver parameters it skips, and how to name
    it: a method of the caller's own class (when no class derives from that class), a
    function of the module or one imported from another module of the package, the
    ``__init__`` of such a class."""
    method = own_method(call, index) or instance_method(call, index, tree)
    if method is not None:
        function, cls = method
        skipped = _receivers(function)
        if cls.name in base_names(package) or skipped is None or not _plain_class(cls, index):
            return None
        return function, skipped, f"{cls.name}.{function.name}"
    found = own_definition(call, index, tree, (ast.FunctionDef, ast.ClassDef))
    if found is None and isinstance(call.func, ast.Name):
        imported = imported_from_package(call.func.id, tree, index, package)
        if imported is not None and not rebound_around(call, call.func.id, index):
            tree, index = modules_by_name(package)[imported[0]]
            found = defined_once(tree, imported[1], (ast.FunctionDef, ast.ClassDef))
    if isinstance(found, ast.FunctionDef):
        return (found, 0, found.name) if not found.decorator_list else None
    if not isinstance(found, ast.ClassDef):
        return None
    made = dataclass_init(found, index)
    if made is not None:
        return made, 1, f"{found.name}.__init__"
    if not _plain_class(found, index):
        return None
    init = defined_once(found, "__init__")
    if not isinstance(init, ast.FunctionDef) or init.decorator_list:
        return None
    return init, 1, f"{found.name}.__init__"


def _receivers(method: ast.FunctionDef) -> int | None:
    """How many leading parameters of ``method`` a call on an instance does not fill: 1 for a
    plain method or a ``@classmethod``, 0 for a ``@staticmethod``; None under any other
    decorator."""
    decorators = [ast.unparse(d) for d in method.decorator_list]
    if decorators in ([], ["classmethod"]):
        return 1
    return 0 if decorators == ["staticmethod"] else None


def _signature(function: ast.FunctionDef) -> str:
    """``name(self, a, b=1, *, c)`` as written (defaults shown as ``=...``)."""
    arguments = ast.unparse(function.args)
    return f"{function.name}({arguments})"


@rule("PYC048", "call-arguments-mismatch", Severity.ERROR,
      fix="Pass what the function takes, or change its parameters")
def call_arguments_mismatch(package: Package) -> Iterator[Hit]:
    """A function, method or class of the package is called with arguments it cannot take.

    ## What it does
    Reports a call that gives more positional arguments than the function takes, leaves out
    a parameter it requires, gives one twice (by position and by keyword) or names a keyword
    it has no parameter for, where the function is certainly the package's own: a plain
    function of the module or one imported from another installed module of the package
    (`from .trajectory import single_point`, `tick(...)`), a plain method (or a
    `@staticmethod`, which receives no instance, or a `@classmethod`) of the caller's own class
    (`self.publish(...)`, when no class derives from that class and nothing assigns
    `self.publish`) or of a name that certainly holds an instance of such a class of the
    module (`node = Talker()`, or a parameter annotated `node: Talker`, bound once:
    `node.publish(...)`), or the `__init__` of such a class deriving from nothing or from rclpy's
    node classes alone (`Talker(...)`), or the `__init__` that `@dataclass` writes for a
    class of plain fields (`Settings(rate=1.0)`). Other decorated functions and classes, calls
    passing `*args` or `**kwargs`, and names any scope around the call rebinds are left
    alone.

    ## Why is this bad?
    Python refuses the call with `TypeError` (`publish() takes 1 positional argument but 2
    were given`) when the line runs: in a callback, the node dies on the first message or
    timer tick; in `main()`, at start-up.

    ## Example
    ```python
    class Talker(Node):
        def __init__(self):
            super().__init__('talker')

    def main():
        node = Talker('talker')
    ```

    ## Use instead
    ```python
    def main():
        node = Talker()
    ```
    """
    for module, tree, index in installed_trees(package):
        for call in index.calls:
            if not may_run_own(call, index, tree):
                continue
            callee = _callee(call, index, tree, package)
            error = binding_error(call, callee[0], callee[1]) if callee else None
            if error is not None:
                assert callee is not None
                yield Hit(Span(module.path, call.lineno, call.col_offset + 1),
                          f"`{ast.unparse(call)}` cannot call `{callee[2]}` "
                          f"(`{_signature(callee[0])}`): {error}{_receiver_note(callee)}, "
                          "Python raises TypeError")


def _receiver_note(callee: tuple[ast.FunctionDef, int, str]) -> str:
    """`` (`target` receives the instance: is `self` missing?)`` for a method whose first
    parameter is not named ``self``."""
    function, skipped, _ = callee
    first = [*function.args.posonlyargs, *function.args.args][:max(skipped, 1)]
    if skipped and first and first[0].arg not in ("self", "cls"):
        return f" (`{first[0].arg}` receives the instance: is `self` missing?)"
    if not skipped and first and first[0].arg == "self":
        return " (a `@staticmethod` receives no instance: its `self` is an argument to give)"
    return ""
