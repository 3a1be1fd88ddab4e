# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Every console script of setup.py names a callable ``main`` that exists."""

import ast
import importlib
from pathlib import Path

SETUP_PY = Path(__file__).resolve().parents[1] / 'setup.py'


def _console_scripts() -> dict[str, str]:
    tree = ast.parse(SETUP_PY.read_text())
    keyword = next(n for n in ast.walk(tree)
                   if isinstance(n, ast.keyword) and n.arg == 'entry_points')
    scripts = ast.literal_eval(keyword.value)['console_scripts']
    return dict((part.strip() for part in line.split('=')) for line in scripts)


def test_console_scripts_resolve_to_callables():
    scripts = _console_scripts()
    assert scripts
    for name, target in scripts.items():
        module, function = target.split(':')
        assert module.rsplit('.', 1)[-1] == name, 'each executable is named after its module'
        assert callable(getattr(importlib.import_module(module), function))
