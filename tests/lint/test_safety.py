"""Lint never runs the code it checks, refuses XML tricks, and turns bad files into findings.

Every test lints with ``--select ALL`` (rules that are off by default included) and checks
that no traceback escapes and that the user's files are left byte-identical.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from pkgtool.commands import ExitCode
from pkgtool.model import files
from pkgtool.model.files import MAX_FILE_BYTES
from tests.helpers import correct_package_files, run_cli, write_tree

WRITE = "open({sentinel!r}, 'a').write({who!r})\n"


def _snapshot(root: Path) -> dict[str, tuple[int, bytes | None]]:
    """Every path under ``root`` with its mode and, for files, its bytes."""
    found = {}
    for path in sorted(root.rglob("*")):
        relative = path.relative_to(root).as_posix()
        content = path.read_bytes() if path.is_file() and os.access(path, os.R_OK) else None
        found[relative] = (path.lstat().st_mode, content)
    return found


def _assert_only_cache_added(root: Path, before: dict[str, tuple[int, bytes | None]]) -> None:
    """Nothing under ``root`` changed except the lint cache ``.pkgtool_cache/`` (created)."""
    after = _snapshot(root)
    cache = {path for path in after if path.split("/")[0] == ".pkgtool_cache"}
    assert cache, "the lint cache is written to the project root"
    assert {path: after[path] for path in set(after) - cache} == before, \
        "lint changed or created files (e.g. __pycache__) besides its cache"


def _lint_subprocess(root: Path, *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "pkgtool", "lint", "--select", "ALL", *args],
                          cwd=root, capture_output=True, text=True, timeout=120)


def _assert_clean_exit(done: subprocess.CompletedProcess[str]) -> None:
    assert "Traceback" not in done.stderr + done.stdout
    assert done.returncode in (ExitCode.OK, ExitCode.FINDINGS), done.stderr


@pytest.fixture()
def trap(tmp_path: Path) -> tuple[Path, Path]:
    """A package whose setup.py, modules, tests and launch files would write a sentinel."""
    sentinel = tmp_path / "SENTINEL"
    write = WRITE.format(sentinel=str(sentinel), who="{}")
    files = correct_package_files("trap")
    files.update({
        "setup.py": write.replace("{}", "setup.py ran") + str(files["setup.py"]),
        "trap/__init__.py": write.replace("{}", "package imported"),
        "trap/talker.py": write.replace("{}", "module imported") + str(files["trap/talker.py"]),
        "test/conftest.py": write.replace("{}", "conftest imported"),
        "launch/trap.launch.py": write.replace("{}", "launch file ran") +
        str(files["launch/trap.launch.py"]),
        "launch/trap.launch.yaml":
            f"launch:\n- !!python/object/apply:os.system [\"touch {sentinel}\"]\n",
    })
    root = write_tree(tmp_path / "ws", {f"src/trap/{k}": v for k, v in files.items()})
    return root, sentinel


def test_nothing_is_executed_or_imported(trap: tuple[Path, Path]) -> None:
    root, sentinel = trap
    before = _snapshot(root)
    for fmt in ("text", "json", "sarif", "github", "junit"):
        _assert_clean_exit(_lint_subprocess(root, "--format", fmt))
    result = run_cli("lint", "--select", "ALL", cwd=root)
    assert result.exit_code in (ExitCode.OK, ExitCode.FINDINGS), result.output
    assert not sentinel.exists(), sentinel.read_text()
    assert "trap" not in sys.modules and "trap.talker" not in sys.modules
    _assert_only_cache_added(root, before)


@pytest.mark.parametrize("doctype", [
    '<!DOCTYPE package [<!ENTITY xxe SYSTEM "file:///etc/passwd">]>',
    '<!DOCTYPE package SYSTEM "http://127.0.0.1:9/package.dtd">',
    '<!DOCTYPE package [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;">'
    '<!ENTITY c "&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;"><!ENTITY d "&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;">]>',
])
def test_entity_and_doctype_tricks_become_findings(tmp_path: Path, doctype: str) -> None:
    files = correct_package_files("xxe")
    files["package.xml"] = str(files["package.xml"]).replace(
        '<package format="3">', f'{doctype}\n<package format="3">').replace(
        "<description>A package for tests.</description>", "<description>&xxe;&d;</description>")
    files["launch/xxe.launch.xml"] = f'<?xml version="1.0"?>\n{doctype}\n<launch/>\n'
    root = write_tree(tmp_path / "xxe", files)
    before = _snapshot(root)
    done = _lint_subprocess(root, "--format", "json")
    _assert_clean_exit(done)
    findings = json.loads(done.stdout)["findings"]
    assert {(f["rule"], f["path"]) for f in findings if f["rule"] == "SYN003"} == {
        ("SYN003", "package.xml"), ("SYN003", "launch/xxe.launch.xml")}
    assert "root:" not in done.stdout and "aaaaaaaaaaaaaaaaaaaa" not in done.stdout
    _assert_only_cache_added(root, before)


BAD_FILES: dict[str, bytes] = {
    "bad/binary.py": b"import os\x00\x01\x02\n",
    "bad/latin1.py": "# caf\u00e9 = 1\n".encode("latin-1"),
    "bad/utf16.py": "x = 1\n".encode("utf-16"),
    "launch/bad.launch.py": b"\xff\xfe\x00\x00",
}
HUGE = {"bad/huge.py": b"# padding\n" * (MAX_FILE_BYTES // 10 + 1)}
"""A file over pkgtool's read limit: a note that it was not checked (SYN004), no error."""


def test_bad_files_become_findings_not_tracebacks(tmp_path: Path) -> None:
    files: dict[str, str | bytes] = dict(correct_package_files("bad"))
    files.update(BAD_FILES | HUGE)
    root = write_tree(tmp_path / "bad", files)
    before = _snapshot(root)
    done = _lint_subprocess(root, "--format", "json")
    _assert_clean_exit(done)
    found = json.loads(done.stdout)["findings"]
    assert {f["path"] for f in found if f["rule"] == "SYN002"} == set(BAD_FILES)
    assert {(f["path"], f["severity"]) for f in found if f["rule"] == "SYN004"} == {
        (path, "info") for path in HUGE}
    _assert_only_cache_added(root, before)


@pytest.mark.parametrize("special", ["package.xml", "setup.cfg", "launch/fifo.launch.py"])
@pytest.mark.parametrize("kind", ["fifo", "endless"])
def test_special_files_are_not_read(tmp_path: Path, special: str, kind: str) -> None:
    """A FIFO (which blocks a reader until someone writes) or a link to an endless device
    under a package file's name: lint finishes, reading neither."""
    root = write_tree(tmp_path / "odd", correct_package_files("odd"))
    target = root / special
    target.parent.mkdir(parents=True, exist_ok=True)
    target.unlink(missing_ok=True)
    if kind == "fifo":
        os.mkfifo(target)
    else:
        target.symlink_to("/dev/zero")
    done = _lint_subprocess(root, "--format", "json", "--no-cache")
    _assert_clean_exit(done)
    fixed = _lint_subprocess(root, "--no-cache", "--fix", "--unsafe-fixes")  # fixers read too
    assert "Traceback" not in fixed.stderr + fixed.stdout
    assert fixed.returncode in (ExitCode.OK, ExitCode.FINDINGS, ExitCode.INTERNAL), fixed.stderr
    assert target.is_fifo() if kind == "fifo" else target.is_symlink()


@pytest.mark.parametrize("empty", ["package.xml", "setup.py", "launch/empty.launch.xml"])
def test_empty_files_become_findings(tmp_path: Path, empty: str) -> None:
    files: dict[str, str | bytes] = dict(correct_package_files("hollow"))
    files[empty] = b""
    root = write_tree(tmp_path / "hollow", files)
    done = _lint_subprocess(root, "--format", "json")
    _assert_clean_exit(done)
    assert empty in {f["path"] for f in json.loads(done.stdout)["findings"]}, done.stdout


def test_unreadable_file_becomes_a_finding(tmp_path: Path,
                                           monkeypatch: pytest.MonkeyPatch) -> None:
    """chmod 000 where it works; as root (who reads anything) the refusal is simulated."""
    root = write_tree(tmp_path / "locked", correct_package_files("locked"))
    secret = root / "locked" / "talker.py"
    if os.geteuid() != 0:
        secret.chmod(0)
        try:
            done = _lint_subprocess(root, "--format", "json")
        finally:
            secret.chmod(0o644)
        _assert_clean_exit(done)
        findings = json.loads(done.stdout)["findings"]
    else:
        real = files.read_bytes

        def refuse(path: str) -> bytes | int:
            if Path(path) == secret:
                raise PermissionError(13, "Permission denied", path)
            return real(path)

        monkeypatch.setattr(files, "read_bytes", refuse)
        result = run_cli("lint", "--select", "ALL", "--format", "json", cwd=root)
        assert result.exit_code in (ExitCode.OK, ExitCode.FINDINGS), result.output
        findings = json.loads(result.stdout)["findings"]
    assert ("SYN002", "locked/talker.py") in {(f["rule"], f["path"]) for f in findings}
