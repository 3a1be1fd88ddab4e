"""PYC086: a dataclass field whose default dataclasses refuse (a list, an array, a message)."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity, shortened
from pkgtool.knowledge.rosdistro import PYTHON_VERSIONS
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees

_ALWAYS = (ast.List, ast.Dict, ast.Set, ast.ListComp, ast.DictComp, ast.SetComp)
"""Displays dataclasses refuse as defaults on every Python."""
_BUILTIN_MAKERS = frozenset({"list", "dict", "set", "bytearray"})
_ARRAY_MAKERS = frozenset({"array", "zeros", "ones", "empty", "full", "eye", "identity",
                           "arange", "linspace", "asarray", "zeros_like", "ones_like",
                           "empty_like", "full_like"})
"""numpy functions that make an ndarray (unhashable: refused from Python 3.11)."""
_INTERFACE_MODULES = frozenset({"msg", "srv", "action"})


@rule("PYC086", "unhashable-dataclass-default", Severity.ERROR,
      fix="Give the field a factory: `field(default_factory=Pose)`, "
          "`field(default_factory=lambda: np.zeros(3))`")
def unhashable_dataclass_default(package: Package) -> Iterator[Hit]:
    """A dataclass field's default is a list, dict, set, NumPy array or ROS message.

    ## What it does
    Reports a field of a `@dataclass` class (annotated, not `ClassVar` or `InitVar`) whose
    default, written directly or as `field(default=...)`, is a list, dict or set (a display,
    a comprehension, `list()`, `dict()`, `set()`), or, when the target's Python is 3.11 or
    newer (Jazzy, Kilted, Rolling), a NumPy array (`np.zeros(3)`, `np.array([...])`) or an
    instance of a ROS interface (`Pose()`: rosidl's classes define `__eq__`, so they are
    unhashable too).

    ## Why is this bad?
    `dataclasses` refuses an unhashable default when the class is created, which is when
    its module is imported: `ValueError: mutable default <class 'geometry_msgs.msg._pose.Pose'>
    for field pose is not allowed: use default_factory`. The node dies before it starts
    (Python 3.11 and newer refuse every unhashable default; older ones only lists, dicts and
    sets, and share one object among all instances).

    ## Example
    ```python
    @dataclass
    class Waypoint:
        pose: Pose = Pose()
        covariance: np.ndarray = np.zeros(6)
    ```

    ## Use instead
    ```python
    @dataclass
    class Waypoint:
        pose: Pose = field(default_factory=Pose)
        covariance: np.ndarray = field(default_factory=lambda: np.zeros(6))
    ```
    """
    python = PYTHON_VERSIONS.get(package.context.distro, "3.12")
    any_unhashable = tuple(int(part) for part in python.split(".")) >= (3, 11)
    for module, _, index in installed_trees(package):
        if not any(i.top_level == "dataclasses" for i in module.imports):
            continue
        for cls in index.classes:
            if not any(_is_dataclass(d, index) for d in cls.decorator_list):
                continue
            for statement in cls.body:
                default = _default(statement, index)
                kind = _refused(default, index, any_unhashable) if default is not None else None
                if kind is not None:
                    assert isinstance(statement, ast.AnnAssign)
                    name = ast.unparse(statement.target)
                    yield Hit(Span(module.path, statement.lineno, statement.col_offset + 1),
                              f"The default of the dataclass field `{name}` is {kind} "
                              f"(`{shortened(ast.unparse(default))}`): creating the class "
                              "raises ValueError (mutable default ... use default_factory) "
                              "when the module is imported")


def _is_dataclass(decorator: ast.expr, index: Index) -> bool:
    """True for ``@dataclass``, ``@dataclasses.dataclass`` and either called with options."""
    target = decorator.func if isinstance(decorator, ast.Call) else decorator
    return isinstance(target, (ast.Name, ast.Attribute)) and \
        index.qualified(target) == "dataclasses.dataclass"


def _default(statement: ast.stmt, index: Index) -> ast.expr | None:
    """The default an annotated field statement gives (also ``field(default=...)``); None for
    a ``ClassVar`` or ``InitVar`` or a field without one."""
    if not isinstance(statement, ast.AnnAssign) or statement.value is None or \
            not isinstance(statement.target, ast.Name):
        return None
    annotation = ast.unparse(statement.annotation)
    if "ClassVar" in annotation or "InitVar" in annotation:
        return None
    value = statement.value
    if isinstance(value, ast.Call) and isinstance(value.func, (ast.Name, ast.Attribute)) and \
            index.qualified(value.func) == "dataclasses.field":
        return next((k.value for k in value.keywords if k.arg == "default"), None)
    return value


def _refused(value: ast.expr, index: Index, any_unhashable: bool) -> str | None:
    """What kind of unhashable value ``value`` is, when dataclasses refuse it."""
    if isinstance(value, _ALWAYS):
        return "a list, dict or set"
    if not isinstance(value, ast.Call) or not isinstance(value.func, (ast.Name, ast.Attribute)):
        return None
    if isinstance(value.func, ast.Name) and value.func.id in _BUILTIN_MAKERS and \
            value.func.id not in index.bound:
        return f"a new {value.func.id}"
    qualified = index.qualified(value.func) or ""
    parts = qualified.split(".")
    if not any_unhashable or len(parts) < 2:
        return None
    if parts[0] == "numpy" and parts[-1] in _ARRAY_MAKERS and len(parts) == 2:
        return "a NumPy array"
    if parts[-2] in _INTERFACE_MODULES or len(parts) > 2 and parts[-3] in _INTERFACE_MODULES:
        return "a ROS message (rosidl's classes are unhashable)"
    return None
