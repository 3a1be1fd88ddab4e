"""PYC055: a pytest fixture of a test module called like a plain function."""

from __future__ import annotations

import ast
from collections.abc import Iterator

from pkgtool.findings import Hit, Severity
from pkgtool.model.package import Package
from pkgtool.model.span import Span
from pkgtool.rules.python._own_callees import own_definition
from pkgtool.rules.pytest_fixtures import is_fixture
from pkgtool.rules.registry import rule
from pkgtool.rules.syntax_trees import index_of, python_files
from pkgtool.rules.test_modules import test_files


@rule("PYC055", "fixture-called", Severity.ERROR,
      fix="Take the fixture as a parameter of the test (`def test_x(name):`) and use that")
def fixture_called(package: Package) -> Iterator[Hit]:
    """A test module calls one of its pytest fixtures like a plain function.

    ## What it does
    Reports a call `name()` in a test module where `name` is a function of that module
    decorated with `@pytest.fixture` (also `@pytest.fixture(...)` and `@fixture` imported
    from pytest), when no scope around the call rebinds the name.

    ## Why is this bad?
    pytest refuses it: the call raises `Fixture "name" called directly. Fixtures are not
    meant to be called directly`, and the test fails (or, from a fixture, every test using
    it errors). pytest runs a fixture itself and passes its value to the tests that name it
    as a parameter; its set-up and tear-down then run where they should.

    ## Example
    ```python
    @pytest.fixture
    def node():
        return Talker()

    def test_topic():
        assert node().topic == 'chatter'
    ```

    ## Use instead
    ```python
    def test_topic(node):
        assert node.topic == 'chatter'
    ```
    """
    tests = test_files(package)
    for path, _, tree in python_files(package, ("fixture",)):
        if path not in tests:
            continue
        index = index_of(tree)
        for call in index.calls:
            function = own_definition(call, index, tree) if isinstance(call.func, ast.Name) \
                else None
            if function is not None and is_fixture(function, index):
                name = call.func.id  # type: ignore[attr-defined]
                yield Hit(Span(path, call.lineno, call.col_offset + 1),
                          f"`{name}()` calls the pytest fixture `{name}` directly: pytest "
                          "raises 'Fixture called directly' and the test fails",
                          f"Take `{name}` as a parameter of the test and use its value")
