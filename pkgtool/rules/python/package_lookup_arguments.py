"""PYC071: ``get_package_share_directory('pkg', 'config', 'x.yaml')``: path parts given to a lookup
that takes a package name only."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import index_of, python_files

_LOOKUPS = {"get_package_share_directory": 2, "get_package_share_path": 2,
            "get_package_prefix": 1}
"""ament_index_python's lookups -> how many positional arguments they take (the package name,
then ``print_warning``)."""
_MODULES = ("ament_index_python.packages", "ament_index_python")


@rule("PYC071", "package-lookup-arguments", Severity.ERROR,
      fix="Join the parts to the folder it returns: "
          "`os.path.join(get_package_share_directory('pkg'), 'config', 'x.yaml')`")
def package_lookup_arguments(package: Package) -> Iterator[Hit]:
    """A package lookup of `ament_index_python` is given path parts after the package name.

    ## What it does
    Reports calls of `get_package_share_directory`, `get_package_share_path` (which take the
    package name and an optional `print_warning` flag) and `get_package_prefix` (the name
    alone) given more positional arguments than they take, or a text as the second one, in
    any Python file of the package (nodes, launch files, tests).

    ## Why is this bad?
    A third positional argument raises `TypeError`, so the launch file or node fails at once.
    A second one is taken as `print_warning`: the call returns the package's share folder
    itself, the path parts are silently dropped, and the file is then not found (or a folder
    is opened as a file) far from the mistake.

    ## Example
    ```python
    params = get_package_share_directory('my_robot', 'config', 'params.yaml')
    ```

    ## Use instead
    ```python
    params = os.path.join(get_package_share_directory('my_robot'), 'config', 'params.yaml')
    ```
    """
    for path, _, tree in python_files(package, tuple(_LOOKUPS)):
        index = index_of(tree)
        for call in index.calls:
            name = index.qualified(call.func) or ""
            owner, _, function = name.rpartition(".")
            taken = _LOOKUPS.get(function) if owner in _MODULES else None
            if taken is None or any(isinstance(a, ast.Starred) for a in call.args):
                continue
            extra = call.args[1:]
            if len(call.args) > taken:
                takes = "the package name alone" if taken == 1 else \
                    "the package name and `print_warning`"
                why = f"takes {takes}: `TypeError`"
            elif extra and _text(extra[0]):
                why = "takes `print_warning` second: the path part is dropped and the " \
                    "package's share folder itself is returned"
            else:
                continue
            parts = ", ".join(ast.unparse(a) for a in extra)
            first = ast.unparse(call.args[0]) if call.args else "..."
            yield Hit(Span(path, call.lineno, call.col_offset + 1),
                      f"`{function}()` is given the path parts {parts}, but it {why}",
                      f"Write `os.path.join({function}({first}), {parts})`")


def _text(node: ast.expr) -> bool:
    """True for a string literal or an f-string."""
    return isinstance(node, ast.JoinedStr) or \
        isinstance(node, ast.Constant) and isinstance(node.value, str)
