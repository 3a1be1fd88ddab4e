"""PYC004: rclpy attributes that do not exist, such as ``ActionClient.GoalStatus``."""

from __future__ import annotations

import ast
from collections.abc import Iterator
from difflib import get_close_matches

from pkgtool.findings import Hit, Severity, shortened
from pkgtool.knowledge.rclpy_classes import ENUMS, PROPERTIES, SETTLED, attributes_of
from pkgtool.knowledge.rclpy_missing import missing_attribute
from pkgtool.knowledge.rclpy_names import close_name, defined_on, defines
from pkgtool.knowledge.rclpy_node import GOAL_HANDLE_ATTRIBUTES
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.modules import Import
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._attribute_guards import guarded, probed_names
from pkgtool.rules.python._callbacks import callback_arguments
from pkgtool.rules.python._code_and_tests import code_and_test_indexes
from pkgtool.rules.python._message_instances import callback_function
from pkgtool.rules.python._rclpy_objects import object_class, table_class
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import scope_bindings
from pkgtool.rules.syntax_trees import Index, installed_trees, resolved_attributes
from pkgtool.lazy_regex import lazy_pattern


@rule("PYC004", "rclpy-missing-attribute", Severity.ERROR,
      fix="Use the rclpy API that exists (see the message)")
def rclpy_missing_attribute(package: Package) -> Iterator[Hit]:
    """Installed code or a test uses an rclpy attribute that does not exist.

    ## What it does
    Reports reads and imports of rclpy modules and names that do not exist, in installed
    modules and tests: misspelt modules (`from rclpy.nodes import Node`, `import
    rclpy.excutors`), misspelt names (`from rclpy.qos import QoSProfil`,
    `rclpy.executors.SingleThreadExecutor`), checked against the
    modules of rclpy and the names each defines in the target distribution (Humble or Jazzy:
    `from rclpy.event_handler import ...` fails on Humble; for another target, a name Humble,
    Jazzy or Rolling has is accepted); imports under `try/except ImportError` or `if
    TYPE_CHECKING:` are not checked. Also, from a curated table checked against rclpy itself:
    `ActionClient.GoalStatus` (GoalStatus is a message in `action_msgs.msg`), rospy habits
    such as `rclpy.is_shutdown()`, `rclpy.loginfo()`, `rclpy.Node` (also as a module: `from
    rclpy.Node import Node`) or `Time.now()`. Only names bound solely to rclpy imports are
    checked, and not in annotations Python never evaluates (`self.node: rclpy.Node = node` in a
    method, any under `from __future__ import annotations`): a type checker's business.
    Also reports reads of attributes rclpy's `ServerGoalHandle` lacks (`goal_handle.succeeded()`,
    `goal_handle.publish(feedback)`) on the goal handle parameter of an `ActionServer`'s
    execute, cancel or accepted callback, when the callback never rebinds that parameter nor
    stores an attribute on it. And reads of attributes missing on the objects a node makes,
    often rospy habits: `self.timer.start()`, `self.pub.get_num_connections()`,
    `self.get_clock().now().to_sec()`, `executor.spin_some()`, `stamp.sec` on an rclpy
    `Time`, `(now - start).to_sec()` on a `Duration`, `future.get_result()`,
    `self.get_parameter('rate').double_value` (a `Parameter` has `value` and
    `get_parameter_value()`), `goal_handle.is_accepted` on the goal handle an action client's
    goal future holds, and enum
    members that do not exist (`QoSReliabilityPolicy.RELIABLE_RELIABLE`); on a target after
    Jazzy (Kilted, Rolling), whose rclpy may have methods the table lacks, such an object's
    attribute only when it is a typo of one it has or a rospy habit; and calls of a
    property that holds a value (`(now - start).nanoseconds()`: an int). The object's class
    must be certain: what
    `self.create_publisher/subscription/timer/rate/client/service()` or `self.get_clock()`
    return in a class deriving from rclpy's `Node` alone (one that does not define the method
    itself), `self.declare_parameter()`/`get_parameter()`/`get_parameter_or()`, a clock's
    `now()`, `Time(...)`, `Duration(...)`, `Parameter(...)`, an executor
    (`SingleThreadedExecutor()`, `MultiThreadedExecutor()`), a client's `call_async()`, an
    action client's `send_goal_async()`, the result of that future, the
    future a done callback gets, a parameter annotated with one of these classes (`future:
    Future`) and never rebound, and local names or `self.x` every assignment of which gives
    one class (`None` placeholders aside). Attributes are checked against the union of
    Humble's, Jazzy's and Rolling's rclpy; names starting with `_`, names the module probes
    with `hasattr`/`getattr` and reads under `try/except AttributeError` are left alone.

    ## Why is this bad?
    The line raises `AttributeError` or `ImportError` when it runs: at start-up for an
    import, often inside a callback for an attribute, where the error shows up as a log line
    and the node silently stops doing its job.

    ## Example
    ```python
    from rclpy.executors import SingleThreadExecutor
    if status == ActionClient.GoalStatus.STATUS_SUCCEEDED:
    elapsed = self.get_clock().now().to_sec()
    ```

    ## Use instead
    ```python
    from rclpy.executors import SingleThreadedExecutor
    from action_msgs.msg import GoalStatus
    if status == GoalStatus.STATUS_SUCCEEDED:
    elapsed = self.get_clock().now().nanoseconds / 1e9
    ```
    """
    distro = package.context.distro
    yield from _goal_handle_reads(package)
    yield from _object_reads(package)
    for module, index in code_and_test_indexes(package):  # tests fail the same way
        for node, owner, attr in resolved_attributes(index):
            if owner.split(".")[0] != "rclpy" or index.in_unevaluated_annotation(node):
                continue
            span = Span(module.path, node.lineno, node.col_offset + 1)
            use = missing_attribute(owner, attr)
            if use:
                shown = f"{owner.rsplit('.', 1)[-1]}.{attr}"
                where = "" if owner == "rclpy" else " in rclpy"
                yield Hit(span, f"`{shown}` does not exist{where}", f"Use {use}")
            elif not defines(owner, attr, distro):
                yield _missing(span, owner, attr, distro, module=False)
        curated = set()
        for node in index.import_froms:
            owner, _, leaf = (node.module or "").rpartition(".")
            use = missing_attribute(owner, leaf) if node.level == 0 and owner == "rclpy" else None
            if use:  # `from rclpy.Node import Node`: no such module
                curated.add(node.lineno)
                yield Hit(Span(module.path, node.lineno, node.col_offset + 1),
                          f"`{node.module}` does not exist in rclpy", f"Use {use}")
            elif node.level == 0 and node.module:
                for alias in node.names:
                    use = missing_attribute(node.module, alias.name)
                    if use and node.module.split(".")[0] == "rclpy":
                        curated.add(node.lineno)
                        yield Hit(Span(module.path, node.lineno, node.col_offset + 1),
                                  f"`{node.module}` has no `{alias.name}`", f"Use {use}")
        for imported in module.imports:
            if imported.top_level == "rclpy" and not imported.guarded and \
                    imported.span.line not in curated:
                yield from _missing_import(imported, distro)


_HANDLED = frozenset({"execute_callback", "cancel_callback", "handle_accepted_callback"})
"""The ``ActionServer`` callbacks rclpy passes a ``ServerGoalHandle``."""


def _goal_handle_reads(package: Package) -> Iterator[Hit]:
    """Reads of an attribute ``ServerGoalHandle`` lacks, on the goal handle parameter of an
    ``ActionServer`` callback that never rebinds it nor stores attributes on it."""
    for path, value, api, parameter, index, tree in callback_arguments(package):
        found = callback_function(value, tree, index) \
            if api == "ActionServer()" and parameter in _HANDLED else None
        positional = [*found[0].args.posonlyargs, *found[0].args.args] if found else []
        if found is None or len(positional) <= found[1]:
            continue
        name = positional[found[1]].arg
        reads = [n for n in nodes_of_class(found[0], ast.Attribute)
                 if isinstance(n, ast.Attribute) and isinstance(n.value, ast.Name) and
                 n.value.id == name]
        if scope_bindings(found[0])[name] != 1 or \
                any(not isinstance(n.ctx, ast.Load) for n in reads):
            continue
        for node in reads:
            if node.attr not in GOAL_HANDLE_ATTRIBUTES and not node.attr.startswith("_"):
                close = get_close_matches(node.attr, sorted(GOAL_HANDLE_ATTRIBUTES), n=1)
                yield Hit(Span(path, node.lineno, node.col_offset + 1),
                          f"`{name}` is the `ServerGoalHandle` rclpy passes `{ast.unparse(value)}`"
                          f", which has no `{node.attr}`: AttributeError",
                          f"Use `{name}.{close[0]}`" if close else None)


_MEMBER = lazy_pattern(r"[A-Z][A-Z0-9_]*")
"""How the members of rclpy's QoS policy enums are named."""


def _object_reads(package: Package) -> Iterator[Hit]:
    """Reads of an attribute that an rclpy object's class lacks (a timer's `start`), or of a
    member a QoS policy enum lacks."""
    for module, tree, index in installed_trees(package):
        probed = probed_names(index)
        for node in index.attributes:
            if node.attr.startswith("_"):
                continue
            enum = ENUMS.get(index.qualified(node.value) or "") \
                if isinstance(node.value, (ast.Name, ast.Attribute)) else None
            if enum is not None and not _MEMBER.fullmatch(node.attr):
                continue
            cls = enum or object_class(node.value, package, tree, index)
            known = attributes_of(table_class(cls)) if cls is not None else None
            if cls is not None and node.attr in PROPERTIES.get(cls, ()) and \
                    _called(node, index):
                owner = _owner(node.value)
                yield Hit(Span(module.path, node.lineno, node.col_offset + 1),
                          f"`{owner}.{node.attr}` is a property of rclpy's "
                          f"`{cls.rsplit('.', 1)[-1]}` that holds a value, not a method: "
                          "calling it raises TypeError", f"Write `{owner}.{node.attr}`")
                continue
            if known is None or node.attr in known or guarded(node, index, probed) or \
                    index.in_unevaluated_annotation(node):
                continue
            shown = shortened(ast.unparse(node.value))
            use = missing_attribute(table_class(cls), node.attr) if cls else None
            close = get_close_matches(node.attr, sorted(a for a in known if a[0] != "_"), n=1)
            if not (use or close or enum) and package.context.distro not in SETTLED:
                continue  # Kilted's or a later Rolling's rclpy may have it: only typos are sure
            kind = "the enum" if enum else "an rclpy"
            owner = _owner(node.value)
            fix = f"Use {use}" if use else f"Use `{owner}.{close[0]}`" if close else None
            yield Hit(Span(module.path, node.lineno, node.col_offset + 1),
                      f"`{shown}` is {kind} `{cls.rsplit('.', 1)[-1]}`, which has no "
                      f"`{node.attr}`: AttributeError", fix)


def _owner(value: ast.expr) -> str:
    """``value`` as written before ``.attribute``: in parentheses when it needs them."""
    shown = shortened(ast.unparse(value))
    return shown if isinstance(value, (ast.Name, ast.Attribute, ast.Call)) else f"({shown})"


def _called(node: ast.Attribute, index: Index) -> bool:
    """True when ``node`` is the function a call calls (``d.nanoseconds()``)."""
    parent = index.parents.get(id(node))
    return isinstance(parent, ast.Call) and parent.func is node


def _missing_import(imported: Import, distro: str) -> Iterator[Hit]:
    """A hit when the rclpy module ``imported`` loads, or a name it takes, does not exist."""
    for dotted in (imported.module, *(f"{imported.module}.{n}" for n in imported.names)):
        parts = dotted.split(".")
        for depth in range(1, len(parts)):
            owner, name = ".".join(parts[:depth]), parts[depth]
            if name != "*" and not defines(owner, name, distro):
                yield _missing(imported.span, owner, name, distro,
                               module=dotted == imported.module)
                return


def _missing(span: Span, owner: str, name: str, distro: str, *, module: bool) -> Hit:
    """The hit for ``owner.name``, which ``distro``'s rclpy does not define (``module``: as a
    module)."""
    if defines(owner, name):  # another distribution's rclpy has it
        elsewhere = ", ".join(defined_on(owner, name)) or "later distributions"
        return Hit(span, f"`{owner}.{name}` does not exist in {distro}'s rclpy (only in "
                   f"{elsewhere})", "Use what the target distribution has, or guard the "
                   "import with `try/except ImportError`")
    close = close_name(owner, name, distro)
    fix = f"Use `{owner}.{close}`" if close else None
    if module:
        return Hit(span, f"`{owner}.{name}` does not exist: rclpy has no such module", fix)
    return Hit(span, f"`{owner}` has no `{name}`", fix)
