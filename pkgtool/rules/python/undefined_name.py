"""PYC001: a name used in installed code that is defined nowhere (pyflakes' ``UndefinedName``)."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.lazy_regex import lazy_pattern
from pkgtool.model.ast_nodes import nodes_of, nodes_of_class, walk_once
from pkgtool.model.package import Package, is_test_data
from pkgtool.model.python_visitor import parse_tree
from pkgtool.model.span import Span
from pkgtool.rules.python._names_proof import every_name_defined
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import catches_name_error
from pkgtool.rules.syntax_trees import installed_modules
from pkgtool.rules.test_modules import test_files


def _names_exec(tree: ast.Module) -> bool:
    """True when ``tree`` names ``exec``, which may define any name."""
    return any(isinstance(n, ast.Name) and n.id == "exec"
               for n in nodes_of_class(tree, ast.Name))


@rule("PYC001", "undefined-name", Severity.ERROR,
      fix="Import or define the name before using it")
def undefined_name(package: Package) -> Iterator[Hit]:
    """Installed code, a test, setup.py or a launch file uses a name that is not defined.

    ## What it does
    Runs pyflakes' checker (as a library, on the parsed tree; a quick proof first spares it the
    files where it would surely find nothing) over every installed module, every test module,
    setup.py and every Python launch file (not those calling `exec()`, which may define any
    name, nor a script under `test/` that pytest does not collect and nothing imports: test
    data, which a test may run with `exec()` and names of its own) and reports its "undefined
    name" messages (not for names the module stores through `globals()`, as generated API
    clients' lazy imports do), with pyflakes' own handling of builtins, `__all__`, star
    imports, conditional definitions and `except NameError` guards (also over the functions and
    classes such a `try` defines after reading the bare name: `try: unicode` / `def text(v):
    return isinstance(v, unicode)`); a `try` of one or two assignments whose handler catches
    anything and assigns the same names (`try: text = unicode` / `except Exception: text =
    str`) is such a guard too, and so is a `try` using a ROS 1 module never imported (`rospy`)
    whose handler catches NameError without raising it again (`try: rospy.loginfo(text)` /
    `except Exception: self.get_logger().info(text)`: the ROS 1 path of a node written for
    both). IPython's builtins (`display`, `get_ipython`) are left alone in a module that
    knows when it runs in a notebook (it names IPython, Jupyter, Colab or Kaggle). Code that
    never runs on Python 3 is skipped: branches of `if sys.version_info <
    (3,):`, `if six.PY2:` or of a module constant set once to False, lines after a `return`,
    `raise`, `continue` or `break` of the same block, and annotations Python never evaluates:
    those of assignments in a function body, a string in an annotation (a forward reference,
    `Optional['Pose']`), and every annotation under `from __future__ import annotations` or in
    a project whose pyproject.toml declares Python 3.14 or newer (`requires-python`,
    `[tool.mypy] python_version`, `[tool.ruff] target-version`, a pixi `python` dependency),
    which evaluates annotations only when they are read (PEP 649).

    ## Why is this bad?
    The line raises `NameError` when it runs, which for a node usually means inside a
    callback, long after start-up checks passed; in setup.py it fails the build, in a launch
    file the launch, in a test the test (for a reason that is not what it checks).

    ## Example
    ```python
    import numpy as np
    gray = cv2.cvtColor(image, cv2.COLOR_BGR2GRAY)  # cv2 never imported
    ```

    ## Use instead
    ```python
    import cv2
    import numpy as np
    gray = cv2.cvtColor(image, cv2.COLOR_BGR2GRAY)
    ```
    """
    trees = [(module.path, tree) for module, tree in installed_modules(package)]
    launch = (f.path for f in package.launch_files if f.kind == "python")
    checked = {path for path, _ in trees}
    imported = _imported_names(package)
    for path in dict.fromkeys(("setup.py", *launch, *sorted(test_files(package)))):
        if path in checked or is_test_data(path) and \
                path.rpartition("/")[2].removesuffix(".py") not in imported:
            continue  # a script of test data nothing imports: a test may exec() it
        tree = parse_tree(path, package.texts[path]) if path in package.texts else None
        if isinstance(tree, ast.Module) and not _names_exec(tree):
            trees.append((path, tree))
    lazy = (package.context.python or (3, 0)) >= LAZY_ANNOTATIONS
    for path, tree in trees:
        if every_name_defined(tree):  # pyflakes would find nothing: spare it (most files)
            continue
        seen: set[tuple[int, str]] = set()
        notes = _unevaluated_annotations(tree, lazy=lazy)
        stored = _stored_in_globals(tree)
        for line, column, name in _pyflakes_undefined(path, tree):
            if stored is None or name in stored or \
                    name in _NOTEBOOK_NAMES and _knows_notebooks(tree) or \
                    any(start <= (line, column) <= end for start, end in notes) or \
                    _bound_at_run_time(tree, line, column, name):
                continue
            if (line, name) not in seen:
                seen.add((line, name))
                yield Hit(Span(path, line, column + 1), f"Undefined name `{name}`")


_NOTEBOOK_NAMES = frozenset({"display", "get_ipython", "__IPYTHON__"})
"""Names IPython puts into ``builtins`` in a notebook or an IPython shell."""
_NOTEBOOK_AWARE = lazy_pattern(r"(?i)ipython|colab|kaggle|jupyter|ipykernel")
"""What a module that knows when it runs in a notebook names in its code (``IS_COLAB``,
``'IPython' in sys.modules``, ``import google.colab``): it uses :data:`_NOTEBOOK_NAMES`
only there."""


def _knows_notebooks(tree: ast.Module) -> bool:
    """True when the module's code (not its comments or docstrings) names a notebook."""
    parents = walk_once(tree).parents
    for node in nodes_of(tree):
        text = node.id if isinstance(node, ast.Name) else node.attr \
            if isinstance(node, ast.Attribute) else node.name if isinstance(node, ast.alias) \
            else node.value if isinstance(node, ast.Constant) and \
            isinstance(node.value, str) and not isinstance(parents.get(id(node)), ast.Expr) \
            else None
        if text and _NOTEBOOK_AWARE.search(text):
            return True
    return False


LAZY_ANNOTATIONS = (3, 14)
"""The first Python that evaluates annotations only when they are read (PEP 649)."""
_DEFERRING = frozenset({"add_done_callback", "create_timer", "create_wall_timer",
                        "create_subscription", "create_service", "create_guard_condition",
                        "Thread", "Timer", "Process", "submit", "call_later", "call_soon",
                        "call_soon_threadsafe", "run_in_executor", "after", "connect",
                        "register", "start_new_thread", "partial"})
"""Calls that keep a function to run it later (callbacks, threads, executors)."""
_SCOPES = (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda, ast.ClassDef)
_DEFINITIONS = (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)
_LOOPS = (ast.For, ast.AsyncFor, ast.While)
_BRANCHES = (ast.If, ast.IfExp, ast.BoolOp, ast.Try, ast.ExceptHandler)


def _imported_names(package: Package) -> frozenset[str]:
    """Every module name the package's Python files import (each part of a dotted one) and
    every name they import from one."""
    return frozenset(name for module in package.modules for imported in module.imports
                     for name in ((imported.module or "").split(".") + list(imported.names)))


def _bound_at_run_time(tree: ast.Module, line: int, column: int, name: str) -> bool:
    """True for the kinds of pyflakes' undefined names that Python finds bound: one read
    only where ``'name' in globals()`` holds, or in a function only called there; a local
    read in a loop that assigns it further on (``x = prev + 1`` ... ``prev = x``: bound by
    the pass that reads it, when the first pass skips the read), and the name of an ``except
    ... as name`` read by a lambda that the handler passes to a call that runs it at once
    (pyflakes checks function bodies after the handler, which unbinds the name)."""
    node = _loads(tree).get((line, column))
    if node is None or node.id != name:
        return False
    parents = walk_once(tree).parents
    if _defined_after_probe(node, name, parents):
        return True
    child, parent = node, parents.get(id(node))
    lambdas: list[ast.Lambda] = []
    branched = False  # the read is in a branch some pass may skip
    while parent is not None and not isinstance(parent, _DEFINITIONS):
        if isinstance(parent, ast.ExceptHandler) and parent.name == name:
            return len(lambdas) == 1 and _run_at_once(lambdas[0], parents)
        if isinstance(parent, (ast.If, ast.IfExp)) and child is not parent.test and \
                _asks_defined(parent.test, name):
            return True
        if isinstance(parent, ast.Try) and any(child is s for s in parent.body) and \
                (_compatibility_fallback(parent) or _ros1_path(parent, name)):
            return True
        if isinstance(parent, ast.Lambda):
            lambdas.append(parent)
        elif isinstance(parent, _BRANCHES):
            branched = True
        elif isinstance(parent, _LOOPS) and branched and not lambdas and \
                _stored_after(parent, node):
            return True
        child, parent = parent, parents.get(id(parent))
    return isinstance(parent, (ast.FunctionDef, ast.AsyncFunctionDef)) and not lambdas and \
        _called_only_when_defined(tree, parent, name, parents)


def _defined_after_probe(node: ast.Name, name: str, parents: dict[int, ast.AST]) -> bool:
    """True when ``node`` is inside a function or class defined in the body of a ``try``
    that reads the bare ``name`` first and catches NameError (``try: unicode`` / ``def
    text(v): return isinstance(v, unicode)`` / ``except NameError: ...``): where ``name`` is
    undefined the probe raises, and the definition never happens."""
    child, parent = node, parents.get(id(node))
    while parent is not None:
        if isinstance(parent, ast.Try) and isinstance(child, _DEFINITIONS) and \
                any(child is s for s in parent.body) and \
                any(catches_name_error(h) for h in parent.handlers):
            before = parent.body[:parent.body.index(child)]
            if any(isinstance(s, ast.Expr) and isinstance(s.value, ast.Name) and
                   s.value.id == name for s in before):
                return True
        child, parent = parent, parents.get(id(parent))
    return False


def _called_only_when_defined(tree: ast.Module, function: ast.FunctionDef |
                              ast.AsyncFunctionDef, name: str, parents: dict[int, ast.AST]
                              ) -> bool:
    """True when every use of ``function`` (by its name: ``save()``, ``self.save()``) is a
    call in the body of an ``if 'name' in globals():`` (a module constant left out on
    purpose turns the feature off)."""
    uses = [n for n in nodes_of_class(tree, ast.Name, ast.Attribute)
            if (n.id if isinstance(n, ast.Name) else n.attr) == function.name  # type: ignore
            and isinstance(n.ctx, ast.Load)]  # type: ignore[attr-defined]
    return bool(uses) and all(_guarded_call(use, name, parents) for use in uses)


def _guarded_call(use: ast.AST, name: str, parents: dict[int, ast.AST]) -> bool:
    """True when ``use`` is the function a call calls, inside the body of an ``if`` asking
    whether ``name`` is defined."""
    call = parents.get(id(use))
    if not isinstance(call, ast.Call) or call.func is not use:
        return False
    child, parent = call, parents.get(id(call))
    while parent is not None:
        if isinstance(parent, ast.If) and any(child is s for s in parent.body) and \
                _asks_defined(parent.test, name):
            return True
        child, parent = parent, parents.get(id(parent))
    return False


def _compatibility_fallback(block: ast.Try) -> bool:
    """True for a ``try`` of assignments (two at most) with a handler catching NameError or
    anything that assigns the same names or passes: ``try: text = unicode`` / ``except
    Exception: text = str``, code written for Python 2 and 3 (pyflakes knows ``except
    NameError:`` alone)."""
    if len(block.body) > 2 or not all(isinstance(s, ast.Assign) for s in block.body):
        return False
    assigned = {ast.unparse(target) for s in block.body for target in s.targets}  # type: ignore
    for handler in block.handlers:
        if not catches_name_error(handler) or \
                not all(isinstance(s, (ast.Assign, ast.Pass)) for s in handler.body):
            continue
        fallback = {ast.unparse(target) for s in handler.body if isinstance(s, ast.Assign)
                    for target in s.targets}
        if not fallback or fallback == assigned:
            return True
    return False


_ROS1_MODULES = frozenset({"rospy", "roslib", "rosbag", "rosparam", "rosnode", "rostopic",
                           "rosservice"})
"""ROS 1's Python modules: a dual ROS 1/ROS 2 node may try them without importing them."""


def _ros1_path(block: ast.Try, name: str) -> bool:
    """True for a ROS 1 module read in the body of a ``try`` whose handler catches NameError,
    binds no exception, does something (not ``pass``) and does not raise again: ``try:
    rospy.loginfo(text)`` / ``except: self.get_logger().info(text)``, the ROS 1 path of a
    node written for both, which ROS 2 always skips (a handler reporting the error, ``except
    Exception as error:``, is a port's leftover that always fails)."""
    return name in _ROS1_MODULES and any(
        catches_name_error(handler) and handler.name is None and
        not all(isinstance(s, ast.Pass) for s in handler.body) and
        not any(nodes_of_class(handler, ast.Raise))
        for handler in block.handlers)


def _asks_defined(test: ast.expr, name: str) -> bool:
    """True for ``'name' in globals()`` (or ``locals()``, ``dir()``, ``vars()``)."""
    return isinstance(test, ast.Compare) and isinstance(test.left, ast.Constant) and \
        test.left.value == name and len(test.ops) == 1 and isinstance(test.ops[0], ast.In) and \
        isinstance(test.comparators[0], ast.Call) and \
        isinstance(test.comparators[0].func, ast.Name) and \
        test.comparators[0].func.id in ("globals", "locals", "dir", "vars")


def _loads(tree: ast.Module) -> dict[tuple[int, int], ast.Name]:
    """The names ``tree`` reads, by line and column (from 0)."""
    return {(n.lineno, n.col_offset): n for n in nodes_of_class(tree, ast.Name)
            if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Load)}


def _stored_after(loop: ast.AST, read: ast.Name) -> bool:
    """True when the body of ``loop`` (not a function or class in it) assigns the name
    ``read`` reads after it: later in source order, or as the target of the assignment
    whose value holds the read in a branch (``acc = row if first else acc + row``: stored
    once the value is worked out, by a pass that skipped the read)."""
    found = list(getattr(loop, "body", ()))
    for current in found:
        if isinstance(current, ast.Name) and current.id == read.id and \
                isinstance(current.ctx, ast.Store) and \
                (current.lineno, current.col_offset) > (read.lineno, read.col_offset):
            return True
        if isinstance(current, (ast.Assign, ast.AnnAssign)) and current.value is not None and \
                _in_a_branch_of(current.value, read) and any(
                    isinstance(n, ast.Name) and n.id == read.id
                    for target in (current.targets if isinstance(current, ast.Assign)
                                   else [current.target]) for n in ast.walk(target)):
            return True
        if not isinstance(current, _SCOPES):
            found.extend(ast.iter_child_nodes(current))
    return False


def _in_a_branch_of(value: ast.expr, read: ast.Name) -> bool:
    """True when ``read`` is in a part of ``value`` that may be skipped: a branch of a
    conditional expression, or an operand of ``and``/``or`` after the first."""
    for node in ast.walk(value):
        parts = [node.body, node.orelse] if isinstance(node, ast.IfExp) else \
            node.values[1:] if isinstance(node, ast.BoolOp) else []
        if any(n is read for part in parts for n in ast.walk(part)):
            return True
    return False


def _run_at_once(function: ast.Lambda, parents: dict[int, ast.AST]) -> bool:
    """True when ``function`` is an argument of a call that does not keep it for later."""
    call = parents.get(id(function))
    if isinstance(call, ast.keyword):
        call = parents.get(id(call))
    if not isinstance(call, ast.Call):
        return False
    callee = call.func.attr if isinstance(call.func, ast.Attribute) else \
        call.func.id if isinstance(call.func, ast.Name) else None
    return callee is not None and callee not in _DEFERRING


def _stored_in_globals(tree: ast.Module) -> frozenset[str] | None:
    """Names the module stores through ``globals()``: ``globals()['X'] = X`` (the lazy
    imports of generated OpenAPI clients), ``globals().update(X=...)``,
    ``globals().setdefault('X', ...)``; None (any name) when a key is not a literal."""
    found: set[str] = set()
    for node in nodes_of_class(tree, ast.Subscript, ast.Call):
        target = node.value if isinstance(node, ast.Subscript) else \
            node.func.value if isinstance(node.func, ast.Attribute) else None
        if not (isinstance(target, ast.Call) and isinstance(target.func, ast.Name) and
                target.func.id == "globals" and not target.args):
            continue
        if isinstance(node, ast.Subscript):
            if isinstance(node.ctx, ast.Store):
                found.add(_key(node.slice))
        elif isinstance(node.func, ast.Attribute) and node.func.attr == "setdefault":
            found.add(_key(node.args[0]) if node.args else "*")
        elif isinstance(node.func, ast.Attribute) and node.func.attr == "update":
            found.update(k.arg or "*" for k in node.keywords)
            found.update("*" for _ in node.args)
    return frozenset(found) if "*" not in found else None


def _key(node: ast.expr) -> str:
    """A literal string key, or ``*`` for any other."""
    return node.value if isinstance(node, ast.Constant) and isinstance(node.value, str) \
        else "*"


def _pyflakes_undefined(path: str, tree: ast.Module) -> list[tuple[int, int, str]]:
    """pyflakes' undefined names in ``tree``: (line, column from 0, name), in order."""
    from pyflakes.checker import Checker  # only for files the proof could not clear
    from pyflakes.messages import UndefinedName

    try:
        messages = Checker(tree, filename=path).messages
    except Exception:  # pyflakes on hostile input (deep nesting, ...): skip, never crash
        return []
    return sorted((m.lineno, m.col, m.message_args[0]) for m in messages
                  if isinstance(m, UndefinedName))


def _unevaluated_annotations(tree: ast.Module, *, lazy: bool = False
                             ) -> list[tuple[tuple[int, int], tuple[int, int]]]:
    """Where annotations Python never evaluates stand: every annotation under ``from
    __future__ import annotations`` (PEP 563) or on a Python that evaluates them only when
    read (``lazy``: 3.14, PEP 649), that of an assignment inside a function (PEP 526), and a
    string in any annotation (a forward reference, ``Optional['Pose']``)."""
    ranges: list[tuple[tuple[int, int], tuple[int, int]]] = []
    postponed = lazy or any(isinstance(node, ast.ImportFrom) and node.module == "__future__"
                            and any(alias.name == "annotations" for alias in node.names)
                            for node in tree.body)
    in_functions = {id(node) for function in nodes_of(tree)
                    if isinstance(function, (ast.FunctionDef, ast.AsyncFunctionDef))
                    for node in ast.walk(function) if isinstance(node, ast.AnnAssign)}
    for node in nodes_of(tree):
        if isinstance(node, ast.AnnAssign):
            note: ast.expr | None = node.annotation
            whole = postponed or id(node) in in_functions
        elif isinstance(node, ast.arg):
            note, whole = node.annotation, postponed
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            note, whole = node.returns, postponed
        else:
            continue
        if note is None:
            continue
        parts = [note] if whole else [inner for inner in ast.walk(note)
                                      if isinstance(inner, ast.Constant)
                                      and isinstance(inner.value, str)]
        ranges.extend(((part.lineno, part.col_offset),
                       (part.end_lineno or part.lineno, part.end_col_offset or 0))
                      for part in parts)
    return ranges
