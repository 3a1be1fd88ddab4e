"""DAT011: a parameter file gives a value of another type than the declared default."""

from __future__ import annotations

import ast
from collections.abc import Iterable, Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.node_parameters import (
    NodeClass, analysed_classes, file_entries, flat_parameters, mixed_list, python_type, span_of,
    yaml_type)
from pkgtool.rules.registry import rule


@rule("DAT011", "parameter-type-mismatch", Severity.ERROR,
      fix="Write the value with the declared type (`1.0`, not `1`, for a double)")
def parameter_type_mismatch(package: Package) -> Iterator[Hit]:
    """A parameter file or launch file gives a value of another type than the node declares.

    ## What it does
    For the parameters DAT010 checks (and also where a launch file gives some node a
    parameter file chosen at run time, since the nodes the launch files name still get their
    files), compares the type rcl's YAML parser gives the value
    (quoted: string; `true`/`yes`/`on`...: bool; an integer literal: integer; else a
    number: double; else string; a list: an array of its items' type) with the type of the
    literal default of `declare_parameter`. Declarations whose default is not a literal, that
    pass a `ParameterDescriptor` with `dynamic_typing=True` (or a descriptor not written
    in the call) or `ignore_override=True` are not checked. A list mixing types is reported
    in any block of those files: rcl rejects the whole file. The literal values a Python
    launch file gives a node of this package in a parameter dict (as DAT010 checks their
    names) are compared the same way, typed as Python types them (launch_ros keeps a string
    a string: `'0.5'` is a string), and so are the static `<param name= value=>` of an XML
    launch file's node, typed as launch types an attribute (YAML's reading tried as an
    integer, then a number: `value="1"` is an integer, `value="1.0"` a double), the plain
    (unquoted) `value:` of a YAML launch file's `param:` entries, typed the same way, and the
    `-p name:=value` arguments of a Python launch file's node, typed as rcl reads them (YAML:
    `period:=1` is an integer, `period:=fast` a string).

    ## Why is this bad?
    The node dies at start-up: `declare_parameter` raises `InvalidParameterTypeException`.
    `1` is an integer, and an integer is not accepted for a double parameter.

    ## Example
    ```python
    self.declare_parameter('period', 0.5)
    ```
    ```yaml
    talker:
      ros__parameters:
        period: 1
    ```

    ## Use instead
    ```yaml
    talker:
      ros__parameters:
        period: 1.0
    ```
    """
    for entry in file_entries(package, unseen_users=True):
        classes = analysed_classes(package, entry.matched) or []
        for name, _, value in flat_parameters(entry.parameters):
            if mixed_list(value):
                yield Hit(span_of(entry.path, value), f"`{name}` mixes value types in one "
                          "list: rcl rejects the file")
                continue
            found = yaml_type(value)
            if found is not None:
                yield from _mismatch(span_of(entry.path, value), name, classes, found, "file")
    for launch in package.launch_files:
        for node in launch.nodes:
            classes = analysed_classes(package, (node,)) if node.inline_parameters else None
            for name, span, text in node.inline_parameters if classes else ():
                found = python_type(ast.literal_eval(text)) if text is not None else None
                if found is not None:
                    yield from _mismatch(span, name, classes or [], found, "launch file")


def _mismatch(span: Span, name: str, classes: Iterable[NodeClass], found: str, giver: str
              ) -> Iterator[Hit]:
    """A hit when the nodes' declarations of ``name`` have types and ``found`` is none of them:
    at the value, with the declarations as related places (either side may be the mistake)."""
    declared = [d for c in classes for d in c.declared if d.name == name and d.type]
    wanted = sorted({d.type for d in declared if d.type})
    if not wanted or found in wanted:
        return
    where = ", ".join(f"`{d.span.path}:{d.span.line}`" for d in declared)
    fix = None
    if wanted == ["INTEGER"] and found == "DOUBLE":
        fix = ("Declare the parameter with a float default (`1.0`, not `1`) if it takes "
               "fractions; else write an integer")
    elif found != "INTEGER" or wanted != ["DOUBLE"]:
        fix = (f"Give the value the declared type, or declare the parameter with a {found} "
               "default if that is the type it takes")
    yield Hit(span, f"`{name}` is declared {' or '.join(wanted)} (at {where}) but the {giver} "
                    f"gives {found}: the node raises InvalidParameterTypeException", fix,
              related=tuple(d.span for d in declared))
