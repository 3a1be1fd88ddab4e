"""Python files read with ``ast``: imports (guarded or not), top-level names, syntax errors."""

from __future__ import annotations

from pkgtool.model.span import ParseProblem, Span
from pkgtool.records import record


@record
class Import:
    """One imported module.

    ``module`` is the dotted name as written (for ``from . import x`` it is ``""``); ``level`` is
    the number of leading dots (0 for absolute). ``guarded`` is True for an import the module
    can run without: inside ``try`` blocks that catch ImportError/ModuleNotFoundError/Exception
    (with a handler that neither ends in ``raise`` nor exits: ``except ImportError:
    sys.exit(...)`` needs the module) and in their ``except`` fallbacks, in the body of ``with
    contextlib.suppress(ImportError):`` (or a broader class), in a module-level function (or
    a module-level class's ``__init__``) that the module only ever calls (constructs) inside
    such ``try`` blocks (an optional backend with a fallback), under ``if
    TYPE_CHECKING:``, in either branch of an ``importlib.util.find_spec`` check or after one
    that raises or returns (``if find_spec("x") is None: raise ...``), after a call that
    pip-installs requirements on demand (``check_requirements('x')``), in either branch of a
    test on ``__name__`` or ``__package__`` (run as a script or as a package), and in
    branches that never run on Python 3 (:mod:`pkgtool.model.static_branches`). ``names``
    are the names of a ``from`` import.
    """

    module: str
    level: int
    names: tuple[str, ...]
    span: Span
    guarded: bool = False

    @property
    def top_level(self) -> str:
        """The first component of an absolute import (``sensor_msgs`` for sensor_msgs.msg)."""
        return self.module.split(".", 1)[0] if self.level == 0 else ""


@record
class PythonModule:
    """A parsed .py file of the package. With ``syntax_error`` set, the rest is what the
    top-level statements before the error say (often nothing)."""

    path: str
    imports: tuple[Import, ...]
    top_level_names: frozenset[str]
    syntax_error: ParseProblem | None = None

    @property
    def is_test(self) -> bool:
        """Under test/ or tests/, or named test_*.py / *_test.py / conftest.py."""
        parts = self.path.split("/")
        name = parts[-1]
        return (parts[0] in ("test", "tests") or name.startswith("test_")
                or name.endswith("_test.py") or name == "conftest.py")


def parse_module(path: str, text: str) -> PythonModule:
    """Parse Python source; a syntax error is recorded, never raised."""
    from pkgtool.model.python_visitor import read_module

    return read_module(path, text)
