"""A created package's linter tests pass with the ament linters and with pkgtool alone."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

BLOCK_AMENT = """
import sys


LINTERS = ('ament_flake8', 'ament_pep257', 'ament_copyright', 'ament_lint')


class _NoAment:
    def find_spec(self, name, path=None, target=None):
        if name.split('.')[0] in LINTERS:
            raise ImportError('ament linters are not installed here')


sys.meta_path.insert(0, _NoAment())
"""


@pytest.fixture(scope="module")
def package(tmp_path_factory: pytest.TempPathFactory) -> Path:
    where = tmp_path_factory.mktemp("created")
    pkgtool = Path(sys.executable).parent / "pkgtool"
    done = subprocess.run([str(pkgtool), "create", "style_demo", "--destination-directory",
                           str(where), "--node", "talker:publisher", "--node", "echo:service",
                           "--launch", "--maintainer-name", "Dev", "--maintainer-email",
                           "dev@example.com", "--copyright-year", "2026"],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    return where / "style_demo"


def _run_linter_tests(package: Path, extra_path: str | None) -> str:
    env = {"PATH": str(Path(sys.executable).parent), "HOME": str(package.parent)}
    if extra_path:
        env["PYTHONPATH"] = extra_path
    done = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider",
                           "-rs", "test/test_flake8.py", "test/test_pep257.py",
                           "test/test_copyright.py"],
                          cwd=package, env=env, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stdout + done.stderr
    return done.stdout


def test_with_the_ament_linters(package: Path) -> None:
    assert "3 passed" in _run_linter_tests(package, None)


def test_with_pkgtool_alone(package: Path, tmp_path: Path) -> None:
    (tmp_path / "sitecustomize.py").write_text(BLOCK_AMENT)
    assert "3 passed" in _run_linter_tests(package, str(tmp_path))


def test_a_style_error_fails_the_generated_test_without_ament(
        package: Path, tmp_path: Path) -> None:
    (tmp_path / "sitecustomize.py").write_text(BLOCK_AMENT)
    module = package / "style_demo" / "talker.py"
    original = module.read_text()
    module.write_text(original + "x = \"double quotes\"\n")
    try:
        with pytest.raises(AssertionError, match="Q000"):
            _run_linter_tests(package, str(tmp_path))
    finally:
        module.write_text(original)


STAND_IN = """
import os
import sys


def main(argv=sys.argv[1:]):
    with open(os.environ['AMENT_ARGV'], 'w') as out:
        out.write(repr(argv))
    return int(os.environ['AMENT_RC'])
"""


@pytest.mark.parametrize("verdict", [0, 1])
def test_copyright_test_runs_ament_copyright_when_it_is_importable(
        package: Path, tmp_path: Path, verdict: int) -> None:
    """The real one has no wheel (its verdicts are in tests/data/ament_copyright): a stand-in
    with its entry point shows that the generated test calls it and trusts its exit code."""
    (tmp_path / "ament_copyright").mkdir()
    (tmp_path / "ament_copyright" / "__init__.py").write_text("")
    (tmp_path / "ament_copyright" / "main.py").write_text(STAND_IN)
    argv = tmp_path / "argv"
    env = {"PATH": str(Path(sys.executable).parent), "PYTHONPATH": str(tmp_path),
           "AMENT_ARGV": str(argv), "AMENT_RC": str(verdict)}
    done = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider",
                           "test/test_copyright.py"], cwd=package, env=env,
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == verdict, done.stdout + done.stderr
    assert argv.read_text() == repr([str(package)])
