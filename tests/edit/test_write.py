"""The writer: atomic, all or nothing, permissions and owner kept, never out of the package."""

from __future__ import annotations

import os
import stat
from pathlib import Path

import pytest

from pkgtool.edit import Edit, EditError
from pkgtool.edit.changes import Session, compute
from pkgtool.edit.write import Write, write_all


def _package(tmp_path: Path) -> Path:
    root = tmp_path / "pkg"
    root.mkdir()
    (root / "setup.py").write_bytes(b"\xef\xbb\xbfx = 1\r\n")
    (root / "package.xml").write_text("<package/>\n")
    return root


def test_bytes_bom_crlf_mode_and_owner_are_kept(tmp_path: Path) -> None:
    root = _package(tmp_path)
    target = root / "setup.py"
    os.chmod(target, 0o751)
    if os.geteuid() == 0:
        os.chown(target, 4321, 4322)
    compute(root, [Edit("setup.py", 5, 5, "\r\ny = 2")]).write()
    assert target.read_bytes() == b"\xef\xbb\xbfx = 1\r\ny = 2\r\n"
    status = target.stat()
    assert stat.S_IMODE(status.st_mode) == 0o751
    if os.geteuid() == 0:
        assert (status.st_uid, status.st_gid) == (4321, 4322)
    assert sorted(p.name for p in root.iterdir()) == ["package.xml", "setup.py"]


def test_a_symlink_out_of_the_package_is_refused_before_anything_is_written(tmp_path: Path
                                                                            ) -> None:
    root = _package(tmp_path)
    outside = tmp_path / "outside.py"
    outside.write_text("secret = 1\n")
    (root / "linked.py").symlink_to(outside)
    with pytest.raises(EditError, match="outside the package"):
        compute(root, [Edit("setup.py", 0, 0, "# a\n"), Edit("linked.py", 0, 0, "# b\n")]
                ).write()
    assert outside.read_text() == "secret = 1\n"
    assert (root / "setup.py").read_bytes() == b"\xef\xbb\xbfx = 1\r\n"


def test_a_symlinked_folder_out_of_the_package_is_refused_for_new_files(tmp_path: Path) -> None:
    root = _package(tmp_path)
    (tmp_path / "elsewhere").mkdir()
    (root / "launch").symlink_to(tmp_path / "elsewhere")
    with pytest.raises(EditError, match="outside the package"):
        compute(root, [Edit("launch/a.launch.py", 0, 0, "x = 1\n", create=True)]).write()
    assert not list((tmp_path / "elsewhere").iterdir())


def test_a_symlink_inside_the_package_is_written_through_and_kept(tmp_path: Path) -> None:
    root = _package(tmp_path)
    (root / "real.py").write_text("a = 1\n")
    (root / "alias.py").symlink_to("real.py")
    compute(root, [Edit("alias.py", 0, 0, "# top\n")]).write()
    assert (root / "alias.py").is_symlink()
    assert (root / "real.py").read_text() == "# top\na = 1\n"


def test_a_failing_rename_restores_every_file_already_replaced(tmp_path: Path,
                                                               monkeypatch: pytest.MonkeyPatch
                                                               ) -> None:
    root = _package(tmp_path)
    real_replace = os.replace
    calls = []

    def flaky(source: object, target: object) -> None:
        calls.append(target)
        if len(calls) == 2:
            raise OSError(28, "No space left on device")
        real_replace(source, target)

    monkeypatch.setattr(os, "replace", flaky)
    changes = compute(root, [Edit("package.xml", 0, 0, "<!-- a -->\n"),
                             Edit("setup.py", 0, 0, "# b\n"),
                             Edit("new/file.py", 0, 0, "c = 1\n", create=True)])
    with pytest.raises(OSError, match="No space"):
        changes.write()
    monkeypatch.setattr(os, "replace", real_replace)
    assert (root / "package.xml").read_text() == "<package/>\n"
    assert (root / "setup.py").read_bytes() == b"\xef\xbb\xbfx = 1\r\n"
    assert sorted(p.name for p in root.iterdir()) == ["package.xml", "setup.py"]


def test_a_new_file_never_replaces_one_that_appeared(tmp_path: Path) -> None:
    root = _package(tmp_path)
    changes = compute(root, [Edit("added.py", 0, 0, "mine = 1\n", create=True)])
    (root / "added.py").write_text("theirs = 1\n")
    with pytest.raises(EditError, match="appeared"):
        changes.write()
    assert (root / "added.py").read_text() == "theirs = 1\n"


def test_creating_an_existing_file_is_idempotent_or_refused(tmp_path: Path) -> None:
    root = _package(tmp_path)
    assert not compute(root, [Edit("package.xml", 0, 0, "<package/>\n", create=True)])
    with pytest.raises(EditError, match="already exists"):
        compute(root, [Edit("package.xml", 0, 0, "<other/>\n", create=True)])


def test_an_edit_that_would_break_parsing_is_never_written(tmp_path: Path) -> None:
    root = _package(tmp_path)
    with pytest.raises(EditError, match="would not parse"):
        compute(root, [Edit("package.xml", 0, 0, "<")])
    assert (root / "package.xml").read_text() == "<package/>\n"


def test_undecodable_and_binary_files_are_not_edited(tmp_path: Path) -> None:
    root = _package(tmp_path)
    (root / "latin.xml").write_bytes("<a>é</a>".encode("latin-1"))
    (root / "blob.py").write_bytes(b"\0\1")
    for path in ("latin.xml", "blob.py"):
        with pytest.raises(EditError, match="does not edit"):
            compute(root, [Edit(path, 0, 0, "x")])


def test_a_declared_python_encoding_round_trips(tmp_path: Path) -> None:
    root = _package(tmp_path)
    data = "# -*- coding: latin-1 -*-\nname = 'Jos\xe9'\n".encode("latin-1")
    (root / "enc.py").write_bytes(data)
    compute(root, [Edit("enc.py", len("# -*- coding: latin-1 -*-\n"), len(
        "# -*- coding: latin-1 -*-\n"), "# é\n")]).write()
    assert (root / "enc.py").read_bytes() == data.replace(b"\nname", "\n# é\nname".encode(
        "latin-1"))


def test_session_diff_and_write_all_or_nothing(tmp_path: Path) -> None:
    root = _package(tmp_path)
    session = Session(root)
    session.apply([Edit("package.xml", 10, 10, "\n<!-- x -->")])
    session.apply([Edit("package.xml", 0, 0, "<?xml version='1.0'?>\n")])
    changes = session.changes()
    assert changes.paths == ("package.xml",)
    assert "+<?xml version='1.0'?>" in changes.diff()
    assert (root / "package.xml").read_text() == "<package/>\n"  # nothing written yet
    changes.write()
    assert (root / "package.xml").read_text() == "<?xml version='1.0'?>\n<package/>\n<!-- x -->\n"


def test_write_all_refuses_a_folder_in_the_way(tmp_path: Path) -> None:
    root = _package(tmp_path)
    (root / "folder").mkdir()
    with pytest.raises(EditError, match="folder"):
        write_all(root, [Write("folder", b"x", create=True)])


def test_fix_changes_apply_safe_fixes_and_defer_overlaps(tmp_path: Path) -> None:
    from pkgtool.edit import Fix
    from pkgtool.edit.changes import fix_changes

    root = _package(tmp_path)
    first = Fix("comment", (Edit("package.xml", 0, 0, "<!-- a -->\n"),))
    clash = Fix("other comment", (Edit("package.xml", 0, 0, "<!-- b -->\n"),))
    risky = Fix("drop x", (Edit("setup.py", 0, 5, "x = 2"),), safe=False)
    changes, applied, deferred = fix_changes(root, [first, clash, risky])
    assert (applied, deferred) == ([first], [clash])
    assert changes.paths == ("package.xml",)
    changes, applied, _ = fix_changes(root, [risky], unsafe=True)
    changes.write()
    assert (root / "setup.py").read_bytes() == b"\xef\xbb\xbfx = 2\r\n"
