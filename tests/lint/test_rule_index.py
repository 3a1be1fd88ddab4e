"""The generated rule index: selection reads it, and only selected rules are imported."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from pkgtool.docs_gen import INDEX, index_source
from pkgtool.rules.registry import index, load_all

RULE_MODULES = """
import sys
print(" ".join(sorted(sys.modules)))
"""


def test_the_index_agrees_with_the_rule_modules() -> None:
    assert INDEX.read_text(encoding="utf-8") == index_source(load_all()), \
        "pkgtool/rules/_index.py is stale: run `python -m pkgtool.docs_gen`"
    assert {code: (r.name, r.severity, r.default_enabled) for code, r in index().items()} == \
        {code: (r.name, r.severity, r.default_enabled) for code, r in load_all().items()}


def _imported_after(code: str) -> set[str]:
    done = subprocess.run([sys.executable, "-c", code + RULE_MODULES], capture_output=True,
                          text=True, check=True, cwd=Path(__file__).parents[2])
    rule_modules = {f"pkgtool.rules.{info.module}" for info in index().values()}
    return set(done.stdout.split()) & rule_modules


def test_selecting_rules_imports_none() -> None:
    imported = _imported_after(
        "from pkgtool.config import Layer, settings_for\n"
        "settings = settings_for([Layer('test', None, ('MAN', 'DEP001'), ('MAN002',), ())])\n"
        "assert 'MAN001' in settings.codes and 'MAN002' not in settings.codes\n")
    assert imported == set()


def test_running_rules_imports_only_theirs() -> None:
    imported = _imported_after(
        "from pkgtool.config import Layer, settings_for\n"
        "settings = settings_for([Layer('test', None, ('MAN001',), (), ())])\n"
        "assert [r.code for r in settings.rules] == ['MAN001']\n")
    assert imported == {"pkgtool.rules.manifest.invalid_package_name"}
