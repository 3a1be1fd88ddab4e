"""The setup.py evaluator is bounded by cost: hostile setup.py files cannot exhaust its reader.

Each attack really runs, in a child process capped at 768 MB of address space and 120 s:
before the bounds, each of them either blew the cap (1.4 GB for one ``str.format``), ran
for minutes (an int squared in a loop) or evaluated an exponential nested ``**`` glob.
Now each is refused ("not evaluated", SET012), with the rest of setup.py still read.
"""

from __future__ import annotations

import itertools
import json
import resource
import subprocess
import sys
from pathlib import Path

import pytest

from tests.helpers import MINIMAL_MANIFEST, write_tree

LIMIT = 768 * 1024 * 1024
DEEP = tuple("/".join(f"d{b}" for b in bits) + "/f.py"
             for bits in itertools.product("ab", repeat=10))
ATTACKS = {
    "format": ("name", "", "name='{:>1500000000}'.format('x')"),
    "f_string": ("name", "", "name=f'{\"x\":>{1500000000}}'"),
    "percent": ("name", "", "name='%1500000000s' % 'x'"),
    "int_times_str": ("name", "", "name=1000 * 1000 * 1000 * 'x'"),
    "replace": ("name", "s = 'x' * 100000\n", "name=s.replace('x', s)"),
    "join": ("name", "s = 'x' * 100000\n", "name=''.join([s] * 100000)"),
    "squaring": ("version", "n = 7\nfor _ in range(40):\n    n = n * n\n",
                 "version=str(n % 10)"),
    "nested_globs": ("data_files", "from glob import glob\n",
                     "data_files=[('share', glob('**/**/**/**/**/*.py', recursive=True))]"),
}
"""name -> (the keyword it feeds, statements before setup(), the keyword's text)."""
CHILD = """
import json, sys
from pkgtool.model.setup_eval import read_setup
text, files = sys.argv[1], tuple(sys.argv[2:])
result = read_setup('setup.py', text, files)
print(json.dumps({'unresolved': [key for key, _ in result.unresolved],
                  'license': result.license.value if result.license else None}))
"""


def _capped() -> None:
    resource.setrlimit(resource.RLIMIT_AS, (LIMIT, LIMIT))


def test_every_attack_is_refused_within_its_caps() -> None:
    children = {}
    for name, (_, before, keyword) in ATTACKS.items():
        text = f"from setuptools import setup\n{before}setup({keyword}, license='MIT')\n"
        files = DEEP if name == "nested_globs" else ("setup.py",)
        children[name] = subprocess.Popen([sys.executable, "-c", CHILD, text, *files],
                                          stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                          text=True, preexec_fn=_capped)
    for name, child in children.items():
        try:
            out, err = child.communicate(timeout=120)
        except subprocess.TimeoutExpired:
            child.kill()
            child.communicate()
            pytest.fail(f"{name}: still evaluating after 120 s")
        assert child.returncode == 0, f"{name}: {err[-2000:]}"
        answer = json.loads(out)
        assert ATTACKS[name][0] in answer["unresolved"], (name, answer)
        assert answer["license"] == "MIT", f"{name}: the rest of setup() is still read"


def test_lint_says_not_evaluated_for_a_bounded_keyword(tmp_path: Path) -> None:
    setup = "from setuptools import setup\nsetup(name='{:>1500000000}'.format('x'))\n"
    write_tree(tmp_path / "demo", {"package.xml": MINIMAL_MANIFEST.format(name="demo"),
                                   "setup.py": setup, "resource/demo": ""})
    done = subprocess.run([sys.executable, "-m", "pkgtool", "lint", "demo", "--select", "SET012",
                           "--format", "json"], cwd=tmp_path, capture_output=True, text=True,
                          timeout=120, preexec_fn=_capped, check=False)
    assert done.returncode == 0, done.stderr[-2000:]
    findings = json.loads(done.stdout)["findings"]
    assert [(f["rule"], f["line"]) for f in findings] == [("SET012", 2)], done.stdout
