"""PYC002: NumPy aliases and functions that current NumPy releases no longer have."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.numpy_removed import REMOVED, SYSTEM_NUMPY, system_has
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._attribute_guards import guarded, probed_names
from pkgtool.rules.syntax_trees import installed_trees, resolved_attributes
from pkgtool.rules.registry import rule
from pkgtool.rules.ros1_platform import is_ros1_package


def _hit(path: str, node: ast.AST, name: str, distro: str) -> Hit:
    removed = REMOVED[name]
    system = ".".join(map(str, SYSTEM_NUMPY.get(distro, ())))
    if system_has(removed, distro):
        whose = "Ubuntu 24.04's" if removed.comes_back else \
            "pip's, the PyPI ROS wheels'"
        what = (f"raises AttributeError under NumPy {removed.lacking} ({whose}; the NumPy "
                f"{system} Ubuntu ships for {distro} still has it)")
    else:
        what = f"raises AttributeError with the NumPy {system} Ubuntu ships for {distro}"
    return Hit(Span(path, node.lineno, node.col_offset + 1),  # type: ignore[attr-defined]
               f"`np.{name}` was removed in NumPy {removed.removed_in}: it {what}",
               f"Use {removed.use} instead of `np.{name}`")


@rule("PYC002", "numpy-removed-alias", Severity.ERROR,
      fix="Replace the removed NumPy name with its documented replacement")
def numpy_removed_alias(package: Package) -> Iterator[Hit]:
    """Installed code uses a NumPy name that NumPy 1.24 or 2.x removed.

    ## What it does
    Reports attributes of the `numpy` module (through any name bound only to `numpy`, such
    as `np`) and `from numpy import ...` names that no longer exist: the builtin aliases
    removed in NumPy 1.24 (`np.float`, `np.int`, `np.object`, `np.bool`, ...) and the names
    NumPy 2 removed (`np.int0`, `np.float_`, `np.product`, `np.NaN`, ...). Annotations Python
    never evaluates (of an assignment in a function, or under `from __future__ import
    annotations`) are not checked, nor are names the module probes (`if getattr(np, 'bool',
    False):`, `hasattr`) or reads where AttributeError is caught. ROS 1 (catkin) packages are
    left alone: Noetic's NumPy 1.17 has every alias.

    ## Why is this bad?
    The line raises `AttributeError` (or `ImportError`) when it runs. ROS 2 Jazzy on Ubuntu
    24.04 ships NumPy 1.26, pip (and the PyPI ROS 2 wheels courses run on) installs NumPy 2:
    old tutorials' `np.int0` breaks on the latter, `np.float` and `np.bool` on the former.
    The message says which NumPy the name is missing from.

    ## Example
    ```python
    corners = np.int0(corners)
    ```

    ## Use instead
    ```python
    corners = np.intp(corners)
    ```
    """
    if is_ros1_package(package):
        return  # Noetic's NumPy 1.17 has every alias (see pkgtool.rules.ros1_platform)
    for module, _, index in installed_trees(package):
        if not any(i.top_level == "numpy" for i in module.imports):
            continue  # nothing can resolve to numpy (the common case: no walk over attributes)
        probed = probed_names(index)
        for node, owner, attr in resolved_attributes(index):
            if owner == "numpy" and attr in REMOVED and \
                    not index.in_unevaluated_annotation(node) and not guarded(node, index, probed):
                yield _hit(module.path, node, attr, package.context.distro)
        for node in index.import_froms:
            if node.module == "numpy" and node.level == 0:
                for alias in node.names:
                    if alias.name in REMOVED:
                        yield _hit(module.path, node, alias.name, package.context.distro)
