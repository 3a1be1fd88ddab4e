"""Writing: --dry-run writes nothing, existing folders are refused, --force only adds, and a
failure halfway leaves nothing behind."""

from __future__ import annotations

import os
import stat
from pathlib import Path

import pytest

from pkgtool.commands import ExitCode
from pkgtool.commands.create import run
from tests.create.conftest import ALL_KINDS, expected_files, request


def _snapshot(folder: Path) -> dict[str, bytes]:
    return {p.relative_to(folder).as_posix(): p.read_bytes() if p.is_file() else b"<dir>"
            for p in sorted(folder.rglob("*"))}


def test_dry_run_draws_the_tree_and_writes_nothing(create, tmp_path: Path) -> None:
    result = create(nodes=("talker:publisher",), launch=True, dry_run=True)
    assert result.exit_code == ExitCode.OK and result.dry_run
    assert list(tmp_path.iterdir()) == []
    assert result.tree.splitlines()[:4] == ["demo_pkg/", "├── demo_pkg/", "│   ├── __init__.py",
                                            "│   └── talker.py"]
    assert "└── setup.py" in result.tree and "test_talker.py" in result.tree
    assert list(result.written) == expected_files("demo_pkg", ("talker:publisher",), launch=True)


def test_an_existing_destination_is_refused_untouched(create, tmp_path: Path) -> None:
    (tmp_path / "demo_pkg").mkdir()
    (tmp_path / "demo_pkg" / "setup.py").write_text("# mine\n")
    before = _snapshot(tmp_path)
    for dry_run in (False, True):
        result = create(nodes=("talker:publisher",), dry_run=dry_run)
        assert result.exit_code == ExitCode.USAGE
        assert "already exists" in result.error and "--force" in result.error
    assert _snapshot(tmp_path) == before


def test_force_adds_missing_files_and_keeps_the_user_s(create, tmp_path: Path) -> None:
    first = create(nodes=("talker:publisher",))
    root = first.root
    setup = (root / "setup.py").read_text()
    (root / "setup.py").write_text("# edited by the user\n" + setup)
    (root / "demo_pkg" / "talker.py").unlink()
    (root / "notes.txt").write_text("mine\n")
    again = create(nodes=("talker:publisher", "beat:timer"), force=True)
    assert again.exit_code == ExitCode.OK
    assert set(again.written) == {"demo_pkg/talker.py", "demo_pkg/beat.py", "test/test_beat.py",
                                  "setup.py"}
    assert "package.xml" in again.kept and "(exists, kept)" in again.tree
    assert "setup.py  (edited)" in again.tree
    assert (root / "setup.py").read_text() == "# edited by the user\n" + setup.replace(
        "'talker = demo_pkg.talker:main',\n",
        "'talker = demo_pkg.talker:main',\n            'beat = demo_pkg.beat:main',\n")
    assert (root / "notes.txt").read_text() == "mine\n"
    assert (root / "demo_pkg" / "beat.py").is_file()


def test_force_refuses_nodes_it_cannot_register_and_writes_nothing(
        create, tmp_path: Path) -> None:
    root = create(nodes=("talker:publisher",)).root
    (root / "setup.py").write_text("# edited by the user\n")
    before = _snapshot(tmp_path)
    again = create(nodes=("beat:timer",), force=True)
    assert again.exit_code == ExitCode.USAGE and "no `setup(...)` call" in again.error
    assert _snapshot(tmp_path) == before


def test_force_refuses_a_file_where_a_folder_belongs(create, tmp_path: Path) -> None:
    (tmp_path / "demo_pkg").mkdir()
    (tmp_path / "demo_pkg" / "test").write_text("not a folder\n")
    before = _snapshot(tmp_path)
    result = create(force=True)
    assert result.exit_code == ExitCode.USAGE and "`test` is in the way" in result.error
    assert _snapshot(tmp_path) == before


def _failing_after(count: int, error: BaseException | None = None):
    seen: list[str] = []

    def hook(relpath: str) -> None:
        seen.append(relpath)
        if len(seen) > count:
            raise error or OSError(28, "No space left on device", relpath)

    return hook


def test_ctrl_c_halfway_leaves_nothing_and_goes_on_to_the_cli(tmp_path: Path) -> None:
    """The CLI then says "Interrupted: nothing was written" (tests/test_cli_conventions.py)."""
    with pytest.raises(KeyboardInterrupt):
        run(request(tmp_path / "ws", nodes=ALL_KINDS),
            before_write=_failing_after(5, KeyboardInterrupt()))
    assert list(tmp_path.iterdir()) == []


def test_a_failure_halfway_leaves_no_half_written_package(tmp_path: Path) -> None:
    result = run(request(tmp_path / "new" / "ws", nodes=ALL_KINDS),
                 before_write=_failing_after(5))
    assert result.exit_code == ExitCode.USAGE
    assert "No space left on device" in result.error and "Nothing was left behind" in result.error
    assert list(tmp_path.iterdir()) == []  # no package, staging or destination folder


def test_a_failure_with_force_removes_only_what_it_added(create, tmp_path: Path) -> None:
    create(nodes=("talker:publisher",))
    root = tmp_path / "demo_pkg"
    (root / "setup.py").write_text("# edited\n")
    before = _snapshot(tmp_path)
    failing = run(request(tmp_path, nodes=("talker:publisher", "a_b:timer", "c_d:timer")),
                  force=True, before_write=_failing_after(2))
    assert failing.exit_code == ExitCode.USAGE
    assert _snapshot(tmp_path) == before


def test_files_get_the_umask_s_permissions(create, tmp_path: Path) -> None:
    old = os.umask(0o022)
    try:
        result = create(nodes=("talker:publisher",))
    finally:
        os.umask(old)
    assert stat.S_IMODE(result.root.stat().st_mode) == 0o755
    assert stat.S_IMODE((result.root / "setup.py").stat().st_mode) == 0o644


@pytest.mark.parametrize("bad, values", [("bad-name", {}),
                                         ("ok_name", {"nodes": ("talker:teleporter",)})])
def test_nothing_is_written_for_a_refused_request(tmp_path: Path, bad: str, values: dict) -> None:
    result = run(request(tmp_path, bad, **values))
    assert result.exit_code == ExitCode.USAGE and result.error
    assert list(tmp_path.iterdir()) == []
