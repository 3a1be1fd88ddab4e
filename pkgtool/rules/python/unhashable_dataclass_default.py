"""PYC086: a dataclass field whose default dataclasses refuse (a list, an array, a message)."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity, shortened
from pkgtool.knowledge.rosdistro import PYTHON_VERSIONS
from pkgtool.model.installed import installed_modules
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees

_ALWAYS = (ast.List, ast.Dict, ast.Set, ast.ListComp, ast.DictComp, ast.SetComp)
"""Displays dataclasses refuse as defaults on every Python."""
_LISTS_DICTS_SETS = frozenset({"list", "dict", "set", "collections.defaultdict",
                               "collections.OrderedDict", "collections.Counter"})
"""Calls making a list, dict or set (or a subclass): refused on every Python."""
_OTHER_UNHASHABLE = frozenset({"bytearray", "collections.deque"})
"""Calls making another unhashable value: refused from Python 3.11."""
_DATACLASS_DECORATORS = frozenset({"dataclasses.dataclass", "pydantic.dataclasses.dataclass"})
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
    a comprehension, `list()`, `dict()`, `set()`, `defaultdict()`, `OrderedDict()`,
    `Counter()`), or, when the target's Python is 3.11 or newer (Jazzy, Kilted, Rolling),
    another unhashable value: a `bytearray()`, a `deque()`, a NumPy array (`np.zeros(3)`,
    `np.array([...])`) or an instance of a ROS interface of another package (`Pose()`:
    rosidl's classes define `__eq__`, so they are unhashable too). Pydantic's dataclasses
    refuse the same defaults.

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
    own = {name.split(".")[0] for name in installed_modules(package) or {}}
    for module, _, index in installed_trees(package):
        if not any(i.top_level in ("dataclasses", "pydantic") for i in module.imports):
            continue
        for cls in index.classes:
            if not any(_is_dataclass(d, index) for d in cls.decorator_list):
                continue
            for statement in cls.body:
                default = _default(statement, index)
                kind = _refused(default, index, any_unhashable, own) \
                    if default is not None else None
                if kind is not None:
                    assert isinstance(statement, ast.AnnAssign)
                    name = ast.unparse(statement.target)
                    when = "the module is imported" if index.enclosing_function(cls) is None \
                        else "the function defining it runs"
                    yield Hit(Span(module.path, statement.lineno, statement.col_offset + 1),
                              f"The default of the dataclass field `{name}` is {kind} "
                              f"(`{shortened(ast.unparse(default))}`): creating the class "
                              "raises ValueError (mutable default ... use default_factory) "
                              f"when {when}")


def _is_dataclass(decorator: ast.expr, index: Index) -> bool:
    """True for ``@dataclass``, ``@dataclasses.dataclass`` and either called with options."""
    target = decorator.func if isinstance(decorator, ast.Call) else decorator
    return isinstance(target, (ast.Name, ast.Attribute)) and \
        index.qualified(target) in _DATACLASS_DECORATORS


def _default(statement: ast.stmt, index: Index) -> ast.expr | None:
    """The default an annotated field statement gives (also ``field(default=...)``); None for
    a ``ClassVar`` or ``InitVar`` or a field without one."""
    if not isinstance(statement, ast.AnnAssign) or statement.value is None or \
            not isinstance(statement.target, ast.Name):
        return None
    if _pseudo_field(statement.annotation, index):
        return None
    value = statement.value
    if isinstance(value, ast.Call) and isinstance(value.func, (ast.Name, ast.Attribute)) and \
            index.qualified(value.func) == "dataclasses.field":
        return next((k.value for k in value.keywords if k.arg == "default"), None)
    return value


_PSEUDO_FIELDS = frozenset({"ClassVar", "InitVar"})


def _pseudo_field(annotation: ast.expr, index: Index) -> bool:
    """True for a ``ClassVar[...]`` or ``InitVar[...]`` annotation (under any import name, or
    written as text): not a field, whose default dataclasses never check."""
    if isinstance(annotation, ast.Constant) and isinstance(annotation.value, str):
        return annotation.value.split("[")[0].rpartition(".")[2] in _PSEUDO_FIELDS
    root = annotation.value if isinstance(annotation, ast.Subscript) else annotation
    if not isinstance(root, (ast.Name, ast.Attribute)):
        return False
    qualified = index.qualified(root) or ast.unparse(root)
    return qualified.rpartition(".")[2] in _PSEUDO_FIELDS


def _refused(value: ast.expr, index: Index, any_unhashable: bool,
             own: set[str]) -> str | None:
    """What kind of unhashable value ``value`` is, when dataclasses refuse it (``own``: the
    package's top-level modules, whose classes are no rosidl interfaces)."""
    if isinstance(value, _ALWAYS):
        return "a list, dict or set"
    if not isinstance(value, ast.Call) or not isinstance(value.func, (ast.Name, ast.Attribute)):
        return None
    builtin = value.func.id if isinstance(value.func, ast.Name) and \
        value.func.id not in index.bound else None
    qualified = builtin or index.qualified(value.func) or ""
    if qualified in _LISTS_DICTS_SETS:
        return f"a new {qualified.rpartition('.')[2]}"
    if not any_unhashable:
        return None
    if qualified in _OTHER_UNHASHABLE:
        return f"a new {qualified.rpartition('.')[2]}"
    parts = qualified.split(".")
    if len(parts) == 2 and parts[0] == "numpy" and parts[-1] in _ARRAY_MAKERS:
        return "a NumPy array"
    if parts[0] not in own and (len(parts) == 3 and parts[1] in _INTERFACE_MODULES or
                                len(parts) == 4 and parts[1] in _INTERFACE_MODULES and
                                parts[3] in ("Request", "Response", "Goal", "Result",
                                             "Feedback")):
        return "a ROS message (rosidl's classes are unhashable)"
    return None
