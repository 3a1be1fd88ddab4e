"""Generated code passes ament's own linters (the ament_flake8 and ament_pep257 wheels).

These are the tools the generated test_flake8.py / test_pep257.py run under ``colcon test``;
here they run in-process over packages with every node kind, odd names and odd text.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.create.conftest import ALL_KINDS, OTHER_TYPES

CASES = {
    "all_kinds": {"nodes": ALL_KINDS, "launch": True, "config": True, "library_name": "util"},
    "other_types": {"nodes": OTHER_TYPES, "launch": True},
    "long_names": {"name": "z" * 40, "nodes": ("a" * 32 + ":action-client", "b" * 32 + ":client",
                                               "c" * 32 + ":publisher"),
                   "maintainer_name": "Zoë O'Brien " + "x" * 60,
                   "description": 'Has "quotes", it\'s <long> ' + "word " * 60,
                   "launch": True, "config": True},
    "clashing_class_names": {"nodes": ("node:timer", "chatter:publisher", "trigger:service")},
    "no_nodes": {"license": "GPL-3.0-only", "package_format": 2},
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_ament_flake8_and_pep257_pass(create, case: str, capsys) -> None:
    from ament_flake8.main import main_with_errors
    from ament_pep257.main import main as pep257_main

    values = dict(CASES[case])
    result = create(values.pop("name", "demo_pkg"), **values)
    assert not result.error
    root = str(result.root)
    rc, errors = main_with_errors(argv=[root])
    assert rc == 0, "\n".join(errors)
    assert pep257_main(argv=[root]) == 0, capsys.readouterr().out
    assert len(list(Path(root).rglob("*.py"))) >= 5
