"""PYC093: a frequency (Hz) given to ``create_timer`` as its period in seconds."""

from __future__ import annotations

import ast
import re
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_api import CALLBACKS, argument, node_api_calls
from pkgtool.rules.registry import rule
from pkgtool.rules.scopes import scope_bindings, single_assignments
from pkgtool.rules.syntax_trees import FUNCTIONS, Index

_FREQUENCY_WORDS = frozenset({"hz", "freq", "frequency", "fps"})
"""Words of a name that hold a frequency (``rate`` alone does not tell: ``spawn_rate = 10``
may mean every ten seconds)."""
_RATE = "rate"
_RATE_ABOVE = 10
"""A value a name saying ``rate`` holds above which it is a frequency (``publish_rate = 20``):
ROS code divides such rates into periods (``1.0 / rate``); a period of more than ten seconds
called a rate is not what is meant."""
_PERIOD_WORDS = frozenset({"period", "dt", "interval", "sec", "secs", "seconds", "s", "ms",
                           "duration", "delay", "time", "timeout"})
"""Words saying the name holds a time after all (``rate_period``, ``freq_sec``)."""
_DEPTH = 4


@rule("PYC093", "frequency-as-timer-period", Severity.WARNING,
      fix="Give the period in seconds: `self.create_timer(1.0 / rate_hz, callback)`")
def frequency_as_timer_period(package: Package) -> Iterator[Hit]:
    """A node's `create_timer` is given a frequency in hertz where it takes a period in
    seconds.

    ## What it does
    Reports the first argument of `create_timer` when it is a name, an attribute or a
    parameter read (`self.get_parameter('rate_hz').value`, also through a local name bound
    to one) whose name says it holds a
    frequency (a word `hz`, `freq`, `frequency` or `fps`: `publish_hz`, `self.frequency`),
    unless its value is known (a literal the name is bound to, a parameter's default,
    `declare_parameter('rate_hz', 50.0)`) and at most 1: `self.frequency_ = 0.01` is a
    period named loosely. A name saying only `rate` counts when its value is known and above
    10 (`publish_rate` declared with `20.0`: ROS code divides rates into periods, `1.0 /
    rate`), not below (`spawn_rate = 10` may mean every ten seconds). Names with a word of
    time (`period`, `dt`, `sec`, `interval`...) and expressions (`1.0 / rate_hz`) are left
    alone.

    ## Why is this bad?
    `create_timer(timer_period_sec, callback)` takes seconds; rospy's `Rate(10)` took hertz.
    A 50 Hz loop becomes one tick every 50 seconds: the node looks alive and does nothing,
    the controller never updates, the watchdog never feeds.

    ## Example
    ```python
    self.declare_parameter('rate_hz', 50.0)
    rate = self.get_parameter('rate_hz').value
    self.timer = self.create_timer(rate, self.on_tick)
    ```

    ## Use instead
    ```python
    self.declare_parameter('rate_hz', 50.0)
    rate = self.get_parameter('rate_hz').value
    self.timer = self.create_timer(1.0 / rate, self.on_tick)
    ```
    """
    for module, call, _, index in node_api_calls(package, ("create_timer",)):
        period = argument(call, CALLBACKS["create_timer"][0], "timer_period_sec")
        if period is None:
            continue
        words = {word for name in _names(period, call, index)
                 for word in re.split(r"[_\W]+", _snake(name))}
        if not words or words & _PERIOD_WORDS:
            continue
        value = _value(period, call, index, 0)
        rate = _RATE in words and isinstance(value, (int, float)) and value > _RATE_ABOVE
        if (words & _FREQUENCY_WORDS and (value is None or value > 1) or rate) and \
                not _inverse(period, call, index):  # not `freq_ = 0.01`, `freq = 1 / 30`
            fires = f"once every {value:g} s" if isinstance(value, (int, float)) else \
                "at the inverse of the rate meant"
            yield Hit(Span(module.path, period.lineno, period.col_offset + 1),
                      f"`{ast.unparse(period)}` is a frequency, but `create_timer` takes its "
                      f"period in seconds: the timer fires {fires}")


def _names(period: ast.expr, call: ast.Call, index: Index) -> list[str]:
    """The name the period reads, and that of what a local name it reads is bound to
    (``rate = self.get_parameter('rate_hz').value``)."""
    name = _name_of(period)
    function = index.enclosing_function(call)
    bound = single_assignments(function).get(period.id) \
        if isinstance(period, ast.Name) and function is not None else None
    further = _name_of(bound) if bound is not None else None
    return [found for found in (name, further) if found]


def _inverse(period: ast.expr, call: ast.Call, index: Index) -> bool:
    """True when the period is ``1 / x`` for a number or a name saying frequency (or a name
    bound once to that in its function, or ``self.x`` assigned only that): a period worked
    out from a frequency (``1.0 / period`` is a frequency)."""
    function = index.enclosing_function(call)
    if isinstance(period, ast.Name) and function is not None:
        period = single_assignments(function).get(period.id) or period
    elif isinstance(period, ast.Attribute) and isinstance(period.value, ast.Name):
        stored = _stored(period.attr, index.enclosing_class(call))
        period = stored[0] if len(stored) == 1 else period
    if not (isinstance(period, ast.BinOp) and isinstance(period.op, ast.Div) and
            isinstance(period.left, ast.Constant) and period.left.value == 1):
        return False
    divisor = period.right  # a rate (`1 / 30`, `1 / rate_hz`), not a period (`1 / dt`)
    name = _name_of(divisor)
    return isinstance(divisor, ast.Constant) or name is not None and bool(
        set(re.split(r"[_\W]+", _snake(name))) & _FREQUENCY_WORDS)


def _stored(attribute: str, cls: ast.ClassDef | None) -> list[ast.expr]:
    """The values the class assigns to ``self.<attribute>``."""
    return [node.value for node in ast.walk(cls) if isinstance(node, ast.Assign)
            and len(node.targets) == 1 and isinstance(node.targets[0], ast.Attribute)
            and node.targets[0].attr == attribute and
            isinstance(node.targets[0].value, ast.Name) and
            node.targets[0].value.id == "self"] if cls is not None else []


def _snake(name: str) -> str:
    """``publishRateHz`` as ``publish_rate_hz``, lower case."""
    return re.sub(r"(?<=[a-z0-9])(?=[A-Z])", "_", name).lower()


def _name_of(period: ast.expr) -> str | None:
    """The name a period expression reads: a name, an attribute, a parameter's name
    (``self.get_parameter('rate').value``), through ``float()`` and ``int()``."""
    if isinstance(period, ast.Call) and isinstance(period.func, ast.Name) and \
            period.func.id in ("float", "int") and len(period.args) == 1:
        return _name_of(period.args[0])
    parameter = _parameter_read(period)
    if parameter is not None:
        return parameter
    return period.id if isinstance(period, ast.Name) else \
        period.attr if isinstance(period, ast.Attribute) else None


def _parameter_read(value: ast.expr) -> str | None:
    """``p`` of ``x.get_parameter('p').value`` (or ``.get_parameter_value().double_value``)."""
    while isinstance(value, (ast.Attribute, ast.Call)):
        if isinstance(value, ast.Call):
            func = value.func
            if isinstance(func, ast.Attribute) and func.attr == "get_parameter" and \
                    value.args and isinstance(value.args[0], ast.Constant) and \
                    isinstance(value.args[0].value, str):
                return value.args[0].value
            value = func
        else:
            value = value.value
    return None


def _value(expr: ast.expr, at: ast.AST, index: Index, depth: int) -> object:
    """The number ``expr`` certainly holds, when it is known: a literal, a name bound once
    in its function to a known value (or a parameter's default), ``self.x`` assigned once in
    its class, a parameter's literal default in ``declare_parameter``."""
    if depth > _DEPTH:
        return None
    if isinstance(expr, ast.Constant):
        return expr.value if isinstance(expr.value, (int, float)) and \
            not isinstance(expr.value, bool) else None
    if isinstance(expr, ast.Call) and isinstance(expr.func, ast.Name) and \
            expr.func.id in ("float", "int") and len(expr.args) == 1:
        return _value(expr.args[0], at, index, depth + 1)
    parameter = _parameter_read(expr)
    if parameter is not None:
        return _declared_default(parameter, index, depth)
    function = index.enclosing_function(at)
    if isinstance(expr, ast.Name) and function is not None:
        bound = single_assignments(function).get(expr.id)
        if bound is not None:
            return _value(bound, bound, index, depth + 1)
        if expr.id not in scope_bindings(function):  # a module's constant
            bound = _body_constant(index.module_of(at), expr.id)
            return _value(bound, bound, index, depth + 1) if bound is not None else None
        return _default(function, expr.id, index, depth)
    if isinstance(expr, ast.Attribute) and isinstance(expr.value, ast.Name) and \
            expr.value.id == "self":
        cls = index.enclosing_class(at)
        stored = _stored(expr.attr, cls) or [
            v for v in [_body_constant(cls, expr.attr)] if v is not None]  # a class attribute
        return _value(stored[0], stored[0], index, depth + 1) if len(stored) == 1 else None
    return None


def _body_constant(holder: ast.AST | None, name: str) -> ast.expr | None:
    """The value of the one ``name = value`` of a module's or class's own body."""
    values = [s.value for s in getattr(holder, "body", ()) if isinstance(s, ast.Assign) and
              any(isinstance(t, ast.Name) and t.id == name for t in s.targets)]
    return values[0] if len(values) == 1 else None


def _default(function: ast.AST, name: str, index: Index, depth: int) -> object:
    """The known default of the parameter ``name`` of ``function``."""
    if not isinstance(function, FUNCTIONS):
        return None
    arguments = function.args
    positional = [*arguments.posonlyargs, *arguments.args]
    defaults = dict(zip([a.arg for a in positional[len(positional) - len(arguments.defaults):]],
                        arguments.defaults))
    defaults.update((a.arg, d) for a, d in zip(arguments.kwonlyargs, arguments.kw_defaults)
                    if d is not None)
    given = defaults.get(name)
    return _value(given, given, index, depth + 1) if given is not None else None


def _declared_default(parameter: str, index: Index, depth: int) -> object:
    """The literal default of the module's one ``declare_parameter('<parameter>', value)``."""
    defaults = [call.args[1] for call in index.calls
                if isinstance(call.func, ast.Attribute) and call.func.attr == "declare_parameter"
                and len(call.args) > 1 and isinstance(call.args[0], ast.Constant) and
                call.args[0].value == parameter]
    return _value(defaults[0], defaults[0], index, depth + 1) if len(defaults) == 1 else None
