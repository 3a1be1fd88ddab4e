"""Name scopes of the evaluator: module globals, function locals, comprehension variables."""

from __future__ import annotations

from typing import Any

from pkgtool.model.setup_eval.values import Builtin

BUILTIN_NAMES = frozenset({
    "str", "list", "tuple", "dict", "set", "frozenset", "sorted", "len", "range", "enumerate",
    "zip", "reversed", "min", "max", "any", "all", "bool", "int", "print",
})
"""Python builtins the evaluator computes itself (all pure)."""

MODULE_GLOBALS = {"__name__": "__main__"}
"""setup.py runs as a script: ``if __name__ == '__main__':`` is taken."""

_MISSING = object()


class Scope:
    """A mapping of names to evaluated values, falling back to ``parent``."""

    def __init__(self, parent: Scope | None = None) -> None:
        self.names: dict[str, Any] = {} if parent else dict(MODULE_GLOBALS)
        self.parent = parent
        self.declared_global: set[str] = set()

    @property
    def module(self) -> Scope:
        """The outermost (module) scope."""
        return self.parent.module if self.parent else self

    def lookup(self, name: str) -> Any:
        """The value bound to ``name``; raises KeyError when unbound."""
        scope: Scope | None = self
        while scope is not None:
            value = scope.names.get(name, _MISSING)
            if value is not _MISSING:
                return value
            scope = scope.parent
        if name in BUILTIN_NAMES:
            return Builtin(name)
        raise KeyError(name)

    def bind(self, name: str, value: Any) -> None:
        """Bind ``name`` here, or in the module scope if declared ``global``."""
        target = self.module if name in self.declared_global else self
        target.names[name] = value

    def unbind(self, name: str) -> None:
        """Forget ``name`` (``del name``)."""
        self.names.pop(name, None)
