"""PYC063: a name a standard library module does not define (``signal.SIGNT``, ``math.sqr``)."""

from __future__ import annotations

from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.stdlib_names import stdlib_names
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._module_names import missing_names, used_on
from pkgtool.rules.registry import rule
from pkgtool.rules.ros1_platform import is_ros1_package


@rule("PYC063", "stdlib-missing-attribute", Severity.ERROR,
      fix="Use the name the module defines (see the message)")
def stdlib_missing_attribute(package: Package) -> Iterator[Hit]:
    """Code uses a name that a standard library module does not define.

    ## What it does
    In every Python file of the package, reports `module.name` read through an import, and
    `from module import name`, when a common standard library module (`math`, `json`,
    `random`, `threading`, `collections`, `datetime`, `pathlib`, `typing` and some forty
    more) defines no such name on any Python from 3.10 to 3.13 (Humble to Rolling): `math.sqr`,
    `random.randInt`, `collections.Mapping` (gone since 3.10). For modules whose names depend
    on the platform (`os`, `os.path`, `sys`, `signal`, `time`, `socket`, `subprocess`,
    `select`, `errno`, `platform`), only a name a typo away from one Linux's Python has is
    reported: `signal.SIGNT`, `os.pah.join`. Private names, names the module assigns or probes
    with `hasattr`/`getattr`, and uses inside `try` (and imports inside `try` or `if`) are left
    alone. In a ROS 1 (catkin) package, built for Noetic's Python 3.8, only typos of a name
    the module has are reported (a name missing from 3.10 may be one 3.8 still has).

    ## Why is this bad?
    The line raises `AttributeError` (an import, `ImportError`) when it runs: often in a
    callback, long after the node started, or at start-up for a console script, in setup.py
    for the build, or in a launch file for the launch.

    ## Example
    ```python
    signal.signal(signal.SIGNT, handler)
    distance = math.sqr(dx * dx + dy * dy)
    ```

    ## Use instead
    ```python
    signal.signal(signal.SIGINT, handler)
    distance = math.sqrt(dx * dx + dy * dy)
    ```
    """
    ros1 = is_ros1_package(package)
    for span, module, name, meant, error, uses in missing_names(package, stdlib_names()):
        if ros1 and (meant is None or _moved(module, name)):
            continue  # maybe a name Python 3.8 still has (see pkgtool.rules.ros1_platform)
        yield _hit(span, module, name, meant, error, uses)


def _moved(module: str, name: str) -> bool:
    """True for an ABC ``collections`` had until Python 3.10 (now in ``collections.abc``)."""
    return module == "collections" and name in stdlib_names()["collections.abc"][0]


def _hit(span: Span, module: str, name: str, meant: str | None, error: str,
         uses: tuple[Span, ...]) -> Hit:
    if _moved(module, name):
        return Hit(span, f"`collections` has no `{name}` since Python 3.10, which moved it to "
                   f"`collections.abc`: the line raises {error}",
                   f"Use `collections.abc.{name}`")
    hint = f" (did you mean `{meant}`?)" if meant else ""
    return Hit(span, f"`{module}` has no `{name}` on Python 3.10-3.13{hint}: the line raises "
               f"{error}{used_on(uses)}", f"Write `{meant}`" if meant else None, related=uses)
