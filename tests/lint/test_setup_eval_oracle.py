"""The setup.py evaluator against CPython: every keyword value it claims to know is CPython's.

Each setup.py (the fixtures', the reference packages', the seeded mistakes' and generated
variants) is evaluated statically and then run for real by ``setup_oracle_driver.py`` in a
sandboxed ``python -I -S`` worker, cwd a temporary copy of its package folder, with a
``setup()`` that records its keywords. A keyword the evaluator leaves unresolved is allowed;
a value it gives must equal CPython's.
"""

from __future__ import annotations

import json
import os
import resource
import select
import shutil
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
import setuptools
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from pkgtool.model.files import list_files
from pkgtool.model.setup_eval import evaluate
from pkgtool.model.setup_eval.values import NotStatic, plain
from pkgtool.model.span import ParseProblem
from tests.lint.seeded import CASES, CREATED
from tests.lint.test_seeded_mistakes import bases  # noqa: F401  (the fixture)
from tests.lint.test_setup_eval import FILES

pytestmark = pytest.mark.oracle

REPO = Path(__file__).resolve().parents[2]
DRIVER = Path(__file__).with_name("setup_oracle_driver.py")
SOURCES = sorted([*(REPO / "tests" / "fixtures").rglob("setup.py"),
                  *(REPO / "reference_packages").glob("*/setup.py")])
ANSWER_SECONDS = 10
MISSING = "<missing>"


def _limits() -> None:
    resource.setrlimit(resource.RLIMIT_AS, (2 << 30, 2 << 30))
    resource.setrlimit(resource.RLIMIT_FSIZE, (1 << 20, 1 << 20))


class CPython:
    """One sandboxed interpreter running setup.py files on request."""

    def __init__(self, home: Path) -> None:
        site = str(Path(setuptools.__file__).parent.parent)
        self.process = subprocess.Popen(
            [sys.executable, "-I", "-S", str(DRIVER), site], stdin=subprocess.PIPE,
            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, cwd=home, text=True,
            env={"PATH": os.defpath, "HOME": str(home), "LC_ALL": "C.UTF-8"},
            preexec_fn=_limits)

    def run(self, folder: Path) -> dict[str, Any]:
        """What ``setup()`` received when ``folder``'s setup.py ran (``calls``, ``error``)."""
        assert self.process.stdin and self.process.stdout
        self.process.stdin.write(f"{folder}\n")
        self.process.stdin.flush()
        ready, _, _ = select.select([self.process.stdout], [], [], ANSWER_SECONDS)
        assert ready, f"CPython gave no answer for {folder} in {ANSWER_SECONDS} s"
        return json.loads(self.process.stdout.readline())

    def close(self) -> None:
        """Stop the interpreter."""
        self.process.kill()
        self.process.wait()


@pytest.fixture(scope="module")
def cpython(tmp_path_factory: pytest.TempPathFactory) -> Iterator[CPython]:
    """The module's CPython worker."""
    worker = CPython(tmp_path_factory.mktemp("oracle-home"))
    yield worker
    worker.close()


def claims(folder: Path) -> dict[str, Any]:
    """The setup() keywords the evaluator gives values for, as JSON data."""
    found = evaluate("setup.py", (folder / "setup.py").read_text(), list_files(folder))
    if isinstance(found, ParseProblem) or found.call is None:
        return {}
    result = {}
    for key, value in found.call.values.items():
        try:
            result[key] = json.loads(json.dumps(plain(value, found.call.sources[key])))
        except NotStatic:
            continue
    return result


def check(cpython: CPython, folder: Path) -> int:
    """Compare the evaluator with CPython on ``folder``; the number of values compared."""
    claimed = claims(folder)
    if not claimed:
        return 0
    ran = cpython.run(folder)
    if not ran["calls"]:  # a fixture that fails when run (a name bound elsewhere): no value
        return 0
    actual = ran["calls"][0]
    wrong = {key: {"evaluator": value, "cpython": actual.get(key, MISSING)}
             for key, value in claimed.items() if actual.get(key, MISSING) != value}
    assert wrong == {}, json.dumps(wrong, indent=1)
    return len(claimed)


def _copy(source: Path, destination: Path) -> Path:
    shutil.copytree(source, destination, symlinks=True,
                    ignore=shutil.ignore_patterns("__pycache__"))
    return destination


@pytest.mark.parametrize("setup_py", SOURCES, ids=lambda p: str(p.parent.relative_to(REPO)))
def test_fixture_setup_py(cpython: CPython, setup_py: Path, tmp_path: Path) -> None:
    check(cpython, _copy(setup_py.parent, tmp_path / "pkg"))


def test_the_oracle_compares_something() -> None:
    """Most fixtures evaluate: a vacuous oracle would pass everything."""
    assert sum(len(claims(p.parent)) for p in SOURCES) > 4 * len(SOURCES)


def test_seeded_setup_py(cpython: CPython, bases: dict[str, Path],  # noqa: F811
                         tmp_path: Path) -> None:
    seen: set[str] = set()
    compared = 0
    for number, case in enumerate(CASES):
        root = _copy(bases[case.base], tmp_path / str(number))
        case.mutate(root)
        setup_py = root / "setup.py"
        text = setup_py.read_text() if setup_py.is_file() else ""
        if text and text not in seen:
            seen.add(text)
            compared += check(cpython, root)
    assert compared > 20 and CREATED in bases


# Generated variants over the evaluator tests' file tree: each piece is an expression (or
# statements) in which F stands for the folder (a literal or the loop variable).
SHARE = ("os.path.join('share', package_name, F)", "'share/' + package_name + '/' + F",
         "f'share/{package_name}/{F}'", "'share/{}/{}'.format(package_name, F)",
         "'share/%s/%s' % (package_name, F)", "str(Path('share') / package_name / F)",
         "os.path.join('share', package_name, F, '')", "os.path.join('share/' + NAME, F)")
SOURCES_OF = ("glob(F + '/*')", "glob(os.path.join(F, '*.*'))", "glob('./' + F + '/*')",
              "glob(F + '/**/*', recursive=True)", "glob(F + '/**', recursive=True)",
              "sorted(glob(f'{F}/*.py'))", "[str(p) for p in Path(F).glob('*')]",
              "[str(p) for p in Path(F).rglob('*.py')]",
              "[p.as_posix() for p in Path(F).glob('**')]",
              "glob(F + '/*.launch.py') + glob(F + '/*_launch.py')",
              "[x for x in glob(F + '/**', recursive=True) if os.path.isfile(x)]",
              "glob(os.path.join('.', F, '*'))", "glob(F + '//*.yaml')", "[F + '/a.launch.py']",
              "glob(F + '/*[!~]')", "list(glob(F + '/.*'))")
FOLDERS = ("launch", "config", "launch/sub", "test", "missing")
PACKAGES = ("[package_name]", "find_packages(exclude=['test'])", "find_packages()",
            "find_packages(include=[package_name, package_name + '.*'])",
            "find_packages(where='src')", "find_namespace_packages(exclude=['test*'])",
            "[package_name, package_name + '.nodes']")
NAMES = ("'demo'", "package_name", "NAME", "'de' + 'mo'", "f'{package_name}'",
         "'%s' % package_name", "'{}'.format(NAME)")
SCRIPTS = ("{'console_scripts': ['talker = ' + package_name + '.talker:main']}",
           "{'console_scripts': [f'talker = {package_name}.talker:main', 'x=demo.x']}",
           "dict(console_scripts=['talker = demo.talker:main'])",
           "'[console_scripts]\\ntalker = demo.talker:main\\n'")
PREAMBLE = """\
import os
from glob import glob
from pathlib import Path
from setuptools import find_namespace_packages, find_packages, setup
package_name = 'demo'
NAME = package_name
BASE = [('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml'])]
"""


def _entry(share: str, sources: str, folder: str) -> str:
    return f"({share.replace('F', folder)}, {sources.replace('F', folder)})"


@st.composite
def setup_texts(draw: st.DrawFn) -> str:
    """A setup.py in the ament_python style, its pieces and their order drawn."""
    folders = draw(st.lists(st.sampled_from(FOLDERS), min_size=1, max_size=3, unique=True))
    share, sources = draw(st.sampled_from(SHARE)), draw(st.sampled_from(SOURCES_OF))
    style = draw(st.sampled_from(("literal", "loop", "comprehension", "concatenation",
                                  "function")))
    if style == "function":
        data = (f"def entry(folder, base=NAME):\n    return {_entry(share, sources, 'folder')}\n"
                f"data_files = BASE + [entry(f) for f in {folders!r}]\n")
    elif style == "loop":
        data = (f"data_files = list(BASE)\nfor folder in {folders!r}:\n"
                f"    data_files.append({_entry(share, sources, 'folder')})\n")
    elif style == "comprehension":
        data = (f"data_files = BASE + [{_entry(share, sources, 'folder')} "
                f"for folder in {folders!r}]\n")
    else:
        entries = [_entry(share, sources, repr(f).replace("'", '"')) for f in folders]
        joiner = ", " if style == "literal" else "] + ["
        data = f"data_files = BASE + [{joiner.join(entries)}]\n"
    keywords = [("name", draw(st.sampled_from(NAMES))), ("version", "'0.0.' + str(1)"),
                ("packages", draw(st.sampled_from(PACKAGES))), ("data_files", "data_files"),
                ("entry_points", draw(st.sampled_from(SCRIPTS))), ("zip_safe", "True"),
                ("install_requires", "['setuptools']"), ("license", "'Apache-2.0'")]
    ordered = draw(st.permutations(keywords))
    arguments = ",\n      ".join(f"{key}={value}" for key, value in ordered)
    return f"{PREAMBLE}{data}setup({arguments})\n"


@pytest.fixture(scope="module")
def variant_root(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The evaluator tests' file tree on disk, where generated setup.py files run."""
    root = tmp_path_factory.mktemp("variant")
    for file in FILES:
        (root / file).parent.mkdir(parents=True, exist_ok=True)
        (root / file).write_text("")
    return root


@settings(max_examples=150, deadline=None, database=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(text=setup_texts())
def test_generated_setup_py(cpython: CPython, variant_root: Path, text: str) -> None:
    (variant_root / "setup.py").write_text(text)
    assert check(cpython, variant_root) > 0
