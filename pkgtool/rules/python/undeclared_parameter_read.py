"""PYC014: a Node subclass reads a parameter it never declares."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.rules.node_parameters import BUILT_IN, near, node_classes
from pkgtool.rules.registry import rule


@rule("PYC014", "undeclared-parameter-read", Severity.ERROR,
      fix="Declare the parameter first: `self.declare_parameter('name', default)`")
def undeclared_parameter_read(package: Package) -> Iterator[Hit]:
    """A `Node` subclass reads a parameter that its code never declares.

    ## What it does
    In classes derived directly from rclpy's `Node`, checks the literal names given to
    `self.get_parameter('name')` and `self.get_parameters([...])` against the names the
    module declares with `declare_parameter` and `declare_parameters` (with their namespace
    prefix: `ns.name`), called directly or through a name bound only to the method in its
    function (`p = self.declare_parameter`, then `p('rate', 1.0)`). `get_parameter_or` and
    `has_parameter` are not checked. Skipped when the module uses
    `allow_undeclared_parameters` or `automatically_declare_parameters_from_overrides`,
    declares a name that is not a literal, uses the method otherwise (passed to `map`, say),
    or the class derives from another class besides `Node`, or hands `self` to other code.

    ## Why is this bad?
    `get_parameter` raises `ParameterNotDeclaredException` for a name never declared: the node
    dies where it reads it, often a misspelling of a declared name.

    ## Example
    ```python
    self.declare_parameter('period', 0.5)
    period = self.get_parameter('perod').value
    ```

    ## Use instead
    ```python
    self.declare_parameter('period', 0.5)
    period = self.get_parameter('period').value
    ```
    """
    for cls in node_classes(package):
        if cls.skip:
            continue
        declared = [d.name for d in cls.declared]
        for name, span in cls.reads:
            if name not in declared and name not in BUILT_IN:
                yield Hit(span, f"`{cls.name}` reads parameter `{name}` but never declares "
                          f"it{near(name, declared)}: ParameterNotDeclaredException")
