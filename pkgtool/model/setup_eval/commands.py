"""The setuptools commands a setup.py's ``cmdclass`` replaces, and which of the replacements
may do more than setuptools' own command: run programs or write files (``protoc`` generating
``_pb2`` modules before ``install`` goes on), read from the classes setup.py defines."""

from __future__ import annotations

import ast

Commands = tuple[tuple[str, str | None], ...]
"""Each replaced command with the name of the class replacing it (None: not a plain name)."""

_RUNNING = frozenset({"open", "system", "call", "check_call", "check_output", "Popen", "spawn",
                      "run_command", "execute", "copy", "copy2", "copyfile", "copytree",
                      "copy_file", "copy_tree", "move", "write", "write_text", "write_bytes",
                      "make_file", "exec", "eval", "compile", "generate", "build"})
"""Names of calls that run programs or write files."""
_RUNNING_MODULES = frozenset({"subprocess", "shutil", "os"})
"""Modules whose calls in a command class run programs or touch files (not ``os.path``)."""


def command_classes(value: ast.expr) -> Commands | None:
    """The commands a ``cmdclass`` written as a dict display replaces (``{'build_py':
    BuildPy}``, ``dict(install=Install)``) with their classes' names; None for any other
    expression."""
    if isinstance(value, ast.Dict) and all(isinstance(k, ast.Constant) and
                                           isinstance(k.value, str) for k in value.keys):
        return tuple((k.value, _name(v)) for k, v in  # type: ignore[union-attr]
                     zip(value.keys, value.values))
    if isinstance(value, ast.Call) and isinstance(value.func, ast.Name) and \
            value.func.id == "dict" and not value.args and \
            all(k.arg is not None for k in value.keywords):
        return tuple((str(k.arg), _name(k.value)) for k in value.keywords)
    return None


def acting(commands: Commands, module: ast.Module) -> tuple[str, ...]:
    """The commands whose replacement may run programs or write files: a class setup.py does
    not define at its top level (imported, or made by a call), or one whose body, or the body of
    a decorator setup.py defines, makes such a call (:data:`_RUNNING`)."""
    tops = {node.name: node for node in module.body
            if isinstance(node, (ast.ClassDef, ast.FunctionDef))}
    return tuple(command for command, name in commands
                 if not isinstance(tops.get(name or ""), ast.ClassDef) or
                 _runs(tops[name or ""], tops))


def _runs(cls: ast.ClassDef, tops: dict[str, ast.ClassDef | ast.FunctionDef]) -> bool:
    """True when the class, its decorators or the functions of setup.py they call (at any
    depth) make a call of :data:`_RUNNING`, or it has a decorator setup.py does not define."""
    todo: list[ast.AST] = [cls]
    for decorator in cls.decorator_list:
        found = tops.get(_name(decorator) or "")
        if not isinstance(found, ast.FunctionDef):
            return True  # a decorator from elsewhere may do anything
        todo.append(found)
    seen = {id(node) for node in todo}
    while todo:
        for node in ast.walk(todo.pop()):
            if not isinstance(node, ast.Call):
                continue
            if _running(node.func):
                return True
            called = tops.get(_name(node.func) or "")
            if isinstance(called, ast.FunctionDef) and id(called) not in seen:
                seen.add(id(called))
                todo.append(called)
    return False


def _running(func: ast.expr) -> bool:
    if isinstance(func, ast.Name):
        return func.id in _RUNNING
    if isinstance(func, ast.Attribute):
        owner = func.value
        return func.attr in _RUNNING or isinstance(owner, ast.Name) and \
            owner.id in _RUNNING_MODULES and func.attr != "path"
    return True


def _name(node: ast.expr) -> str | None:
    return node.id if isinstance(node, ast.Name) else None
