"""Branches of a module that never run on the target Python, decided without running anything.

A test is decided only when it is certain for every Python 3: ``sys.version_info`` (or
SWIG's ``_swig_python_version_info``, which its wrappers import it as; or its
``[0]``/``.major``) compared with constants, ``six.PY2``/``PY2``/``PY3``, literal constants,
a module-level name assigned once to a constant and never again (in a function, also a name
its own body assigns once to a constant that nothing else in the file binds), and
``not``/``and``/``or`` of those. Anything else is undecided (None) and both branches count as
running.

Tests on the ROS version are decided for ROS 2, the build pkgtool checks (packages built by
catkin under ROS 1 and by ament under ROS 2 keep their ROS 1 code under ``if ROS_VERSION ==
1:``): the ``ROS_VERSION`` environment variable (read with ``os.environ[...]``,
``os.environ.get``, ``os.getenv``, as is or through ``int()``) or a name or attribute called
``ROS_VERSION`` (the variable mirroring it, whatever it is assigned from) compared with ``1``
or ``2``.

Tests on the ROS distribution (the ``ROS_DISTRO`` environment variable) are never decided:
:func:`depends_on_ros_distro` tells the rules about API that a ROS release removed or renamed
that both branches hold code written for some distributions only.
"""

from __future__ import annotations

import ast
import operator
from collections import Counter
from collections.abc import Callable

from pkgtool.model.ast_nodes import descendants, enclosing, nodes_of_class, walk_once
from pkgtool.model.memo import per_tree
from pkgtool.lazy_regex import lazy_pattern

_COMPARE = {ast.Lt: operator.lt, ast.LtE: operator.le, ast.Gt: operator.gt,
            ast.GtE: operator.ge, ast.Eq: operator.eq, ast.NotEq: operator.ne}
_PYTHON3 = ((3, 0, 0, "alpha", 0), (3, 99, 99, "final", 0))
"""Two versions that bound every Python 3 a test is asked about."""
_VERSION_NAMES = frozenset({"_swig_python_version_info"})
"""The name SWIG's wrappers import ``sys.version_info`` as (a plain ``version_info`` may be
anything: it is not followed to its import)."""
MODULE_DUNDERS = frozenset({"__name__", "__package__", "__spec__"})


@per_tree
def module_constants(tree: ast.Module) -> dict[str, bool]:
    """Names assigned exactly once in the whole file, at module level, to a constant.

    Computed once per tree; callers must not change the returned dict. Only the names of the
    module-level constant assignments (most modules have none) are counted in the rest.
    """
    candidates = [(node.targets[0].id, value) for node in tree.body
                  if isinstance(node, ast.Assign) and len(node.targets) == 1
                  and isinstance(node.targets[0], ast.Name)
                  and (value := _fixed_value(node.value)) is not None]
    if not candidates:
        return {}
    names = {name for name, _ in candidates}
    stores = Counter(n.id for n in nodes_of_class(tree, ast.Name)  # type: ignore[attr-defined]
                     if n.id in names and not isinstance(n.ctx, ast.Load))  # type: ignore
    stores.update(name for n in nodes_of_class(tree, ast.Global, ast.Nonlocal)
                  for name in n.names if name in names)  # type: ignore[attr-defined]
    return {name: bool(value) for name, value in candidates if stores[name] == 1}


def _fixed_value(value: ast.expr) -> object | None:
    """What a module-level assignment of ``value`` sets on every Python 3: a constant, or a
    test decided there (``_IS_PY2 = sys.version_info.major == 2``); None when not fixed."""
    if isinstance(value, ast.Constant):
        return value.value
    return truth(value, {}) if isinstance(value, (ast.Compare, ast.BoolOp, ast.UnaryOp)) \
        else None


def truth(test: ast.expr, constants: dict[str, bool]) -> bool | None:
    """The value of an ``if`` test on every Python 3, or None when it is not certain."""
    if isinstance(test, ast.Constant):
        return bool(test.value)
    if isinstance(test, ast.UnaryOp) and isinstance(test.op, ast.Not):
        inner = truth(test.operand, constants)
        return None if inner is None else not inner
    if isinstance(test, ast.BoolOp):
        values = [truth(v, constants) for v in test.values]
        wanted = isinstance(test.op, ast.Or)
        if wanted in values:
            return wanted
        return None if None in values else not wanted
    name = _plain_name(test)
    if name in ("PY2", "PY3"):
        return name == "PY3"
    if isinstance(test, ast.Name) and test.id in constants:
        return constants[test.id]
    if not isinstance(test, ast.Compare):
        return None
    version = _version_test(test)
    return _ros_version_test(test) if version is None else version


def _plain_name(node: ast.expr) -> str | None:
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and \
            node.value.id == "six":
        return node.attr
    return None


def _version_test(test: ast.Compare) -> bool | None:
    """``sys.version_info >= (3,)``, ``sys.version_info[0] == 2``, ``.major < 3``..."""
    if len(test.ops) != 1 or type(test.ops[0]) not in _COMPARE:
        return None
    left, right = _version_side(test.left), _constant(test.comparators[0])
    if left is None or right is None:
        return None
    compare = _COMPARE[type(test.ops[0])]
    try:
        results = {compare(left(version), right) for version in _PYTHON3}
    except TypeError:
        return None
    return results.pop() if len(results) == 1 else None


def _version_side(node: ast.expr) -> Callable[[tuple], object] | None:
    """What a test reads of the version tuple: all of ``sys.version_info``, its first item
    (``[0]``, ``.major``) or a prefix (``[:2]``); None for anything else."""
    def is_version_info(n: ast.expr) -> bool:
        return isinstance(n, ast.Attribute) and n.attr == "version_info" and \
            isinstance(n.value, ast.Name) and n.value.id == "sys" or \
            isinstance(n, ast.Name) and n.id in _VERSION_NAMES

    if is_version_info(node):
        return lambda version: version
    if isinstance(node, ast.Subscript) and is_version_info(node.value):
        part = node.slice
        if isinstance(part, ast.Constant) and part.value == 0:
            return lambda version: version[0]
        if isinstance(part, ast.Slice) and part.step is None and \
                (part.lower is None or _constant(part.lower) == 0) and \
                isinstance(end := _constant(part.upper) if part.upper else None, int):
            return lambda version: version[:end]
        return None
    if isinstance(node, ast.Attribute) and node.attr == "major" and is_version_info(node.value):
        return lambda version: version[0]
    return None


def _constant(node: ast.expr) -> tuple[int, ...] | int | None:
    if isinstance(node, ast.Constant) and isinstance(node.value, int):
        return node.value
    if isinstance(node, ast.Tuple) and all(isinstance(e, ast.Constant) and
                                           isinstance(e.value, int) for e in node.elts):
        return tuple(e.value for e in node.elts)  # type: ignore[attr-defined]
    return None


_ROS_VERSION = "ROS_VERSION"
_TARGET_ROS_VERSION = 2


def _ros_version_test(test: ast.Compare) -> bool | None:
    """``os.environ['ROS_VERSION'] == '1'``, ``int(os.getenv('ROS_VERSION')) != 2``,
    ``ROS_VERSION == 1`` (either side), decided for ROS 2."""
    if len(test.ops) != 1 or type(test.ops[0]) not in _COMPARE:
        return None
    left, right = test.left, test.comparators[0]
    kind, constant = _ros_version_side(left), right
    if kind is None:
        kind, constant = _ros_version_side(right), left
        if kind is None:
            return None
        left, right = right, left
    if not isinstance(constant, ast.Constant) or str(constant.value) not in ("1", "2") or \
            isinstance(constant.value, bool):
        return None
    text = isinstance(constant.value, str)
    if kind != "any" and text != (kind == "str"):
        return None  # '2' == 2 is False under ROS 1 too: a bug, not a test on the version
    target: str | int = str(_TARGET_ROS_VERSION) if text else _TARGET_ROS_VERSION
    pair = (target, constant.value) if left is not constant else (constant.value, target)
    return bool(_COMPARE[type(test.ops[0])](*pair))


def _ros_version_side(node: ast.expr) -> str | None:
    """``str`` for a read of the environment variable, ``int`` for one through ``int()``,
    ``any`` for a name or attribute called ``ROS_VERSION``; None for anything else."""
    if isinstance(node, ast.Call) and _is_name(node.func, "int") and len(node.args) == 1:
        return "int" if reads_environment(node.args[0], _ROS_VERSION) else None
    if reads_environment(node, _ROS_VERSION):
        return "str"
    if (isinstance(node, ast.Name) and node.id == _ROS_VERSION) or (
            isinstance(node, ast.Attribute) and node.attr == _ROS_VERSION):
        return "any"
    return None


def mentions_module_name(test: ast.expr) -> bool:
    """The test looks at ``__name__``/``__package__``/``__spec__``: run as script or package."""
    return any(isinstance(n, ast.Name) and n.id in MODULE_DUNDERS for n in descendants(test))


_FUNCTIONS = (ast.FunctionDef, ast.AsyncFunctionDef)


@per_tree
def function_constants(tree: ast.Module) -> dict[int, dict[str, bool]]:
    """By id of a function, its local flags: names a statement of the function's own body
    assigns a constant (``debug = False``), when nothing else in the whole file binds the name
    (no other assignment, no parameter anywhere, no ``global``/``nonlocal``)."""
    candidates = [(function, statement.targets[0].id, statement.value.value)
                  for function in nodes_of_class(tree, *_FUNCTIONS)
                  for statement in function.body  # type: ignore[attr-defined]
                  if isinstance(statement, ast.Assign) and len(statement.targets) == 1
                  and isinstance(statement.targets[0], ast.Name)
                  and isinstance(statement.value, ast.Constant)]
    if not candidates:
        return {}
    names = {name for _, name, _ in candidates}
    binds = Counter(n.id for n in nodes_of_class(tree, ast.Name)  # type: ignore[attr-defined]
                    if n.id in names and not isinstance(n.ctx, ast.Load))  # type: ignore
    binds.update(n.arg for n in nodes_of_class(tree, ast.arg)  # type: ignore[attr-defined]
                 if n.arg in names)  # type: ignore[attr-defined]
    binds.update(name for n in nodes_of_class(tree, ast.Global, ast.Nonlocal)
                 for name in n.names if name in names)  # type: ignore[attr-defined]
    found: dict[int, dict[str, bool]] = {}
    for function, name, value in candidates:
        if binds[name] == 1:
            found.setdefault(id(function), {})[name] = bool(value)
    return found


@per_tree
def dead_expressions(tree: ast.Module) -> list[tuple[tuple[int, int], tuple[int, int]]]:
    """Where the branches of conditional expressions that never run on Python 3 stand
    (``basestring if PY2 else str``), as ((line, column), (end line, end column)), columns
    from 0; treat as read-only."""
    constants = module_constants(tree)
    found = []
    for node in nodes_of_class(tree, ast.IfExp):
        assert isinstance(node, ast.IfExp)
        value = truth(node.test, constants)
        branch = node.body if value is False else node.orelse if value is True else None
        if branch is not None:
            found.append(((branch.lineno, branch.col_offset),
                          (branch.end_lineno or branch.lineno, branch.end_col_offset or 0)))
    return found


@per_tree
def dead_lines(tree: ast.Module) -> list[tuple[int, int]]:
    """Line ranges (first, last) of code that never runs: ``if`` branches that never run on
    Python 3 (also those a function's own constant flag decides: ``debug = False`` then ``if
    debug:``) and statements after a ``return``, ``raise``, ``continue`` or ``break`` of the
    same block or after a ``while True:`` loop without a ``break``, worked out once per tree
    (PYC001, PYC016 and PYC019 ask); treat as read-only."""
    constants = module_constants(tree)
    local = function_constants(tree)
    parents = walk_once(tree).parents if local else {}
    ranges = _after_jumps(tree)
    for node in nodes_of_class(tree, ast.If):
        if isinstance(node, ast.If):
            function = enclosing(node, parents, _FUNCTIONS) if local else None
            flags = local.get(id(function)) if function is not None else None
            value = truth(node.test, {**constants, **flags} if flags else constants)
            branch = node.body if value is False else node.orelse if value is True else []
            if branch:
                ranges.append((branch[0].lineno, branch[-1].end_lineno or branch[-1].lineno))
    return ranges


_JUMPS = (ast.Return, ast.Raise, ast.Continue, ast.Break)
_BLOCKS = ("body", "orelse", "finalbody")
_HOLDERS = tuple(getattr(ast, name) for name in (
    "Module", "FunctionDef", "AsyncFunctionDef", "ClassDef", "If", "For", "AsyncFor", "While",
    "With", "AsyncWith", "Try", "TryStar", "ExceptHandler", "match_case") if hasattr(ast, name))
"""The node classes holding blocks of statements."""


def _after_jumps(tree: ast.Module) -> list[tuple[int, int]]:
    """Line ranges of the statements that follow a jump in the same block, or an endless loop
    (:func:`_endless`), and of the ``else:`` of such a loop."""
    ranges: list[tuple[int, int]] = []
    endless = {id(loop) for loop in nodes_of_class(tree, ast.While) if _endless(loop)}
    for node in nodes_of_class(tree, *_HOLDERS):
        if isinstance(node, ast.While) and id(node) in endless and node.orelse:
            ranges.append((node.orelse[0].lineno,
                           node.orelse[-1].end_lineno or node.orelse[-1].lineno))
        for name in _BLOCKS:
            block = getattr(node, name, None)
            if type(block) is not list or len(block) < 2:
                continue
            jump = next((i for i, s in enumerate(block[:-1])
                         if isinstance(s, _JUMPS) or id(s) in endless), None)
            if jump is not None:
                last = block[-1]
                ranges.append((block[jump + 1].lineno, last.end_lineno or last.lineno))
    return ranges


def _endless(loop: ast.While) -> bool:
    """True for ``while True:`` (or another constant true test) with no ``break`` of its own:
    only a ``return`` or an exception leaves it, and neither runs what follows it."""
    test = loop.test
    if not isinstance(test, ast.Constant) or not test.value:
        return False
    todo: list[ast.AST] = list(loop.body)
    while todo:
        node = todo.pop()
        if isinstance(node, ast.Break):
            return False
        if not isinstance(node, (ast.For, ast.AsyncFor, ast.While, ast.FunctionDef,
                                 ast.AsyncFunctionDef, ast.Lambda, ast.ClassDef)):
            todo.extend(ast.iter_child_nodes(node))
        elif isinstance(node, (ast.For, ast.AsyncFor, ast.While)):
            todo.extend(node.orelse)  # a break in a loop's else leaves the outer loop
    return True


_ROS_DISTRO_VARIABLE = "ROS_DISTRO"


def _reads_ros_distro(node: ast.AST) -> bool:
    """``os.environ['ROS_DISTRO']``, ``os.environ.get('ROS_DISTRO', ...)``, ``os.getenv(...)``
    (also through ``from os import environ, getenv``)."""
    return reads_environment(node, _ROS_DISTRO_VARIABLE)


def reads_environment(node: ast.AST, variable: str) -> bool:
    """``node`` reads the environment variable ``variable`` (as :func:`_reads_ros_distro`)."""
    if isinstance(node, ast.Subscript):
        return _is_environ(node.value) and _names(node.slice, variable)
    if not isinstance(node, ast.Call) or not node.args:
        return False
    func = node.func
    getenv = (isinstance(func, ast.Name) and func.id == "getenv") or (
        isinstance(func, ast.Attribute) and func.attr == "getenv" and _is_name(func.value, "os"))
    get = isinstance(func, ast.Attribute) and func.attr == "get" and _is_environ(func.value)
    return (getenv or get) and _names(node.args[0], variable)


def depends_on_ros_distro(test: ast.expr,
                          assigned: Callable[[str], ast.expr | None] = lambda name: None,
                          depth: int = 0) -> bool:
    """The test reads the ROS distribution: directly, or through names whose one assignment
    (``assigned`` looks it up in the enclosing scopes) reads it, a few names deep (``p =
    subprocess.Popen('echo $ROS_DISTRO', ...)``, ``version = p.communicate()[0]``). Code in
    either branch is written for some distributions only."""
    for node in descendants(test):
        if _reads_ros_distro(node) or depth and isinstance(node, ast.Constant) and \
                isinstance(node.value, str) and _SHELL_DISTRO.search(node.value):
            return True
        if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Load) and depth < 3:
            value = assigned(node.id)
            if value is not None and depends_on_ros_distro(value, assigned, depth + 1):
                return True
    return False


_SHELL_DISTRO = lazy_pattern(r"\$\{?ROS_DISTRO\b|^ROS_DISTRO$")
"""The distribution as a command reads it: ``echo $ROS_DISTRO``, ``['printenv', 'ROS_DISTRO']``."""


def _is_name(node: ast.expr, name: str) -> bool:
    return isinstance(node, ast.Name) and node.id == name


def _is_environ(node: ast.expr) -> bool:
    return _is_name(node, "environ") or (
        isinstance(node, ast.Attribute) and node.attr == "environ" and _is_name(node.value, "os"))


def _names(node: ast.expr, variable: str) -> bool:
    return isinstance(node, ast.Constant) and node.value == variable
