"""A warm run replays the last report only while nothing the run read has changed."""

from __future__ import annotations

import binascii
import json
import os
import shutil
import time
from collections.abc import Callable
from pathlib import Path

import pytest

from pkgtool.cache import replay
from pkgtool.cli_lint_run import Format, lint_call
from pkgtool.commands import lint as command
from tests.helpers import correct_package_files, write_tree

Lint = Callable[..., tuple[int, str, bool]]


@pytest.fixture
def workspace(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """Two packages in a colcon workspace (one with a finding), the current folder."""
    listener = correct_package_files("listener")
    listener["listener/use.py"] = "import talker\nx = y\n"
    ws = write_tree(tmp_path / "ws", {
        **{f"src/talker/{k}": v for k, v in correct_package_files("talker").items()},
        **{f"src/listener/{k}": v for k, v in listener.items()}})
    monkeypatch.chdir(ws)
    monkeypatch.delenv("PKGTOOL_CACHE_DIR", raising=False)
    monkeypatch.delenv("NO_COLOR", raising=False)
    monkeypatch.setattr(replay, "SETTLED_NS", 0)  # trusted at once; _pause() keeps edits apart
    monkeypatch.setattr(replay, "FINE_SETTLED_NS", 0)
    _pause()
    return ws


@pytest.fixture
def lint(monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]) -> Lint:
    """Run ``pkgtool lint`` in this process: (exit code, stdout, whether it was replayed)."""
    real = command.run
    calls: list[int] = []

    def counted(*args: object, **kwargs: object) -> command.LintResult:
        calls.append(1)
        return real(*args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(command, "run", counted)

    def run(*paths: str, **options: object) -> tuple[int, str, bool]:
        before = len(calls)
        code = lint_call(paths=list(paths) or None, **{"fmt": Format.JSON, **options})
        return code, capsys.readouterr().out, len(calls) == before
    return run


def _pause() -> None:
    """Let the file system's clock move on: a later change gets a later change time."""
    time.sleep(0.05)


def _records(ws: Path) -> list[Path]:
    return sorted((ws / ".pkgtool_cache" / "lint").glob("run-*.json"))


def test_a_second_run_replays_the_report(workspace: Path, lint: Lint) -> None:
    code, first, replayed = lint()
    assert not replayed and code == 1 and "PYC001" in first
    assert len(_records(workspace)) == 1
    entries = replay._read(_records(workspace)[0])["entries"]  # a warm worker is worth it?
    assert entries > 30  # the folders and files of the two packages, pkgtool's own and more
    assert lint() == (1, first, True)
    assert lint(".") == (1, first, False)  # another command line: its own record
    assert lint(".") == (1, first, True)


@pytest.mark.parametrize("change", [
    "edit", "add_file", "add_folder_file", "add_package", "remove_package", "ignore_marker",
    "config", "rename_module", "chmod"])
def test_any_change_the_run_could_see_is_never_replayed(workspace: Path, lint: Lint,
                                                        change: str) -> None:
    lint()
    assert lint()[2]
    listener = workspace / "src" / "listener"
    use = listener / "listener" / "use.py"
    if change == "edit":  # same size, same modification time: the change time still differs
        stat = use.stat()
        use.write_text("import talker\nx = 1\n")
        os.utime(use, ns=(stat.st_atime_ns, stat.st_mtime_ns))
    elif change == "add_file":
        (listener / "listener" / "more.py").write_text("y = z\n")
    elif change == "add_folder_file":
        write_tree(listener / "launch", {"x.launch.py": "import nothing_here\n"})
    elif change == "add_package":
        write_tree(workspace / "src" / "third", correct_package_files("third"))
    elif change == "remove_package":
        shutil.rmtree(workspace / "src" / "talker")
    elif change == "ignore_marker":
        (listener / "COLCON_IGNORE").write_text("")
    elif change == "config":
        (workspace / "pyproject.toml").write_text('[tool.pkgtool]\nignore = ["PYC001"]\n')
    elif change == "rename_module":
        (workspace / "src" / "talker" / "talker").rename(workspace / "src" / "talker" / "t2")
    elif change == "chmod":
        use.chmod(0)
    code, now, replayed = lint()
    assert not replayed
    assert (code, now) == lint(no_cache=True)[:2]
    if os.geteuid() != 0 or change != "chmod":  # root reads a file without permissions
        assert lint() == (code, now, True)


def test_the_command_line_colour_and_folder_are_part_of_the_record(
        workspace: Path, lint: Lint, monkeypatch: pytest.MonkeyPatch) -> None:
    lint()
    assert not lint(select=["PYC"])[2]
    assert lint(select=["PYC"])[2]
    assert not lint(fmt=Format.TEXT)[2]
    monkeypatch.chdir(workspace / "src")
    code, text, replayed = lint("..")
    assert not replayed and json.loads(text)["summary"]
    assert len(_records(workspace)) == 3  # the records of both folders share one cache


def _load(path: Path) -> dict:
    return json.loads(path.read_text().partition("\n")[2])


def _store(path: Path, data: object) -> None:
    """Write ``data`` as pkgtool would, with a valid check: well-formed but wrong."""
    text = json.dumps(data)
    path.write_text(f"{binascii.crc32(text.encode()):08x}\n{text}")


def test_a_broken_or_foreign_record_is_ignored_and_replaced(workspace: Path, lint: Lint) -> None:
    _, expected, _ = lint()
    record = _records(workspace)[0]
    whole = _load(record)
    lies = {**whole, "shown": [0, "{}", []]}
    layout = record.parent / f"layout-{whole['layout']}.json"
    shape = _load(layout)
    damaged = [lambda: record.write_text("{not json"), lambda: record.write_text(""),
               lambda: record.write_bytes(b"\xff\xfe\n{}"),
               lambda: record.write_text(record.read_text().replace('"shown":[1', '"shown":[0')),
               lambda: layout.write_text(layout.read_text()[:-2]),
               *(lambda data=data: _store(record, data) for data in [
                   [], {**lies, "schema": "other"}, {**lies, "stamp": ["other"]},
                   {**lies, "times": 1}, {**lies, "layout": "../../x"}, {**lies, "layout": 7},
                   {**whole, "shown": [0, 1, 2]}]),
               *(lambda data=data: _store(layout, data) for data in [
                   {**shape, "folders": 3}, {**shape, "files": 3}, {**shape, "schema": "x"},
                   {**shape, "folders": shape["folders"][1:]}])]
    for number, damage in enumerate(damaged):
        if number >= len(damaged) - 4:
            _store(record, lies)
        damage()
        assert lint()[:2] == (1, expected), number
        assert lint() == (1, expected, True)


def test_nothing_is_recorded_for_fixes_files_or_packages_above(workspace: Path, lint: Lint
                                                               ) -> None:
    lint(no_cache=True)
    lint("src/listener/listener/use.py")  # a file: its package is found above it
    lint("src/listener/listener")  # a folder inside a package
    lint(diff=True)
    assert _records(workspace) == []


def test_files_changed_just_before_the_run_are_not_trusted(
        workspace: Path, lint: Lint, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(replay, "SETTLED_NS", 3_600 * 10**9)
    monkeypatch.setattr(replay, "FINE_SETTLED_NS", 3_600 * 10**9)
    lint()
    assert not lint()[2] and _records(workspace) == []


def test_only_the_newest_records_are_kept(workspace: Path, lint: Lint) -> None:
    for number in range(replay.KEPT + 3):
        lint(select=["PYC001"] * (number + 1))
    assert len(_records(workspace)) == replay.KEPT


def test_after_an_edit_the_folders_come_from_the_record(
        workspace: Path, lint: Lint, monkeypatch: pytest.MonkeyPatch) -> None:
    from pkgtool import workspace as discovery

    real = discovery._listed
    listed: list[str] = []
    monkeypatch.setattr(discovery, "_listed", lambda folder: listed.append(str(folder))
                        or real(folder))
    (workspace / "src" / "talker" / "helper").symlink_to(workspace / "src" / "talker" / "talker")
    _pause()
    lint()
    listed.clear()
    (workspace / "src" / "listener" / "listener" / "use.py").write_text("import talker\n")
    code, text, replayed = lint()
    assert {f for f in listed if f.startswith(str(workspace))} == {
        str(workspace / "src" / "talker")}  # it holds a link: listed again
    assert not replayed and (code, text) == lint(no_cache=True)[:2]
    assert lint() == (code, text, True)
    listed.clear()
    (workspace / "src" / "listener" / "listener" / "new.py").write_text("x = y\n")
    code, text, replayed = lint()
    assert not replayed and "new.py" in text
    assert str(workspace / "src" / "listener" / "listener") in listed  # changed: listed


def test_after_an_edit_the_packages_and_their_files_come_from_the_record(
        workspace: Path, lint: Lint, monkeypatch: pytest.MonkeyPatch) -> None:
    walks: list[int] = []
    real = command.discover
    monkeypatch.setattr(command, "discover", lambda *a, **k: walks.append(1) or real(*a, **k))
    lint()
    use = workspace / "src" / "listener" / "listener" / "use.py"
    for text in ("import talker\n", "import talker\nx = y\n", "import nothing\n"):
        walks.clear()
        use.write_text(text)
        code, report, replayed = lint()
        assert not walks and not replayed
        assert (code, report) == lint(no_cache=True)[:2]
        _pause()
    walks.clear()
    (workspace / "src" / "talker" / "talker" / "new.py").write_text("")
    assert lint()[:2] == lint(no_cache=True)[:2] and walks  # a folder changed: walked again


def test_after_an_edit_only_the_changed_packages_are_checked(
        workspace: Path, lint: Lint, monkeypatch: pytest.MonkeyPatch) -> None:
    from pkgtool.cache.store import LintCache

    looked: list[str] = []
    real = LintCache.lookup
    monkeypatch.setattr(LintCache, "lookup", lambda self, root, *a, **k:
                        looked.append(root.name) or real(self, root, *a, **k))
    lint()
    talker = workspace / "src" / "talker"
    steps: list[tuple[Callable[[], object], list[str]]] = [
        (lambda: (workspace / "src" / "listener" / "listener" / "use.py").write_text(
            "import talker\nx = z\n"), ["listener"]),
        (lambda: (talker / "talker" / "__init__.py").write_text('"""Talker."""\n'), ["talker"]),
        # What the listener sees of the talker changes: every package is looked up again.
        (lambda: (talker / "package.xml").write_text(
            (talker / "package.xml").read_text().replace("<name>talker<", "<name>speaker<")),
         ["listener", "talker"])]
    for change, expected in steps:
        _pause()
        change()
        looked.clear()
        code, report, replayed = lint()
        assert not replayed and sorted(set(looked)) == expected
        assert (code, report) == lint(no_cache=True)[:2]
        assert lint() == (code, report, True)


def test_a_changed_pyproject_toml_in_a_package_checks_every_package_again(
        workspace: Path, lint: Lint, monkeypatch: pytest.MonkeyPatch) -> None:
    from pkgtool.cache.store import LintCache

    settings = workspace / "src" / "talker" / "pyproject.toml"
    settings.write_text("[tool.pkgtool]\n")
    _pause()
    lint()
    looked: list[str] = []
    real = LintCache.lookup
    monkeypatch.setattr(LintCache, "lookup", lambda self, root, *a, **k:
                        looked.append(root.name) or real(self, root, *a, **k))
    settings.write_text('[tool.pkgtool]\nignore = ["PYC001"]\n')
    code, report, replayed = lint()
    assert not replayed and sorted(set(looked)) == ["listener", "talker"]
    assert (code, report) == lint(no_cache=True)[:2]
