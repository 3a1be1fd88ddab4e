"""PYC065: a misspelt pytest name in a test (``pytest.fixure``, ``pytest.mark.paramtrize``)."""

from __future__ import annotations

import ast
import posixpath
import re
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.rosdistro import is_typo
from pkgtool.model.ast_nodes import nodes_of_class
from pkgtool.model.package import Package
from pkgtool.model.pytest_config import CONFIG_FILES
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import FUNCTIONS, Index, index_of
from pkgtool.rules.test_modules import test_trees

PYTEST_NAMES = frozenset("""
Approx Cache CallInfo CaptureFixture Class CollectReport Collector Config Dir Directory
DoctestItem ExceptionInfo ExitCode File FixtureDef FixtureLookupError FixtureRequest Function
HookRecorder Item LineMatcher LogCaptureFixture Mark MarkDecorator MarkGenerator Metafunc Module
MonkeyPatch OptionGroup Package ParameterSet Parser PytestPluginManager Pytester RaisesExc
RaisesGroup RecordedHookCall RunResult Session Stash StashKey TempPathFactory TempdirFactory
TerminalReporter TestReport Testdir UsageError WarningsRecorder approx cmdline console_main
deprecated_call exit fail fixture freeze_includes hookimpl hookspec importorskip main mark param
raises register_assert_rewrite register_fixture set_trace skip version_tuple warns xfail
yield_fixture collect
""".split())
"""The public names of the ``pytest`` module (pytest 6 to 9; warning classes aside)."""
MARKS = frozenset({"parametrize", "skip", "skipif", "xfail", "usefixtures", "filterwarnings"})
"""pytest's own marks."""
_PLUGIN_MARKS = frozenset({"timeout", "asyncio", "launch_test", "flaky", "order", "linter",
                           "copyright", "flake8", "pep257", "mypy", "xmllint", "rostest"})
"""Marks of plugins ROS packages use (ament's linters, launch_testing, pytest-timeout...)."""
_HABITS = {"parameterize": "parametrize", "parametrise": "parametrize",
           "parameterise": "parametrize", "parameterized": "parametrize"}
"""Spellings of ``parametrize`` people write."""


def _near(name: str, known: frozenset[str]) -> list[str]:
    """The names of ``known`` a typo away from ``name`` (one habit for ``parametrize``)."""
    if known is MARKS and name in _HABITS:
        return [_HABITS[name]]
    return sorted(c for c in known if is_typo(name, c))


def _at_import(node: ast.AST, index: Index) -> bool:
    """True when ``node`` runs when the module is imported: outside any function body
    (a decorator or a default value of a module-level function runs then)."""
    child, parent = node, index.parents.get(id(node))
    while parent is not None:
        if isinstance(parent, (*FUNCTIONS, ast.Lambda)) and \
                any(child is s for s in getattr(parent, "body", ()) or ()) or \
                isinstance(parent, ast.Lambda) and child is parent.body:
            return False
        child, parent = parent, index.parents.get(id(parent))
    return True


@rule("PYC065", "misspelled-pytest-name", Severity.ERROR,
      fix="Write the pytest name meant (see the message)")
def misspelled_pytest_name(package: Package) -> Iterator[Hit]:
    """A test uses a misspelt pytest name or mark.

    ## What it does
    In the package's test modules (and `conftest.py`), reports `pytest.<name>` and `from
    pytest import <name>` when pytest has no such name and one it has is a typo away
    (`pytest.fixure`, `pytest.aprox`), and `@pytest.mark.<name>` when the mark is a typo of
    one of pytest's own (`parametrize`, `skip`, `skipif`, `xfail`, `usefixtures`,
    `filterwarnings`), including `parameterize` and `parametrise`. A mark named in the
    package's pytest configuration or a `conftest.py` (a registered custom mark) is left
    alone, and so are the marks of plugins ROS packages use.

    ## Why is this bad?
    A missing name raises `AttributeError` or `ImportError` when pytest imports the module:
    none of its tests runs. An unknown mark is only a warning: the test runs without it, so
    `@pytest.mark.paramtrize('speed', [...])` makes `speed` a fixture pytest cannot find,
    and a misspelt `skipif` or `xfail` runs (and fails) the test it meant to set aside.

    ## Example
    ```python
    @pytest.fixure
    def node():
        ...

    @pytest.mark.paramtrize('speed', [0.1, 1.0])
    def test_speed(node, speed):
        ...
    ```

    ## Use instead
    ```python
    @pytest.fixture
    def node():
        ...

    @pytest.mark.parametrize('speed', [0.1, 1.0])
    def test_speed(node, speed):
        ...
    ```
    """
    registered = "\n".join(text for path, text in package.texts.items()
                           if path in CONFIG_FILES or posixpath.basename(path) == "conftest.py")
    for path, tree in test_trees(package):
        index = index_of(tree)
        for node in index.attributes:
            dotted = index.qualified(node)
            if dotted is None or not dotted.startswith("pytest.") or dotted.count(".") != \
                    (2 if dotted.startswith("pytest.mark.") else 1):
                continue
            mark = dotted.startswith("pytest.mark.")
            known = MARKS if mark else PYTEST_NAMES
            if node.attr in known or mark and (node.attr in _PLUGIN_MARKS or
                                               re.search(rf"\b{node.attr}\b", registered)):
                continue
            near = _near(node.attr, known)
            if near:
                when = "importing the module fails, and none of its tests runs" \
                    if _at_import(node, index) else "running the test fails"
                yield _hit(Span(path, node.end_lineno or node.lineno,
                                (node.end_col_offset or 0) - len(node.attr) + 1),
                           node.attr, near, "mark" if mark else when)
        for imported in index.import_froms:
            if imported.module == "pytest" and not imported.level:
                for alias in imported.names:
                    near = [] if alias.name in PYTEST_NAMES else _near(alias.name, PYTEST_NAMES)
                    if near:
                        uses = () if alias.asname else tuple(
                            Span(path, n.lineno, n.col_offset + 1)
                            for n in nodes_of_class(tree, ast.Name)
                            if isinstance(n, ast.Name) and n.id == alias.name)
                        yield _hit(Span(path, imported.lineno, imported.col_offset + 1),
                                   alias.name, near, "importing the module fails, and none of "
                                   "its tests runs", uses)


def _hit(span: Span, name: str, near: list[str], when: str, uses: tuple[Span, ...] = ()
         ) -> Hit:
    """The hit for ``name``; ``when`` says what fails (``mark``: an unknown mark); ``uses``:
    where the module uses a misspelt name it imports (renamed with it)."""
    hint = f" (did you mean `{near[0]}`?)" if len(near) == 1 else \
        f" (did you mean one of {', '.join(f'`{n}`' for n in near)}?)"
    fix = f"Write `{near[0]}`" if len(near) == 1 else None
    if when == "mark":
        return Hit(span, f"`pytest.mark.{name}` is not a mark pytest knows{hint}: pytest only "
                   "warns, and the test runs without it", fix)
    return Hit(span, f"`pytest` has no `{name}`{hint}: {when}", fix, related=uses)
