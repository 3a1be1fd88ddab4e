"""PYC069: tf2_ros given a number where it wants an rclpy ``Duration``, or the node where it
wants the buffer."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import argument, unpacks
from pkgtool.rules.python._value_types import NUMBER_TYPES, certain_type
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import Index, installed_trees

_TIMEOUTS = {"lookup_transform": ("target_frame", "source_frame", "time", "timeout"),
             "can_transform": ("target_frame", "source_frame", "time", "timeout"),
             "lookup_transform_full": ("target_frame", "target_time", "source_frame",
                                       "source_time", "fixed_frame", "timeout"),
             "can_transform_full": ("target_frame", "target_time", "source_frame",
                                    "source_time", "fixed_frame", "timeout")}
"""tf2_ros ``Buffer`` methods (Humble to Rolling) taking a ``timeout`` Duration, with their
positional parameters."""
_LISTENERS = frozenset({"tf2_ros.TransformListener",
                        "tf2_ros.transform_listener.TransformListener"})


_NEEDS_NODE = frozenset({
    *_LISTENERS, "tf2_ros.TransformBroadcaster",
    "tf2_ros.transform_broadcaster.TransformBroadcaster", "tf2_ros.StaticTransformBroadcaster",
    "tf2_ros.static_transform_broadcaster.StaticTransformBroadcaster"})
"""tf2_ros classes whose constructor requires the node (Humble to Rolling)."""


def _without_node(call: ast.Call, func: ast.expr, index: Index) -> bool:
    """True when a tf2_ros constructor requiring the node is given too few arguments for it
    (no ``node=`` either): a broadcaster nothing, a listener one positional argument."""
    required = 2 if index.qualified(func) in _LISTENERS else 1
    return len(call.args) < required and not any(k.arg == "node" for k in call.keywords)


def _number(value: ast.expr | None, package: Package, tree: ast.Module, index: Index) -> bool:
    """True for a value that certainly is a plain number (``1.0``, a name bound only to one)."""
    return value is not None and \
        certain_type(value, package, tree, index) in NUMBER_TYPES - {"bool"}


def _node_first(call: ast.Call, index: Index) -> bool:
    """True for ``TransformListener(self, buffer)`` in a method whose ``self`` is the node."""
    first = call.args[0] if call.args else None
    method = index.enclosing_function(call, through_lambdas=False)
    positional = [*method.args.posonlyargs, *method.args.args] if method else []
    return isinstance(first, ast.Name) and len(call.args) >= 2 and bool(positional) and \
        positional[0].arg == first.id and index.enclosing_class(call) is not None


@rule("PYC069", "tf2-argument-misuse", Severity.ERROR,
      fix="Pass `timeout=Duration(seconds=1.0)`; create the listener as "
          "`TransformListener(self.tf_buffer, self)`")
def tf2_argument_misuse(package: Package) -> Iterator[Hit]:
    """tf2_ros is given a plain number where it wants a `Duration`, or the node where it
    wants the buffer.

    ## What it does
    In installed modules importing `tf2_ros`, reports the `timeout` of a buffer's
    `lookup_transform`, `can_transform`, `lookup_transform_full` or `can_transform_full`
    given as a plain number (`timeout=1.0`, or a name every binding of which is a number;
    not when the module defines a function of that name), and `TransformListener(self,
    buffer)`: the node first, where the listener takes the
    buffer first (`TransformListener(buffer, node)`); and a `TransformBroadcaster()`,
    `StaticTransformBroadcaster()` or `TransformListener(buffer)` given no node.

    ## Why is this bad?
    tf2_ros adds the timeout to an rclpy `Time`, which accepts only a `Duration`: the lookup
    raises `TypeError` (not the `TransformException` the code around it catches), and the
    callback dies. A listener given the node as its buffer calls `create_subscription` on
    the buffer and raises `AttributeError` as the node starts.

    ## Example
    ```python
    self.tf_listener = TransformListener(self, self.tf_buffer)
    t = self.tf_buffer.lookup_transform('map', 'base_link', rclpy.time.Time(), timeout=1.0)
    ```

    ## Use instead
    ```python
    self.tf_listener = TransformListener(self.tf_buffer, self)
    t = self.tf_buffer.lookup_transform('map', 'base_link', rclpy.time.Time(),
                                        timeout=Duration(seconds=1.0))
    ```
    """
    for module, tree, index in installed_trees(package):
        if not index.imports_from("tf2_ros"):
            continue
        for call in index.calls:
            func = call.func
            if unpacks(call):
                continue
            if isinstance(func, ast.Attribute) and func.attr in _TIMEOUTS and \
                    not index.defines_function(func.attr):  # not a wrapper of the module's
                timeout = argument(call, _TIMEOUTS[func.attr], "timeout")
                if _number(timeout, package, tree, index):
                    assert timeout is not None
                    yield Hit(Span(module.path, timeout.lineno, timeout.col_offset + 1),
                              f"`{func.attr}()` is given the timeout `{ast.unparse(timeout)}`, "
                              "a number: tf2_ros adds it to an rclpy `Time`, which raises "
                              "TypeError (no `TransformException`)",
                              f"Write `timeout=Duration(seconds={ast.unparse(timeout)})`")
            elif isinstance(func, (ast.Name, ast.Attribute)) and \
                    index.qualified(func) in _NEEDS_NODE and _without_node(call, func, index):
                made = index.qualified(func).rpartition(".")[2]
                yield Hit(Span(module.path, call.lineno, call.col_offset + 1),
                          f"`{ast.unparse(call)}` is given no node: `{made}` takes "
                          f"{'the buffer and ' if made == 'TransformListener' else ''}the node "
                          "and raises TypeError (missing argument) as the node starts",
                          f"Pass the node: `{made}(self)`" if made != "TransformListener" else
                          "Pass the buffer and the node: `TransformListener(self.tf_buffer, "
                          "self)`")
            elif isinstance(func, (ast.Name, ast.Attribute)) and \
                    index.qualified(func) in _LISTENERS and _node_first(call, index):
                node, buffer = (ast.unparse(a) for a in call.args[:2])
                yield Hit(Span(module.path, call.lineno, call.col_offset + 1),
                          f"`{ast.unparse(func)}({node}, {buffer})` gives the node where the "
                          "listener takes the buffer: it calls `create_subscription` on the "
                          "buffer and raises AttributeError",
                          f"Write `{ast.unparse(func)}({buffer}, {node})`")
