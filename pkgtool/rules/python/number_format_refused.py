"""PYC051: a number formatted with a specification numbers of its type refuse (``{n:s}``)."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._field_reads import field_reads, value_type
from pkgtool.rules.python._format_specs import format_specs
from pkgtool.rules.python._value_types import NUMBER_TYPES
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import installed_trees
from pkgtool.lazy_regex import lazy_pattern

_SAMPLES = {"int": 1, "float": 1.5, "bool": True}
"""A value of each number type, to ask Python itself whether it takes a specification."""
_HUGE = lazy_pattern(r"\d{5,}")
"""A width or precision too large to try (formatting would build a huge string)."""


def refused_by_number(spec: str, kind: str) -> str | None:
    """The error Python raises formatting a number of type ``kind`` (``int``, ``float``,
    ``bool``) with the format ``spec``, or None when it takes it. Python's own ``format()``
    answers, given a sample value of that type: only the specification comes from the code."""
    if _HUGE.search(spec):
        return None
    try:
        format(_SAMPLES[kind], spec)
    except ValueError as error:
        return f"ValueError: {error}"
    return None


@rule("PYC051", "number-format-refused", Severity.ERROR,
      fix="Use a format code of the number's type: `d` for an int, `f` or `g` for a float, none "
          "to print it as it is")
def number_format_refused(package: Package) -> Iterator[Hit]:
    """A number is formatted with a specification numbers of its type refuse.

    ## What it does
    Reports a value that is certainly an int, a float or a bool (a literal, a builtin
    conversion, a local name or a node's `self.x` all of whose assignments give one, a number
    field of a known message: `msg.linear.x` is a float) formatted, in an f-string, a
    `'...'.format()` field or `format(value, spec)`, with a specification Python refuses for
    that type: `s` for any number, `d`, `x`, `o`, `b` or `c` for a float, a precision for an
    int (`{count:.2}`).

    ## Why is this bad?
    `f'{msg.linear.x:d}'` raises `ValueError: Unknown format code 'd' for object of type
    'float'` (Python never rounds for `d`), and `f'{self.count:s}'` the same for `s`: the
    callback that logs dies on its first message.

    ## Example
    ```python
    self.get_logger().info(f'speed: {msg.linear.x:d} m/s')
    ```

    ## Use instead
    ```python
    self.get_logger().info(f'speed: {msg.linear.x:.2f} m/s')
    ```
    """
    for module, tree, index in installed_trees(package):
        fields = None
        for value, spec, converted in format_specs(tree, index):
            if converted:
                continue
            if fields is None:
                fields = field_reads(tree, index, package)
            read, kind = fields.get(id(value)), value_type(value, fields, package, tree, index)
            refused = refused_by_number(spec, kind) if kind in NUMBER_TYPES else None
            if refused:
                what = f" (the field `{read.field}`)" if read is not None else ""
                yield Hit(Span(module.path, value.lineno, value.col_offset + 1),
                          f"`{ast.unparse(value)}`{what} is {'an' if kind == 'int' else 'a'} "
                          f"{kind} and is formatted with `{spec}`: Python raises {refused}")
