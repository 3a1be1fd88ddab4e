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
