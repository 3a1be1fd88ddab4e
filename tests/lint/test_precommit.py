"""The real ``pre-commit`` runs our hook on a temporary git repository, offline.

The hook definition is read from the repository's ``.pre-commit-hooks.yaml`` and used as a
``repo: local`` hook with ``language: system`` pointing at this interpreter, so pre-commit
needs neither the network nor PyPI (``language: python`` would pip-install the checkout).
Everything else (``files``, ``pass_filenames``, ``require_serial``, the entry's arguments)
is the published hook's own.
"""

from __future__ import annotations

import os
import shlex
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from tests.helpers import correct_package_files, write_tree

REPO_ROOT = Path(__file__).resolve().parents[2]
HOOKS = REPO_ROOT / ".pre-commit-hooks.yaml"
PRE_COMMIT = Path(sys.executable).with_name("pre-commit")
BROKEN_TALKER = "import rclpy\n\n\ndef main(:\n    rclpy.init()\n"


def _git(repo: Path, *args: str) -> None:
    subprocess.run(["git", *args], cwd=repo, check=True, capture_output=True, timeout=60)


def _local_config(hook_id: str = "pkgtool-lint") -> str:
    (hook,) = [h for h in yaml.safe_load(HOOKS.read_text()) if h["id"] == hook_id]
    command, _, arguments = hook["entry"].partition(" ")
    assert command == "pkgtool"
    hook.update(language="system", entry=f"{shlex.quote(sys.executable)} -m pkgtool {arguments}")
    return yaml.safe_dump({"repos": [{"repo": "local", "hooks": [hook]}]})


@pytest.fixture()
def repo(tmp_path: Path) -> Path:
    root = tmp_path / "repo"
    files = {f"src/fixed_pkg/{k}": v for k, v in correct_package_files("fixed_pkg").items()}
    broken = correct_package_files("broken_pkg")
    broken["broken_pkg/talker.py"] = BROKEN_TALKER
    files.update({f"src/broken_pkg/{k}": v for k, v in broken.items()})
    files.update({".pre-commit-config.yaml": _local_config(), "tools/helper.py": "def f(:\n",
                  "README.md": "# robots\n"})
    write_tree(root, files)
    _git(root, "init", "-q")
    _git(root, "config", "user.email", "dev@example.com")
    _git(root, "config", "user.name", "Dev")
    return root


def _pre_commit(repo: Path, *args: str) -> subprocess.CompletedProcess[str]:
    env = {**os.environ, "PRE_COMMIT_HOME": str(repo.parent / "pre-commit-home"),
           "NO_COLOR": "1", "SKIP": ""}
    return subprocess.run([str(PRE_COMMIT), "run", "--color", "never", *args], cwd=repo, env=env,
                          capture_output=True, text=True, timeout=300)


def test_the_published_hook_manifest_is_valid() -> None:
    done = subprocess.run([str(PRE_COMMIT), "validate-manifest", str(HOOKS)],
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stdout + done.stderr


def test_broken_package_fails_and_fixed_package_passes(repo: Path) -> None:
    broken = _pre_commit(repo, "--files", "src/broken_pkg/broken_pkg/talker.py",
                         "src/broken_pkg/package.xml")
    assert broken.returncode == 1, broken.stdout
    assert "src/broken_pkg/broken_pkg/talker.py:4:" in broken.stdout
    assert "SYN001" in broken.stdout
    fixed = _pre_commit(repo, "--files", "src/fixed_pkg/fixed_pkg/talker.py",
                        "src/fixed_pkg/setup.py", "tools/helper.py", "README.md")
    assert fixed.returncode == 0, fixed.stdout


def test_staged_files_then_the_fix(repo: Path) -> None:
    _git(repo, "add", "-A")
    first = _pre_commit(repo)
    assert first.returncode == 1, first.stdout
    assert first.stdout.count("SYN001") == 1, "each package is linted once"
    assert "fixed_pkg" not in first.stdout
    fixed = correct_package_files("broken_pkg")["broken_pkg/talker.py"]
    write_tree(repo / "src" / "broken_pkg", {"broken_pkg/talker.py": fixed})
    _git(repo, "add", "-A")
    second = _pre_commit(repo)
    assert second.returncode == 0, second.stdout


def test_the_fixing_hook_fails_when_it_changes_files_then_passes(repo: Path) -> None:
    manifest = repo / "src" / "fixed_pkg" / "package.xml"
    duplicate = "  <exec_depend>rclpy</exec_depend>\n"
    manifest.write_text(manifest.read_text().replace(duplicate, duplicate * 2))
    write_tree(repo, {".pre-commit-config.yaml": _local_config("pkgtool-fix")})
    _git(repo, "add", "-A")
    files = ("--files", "src/fixed_pkg/package.xml")
    first = _pre_commit(repo, *files)
    assert first.returncode == 1, first.stdout
    assert "files were modified by this hook" in first.stdout
    assert manifest.read_text().count(duplicate) == 1
    assert manifest.read_text() == correct_package_files("fixed_pkg")["package.xml"]
    second = _pre_commit(repo, *files)
    assert second.returncode == 0, second.stdout
