"""Moodle and Canvas downloads: one submission per student, labelled by student."""

from __future__ import annotations

import zipfile
from pathlib import Path

from pkgtool.grade.batch import expand
from pkgtool.grade.extract import lone_archive


def _zip(path: Path) -> Path:
    with zipfile.ZipFile(path, "w") as archive:
        archive.writestr("robot_monitor/package.xml", "<package/>")
    return path


def test_moodle_folders_are_labelled_by_student(tmp_path: Path) -> None:
    alice = tmp_path / "Alice Smith_101_assignsubmission_file_"
    alice.mkdir()
    upload = _zip(alice / "robot_monitor.zip")
    bob = tmp_path / "Bob Jones_102_assignsubmission_file_"
    (bob / "robot_monitor").mkdir(parents=True)
    (bob / "robot_monitor" / "package.xml").write_text("<package/>")
    (bob / "notes.txt").write_text("two entries: the folder itself is graded")
    assert expand([tmp_path], batch=True) == [("Alice Smith_101", alice),
                                              ("Bob Jones_102", bob)]
    assert lone_archive(alice) == upload and lone_archive(bob) is None


def test_only_a_lone_regular_archive_stands_for_its_folder(tmp_path: Path) -> None:
    linked = tmp_path / "linked"
    linked.mkdir()
    (linked / "upload.zip").symlink_to(_zip(tmp_path / "elsewhere.zip"))
    hidden_too = tmp_path / "hidden_too"
    hidden_too.mkdir()
    upload = _zip(hidden_too / "upload.zip")
    (hidden_too / ".DS_Store").write_text("ignored")
    assert lone_archive(linked) is None and lone_archive(hidden_too) == upload


def test_canvas_files_are_labelled_by_student(tmp_path: Path) -> None:
    late = _zip(tmp_path / "smithalice_LATE_101_555_robot_monitor.zip")
    ontime = _zip(tmp_path / "jonesbob_102_556_robot_monitor-1.zip")
    plain = _zip(tmp_path / "carol.zip")
    (tmp_path / "jonesbob_102_557_readme.txt").write_text("not an archive: not a submission")
    assert expand([tmp_path], batch=True) == [("carol", plain), ("jonesbob_102", ontime),
                                              ("smithalice_101", late)]


def test_a_label_seen_twice_stays_distinct(tmp_path: Path) -> None:
    first = _zip(tmp_path / "jonesbob_102_556_a.zip")
    second = _zip(tmp_path / "jonesbob_102_557_b.zip")
    assert expand([tmp_path], batch=True) == [("jonesbob_102", first),
                                              ("jonesbob_102-2", second)]
