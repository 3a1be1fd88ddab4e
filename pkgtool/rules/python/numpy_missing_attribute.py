"""PYC076: a NumPy name misspelt (``np.uit8``, ``np.arage``, ``np.linalg.nrom``)."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.numpy_removed import REMOVED
from pkgtool.knowledge.stdlib_names import numpy_names
from pkgtool.model.package import Package
from pkgtool.rules.python._module_names import missing_names, used_on
from pkgtool.rules.registry import rule


@rule("PYC076", "numpy-missing-attribute", Severity.ERROR,
      fix="Write the name NumPy defines (see the message)")
def numpy_missing_attribute(package: Package) -> Iterator[Hit]:
    """Code uses a NumPy name that no NumPy release defines, spelled like one that it does.

    ## What it does
    In every Python file of the package, reports `np.name` (NumPy imported under any name) and
    `from numpy import name` for `numpy`, `numpy.linalg`, `numpy.random` and `numpy.fft`, when
    no NumPy from 1.23 to 2.x defines the name and it is a typo away from one that does:
    `np.uit8`, `np.arage`, `np.linalg.nrom`, `np.random.randn` misspelt `randm`. A name far
    from every NumPy name is left alone (it may be newer than pkgtool's table), as are
    private names, names the module assigns or probes with `hasattr`/`getattr`, and uses
    inside `try`. Names that NumPy 2 removed (`np.float_`, `np.int0`) are PYC002's.

    ## Why is this bad?
    The line raises `AttributeError` (an import, `ImportError`) when it runs, most often in a
    callback converting a message, long after the node started.

    ## Example
    ```python
    buffer = np.frombuffer(msg.data, dtype=np.uit8)
    ```

    ## Use instead
    ```python
    buffer = np.frombuffer(msg.data, dtype=np.uint8)
    ```
    """
    for span, module, name, meant, error, uses in missing_names(package, numpy_names()):
        if module == "numpy" and name in REMOVED:
            continue  # a name NumPy had (`np.complex`): PYC002 says when it went away
        yield Hit(span, f"NumPy's `{module}` has no `{name}` in any release (did you mean "
                  f"`{meant}`?): the line raises {error}{used_on(uses)}", f"Write `{meant}`",
                  related=uses)
