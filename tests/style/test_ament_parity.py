"""pkgtool's in-process flake8/pydocstyle report exactly what ament_flake8/ament_pep257 report."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

from pkgtool.ament.flake8_runner import run_flake8
from pkgtool.ament.pydocstyle_runner import run_pydocstyle
from tests.helpers import write_tree

CORPUS = {
    "pkg/__init__.py": "",
    "pkg/imports.py": '''
        """Imports out of order and unused."""
        import sys
        import os
        from collections import OrderedDict, defaultdict
        import rclpy
        from std_msgs.msg import String
        x = "double"
        y = 'single'
        def f(list):
            return [i for i in list(range(3))]
        ''',
    "pkg/docstrings.py": '''
        """module doc"""


        class Node:
            """  Spaces."""

            def speed(self):
                """returns the speed"""
                return 1

            def long(self):
                """Summary line.
                more text here"""
                return dict([(1, 2)])
        ''',
    "pkg/lines.py": "value = 1  " + "#" * 120 + "\n\n\n\nother = value == None\n",
    "pkg/noqa.py": 'import os  # noqa: F401\nq = "x"  # noqa\n',
    "test/test_thing.py": '''
        def test_x():
            assert 1 == 1
        ''',
    "setup.py": '''
        from setuptools import setup
        setup(name="x")
        ''',
}


@pytest.fixture(scope="module")
def corpus(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return write_tree(tmp_path_factory.mktemp("style"), CORPUS)


def _files(root: Path) -> list[str]:
    return sorted(p.relative_to(root).as_posix() for p in root.rglob("*.py"))


def _ament(tool: str, root: Path) -> str:
    script = Path(sys.executable).parent / tool
    done = subprocess.run([str(script)], cwd=root, capture_output=True, text=True, timeout=120)
    return done.stdout + done.stderr


def test_flake8_matches_ament_flake8(corpus: Path) -> None:
    output = _ament("ament_flake8", corpus)
    theirs = {(m[1], int(m[2]), int(m[3]), m[4]) for m in
              re.finditer(r"^\./(\S+?):(\d+):(\d+): ([A-Z]+\d+) ", output, re.MULTILINE)}
    ours = {(v.path, v.line, v.col, v.code) for v in run_flake8(corpus, _files(corpus))}
    assert len(theirs) > 10, output
    assert ours == theirs


def test_pydocstyle_matches_ament_pep257(corpus: Path) -> None:
    output = _ament("ament_pep257", corpus)
    theirs = {(m[1], int(m[2]), m[3]) for m in
              re.finditer(r"^\./(\S+?):(\d+) .*?: (D\d+): ", output, re.MULTILINE)}
    ours = {(v.path, v.line, v.code) for v in run_pydocstyle(corpus, _files(corpus))}
    assert len(theirs) >= 5, output
    assert ours == theirs


PLUGINS = {"flake8-builtins": "A", "flake8-comprehensions": "C4", "flake8-docstrings": "D",
           "flake8-import-order": "I", "flake8-quotes": "Q"}
"""The plugins ament_flake8 runs with in a ROS 2 workspace, and the code prefix each reports."""


def test_the_plugins_parity_rests_on_are_pinned_installed_and_reporting(corpus: Path) -> None:
    """Without a plugin both sides would agree on missing its codes: parity would prove little."""
    import importlib.metadata

    from pkgtool.compat import tomllib

    style = tomllib.loads((Path(__file__).parents[2] / "pyproject.toml").read_text())[
        "project"]["optional-dependencies"]["style"]
    pinned = dict(entry.split("==") for entry in style if "==" in entry)
    codes = {v.code for v in run_flake8(corpus, _files(corpus))}
    for plugin, prefix in PLUGINS.items():
        assert pinned.get(plugin) == importlib.metadata.version(plugin), plugin
        assert any(code.startswith(prefix) for code in codes), (plugin, sorted(codes))
