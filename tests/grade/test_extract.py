"""Safe unpacking of submission archives: every escape is refused before anything is written."""

from __future__ import annotations

import io
import os
import tarfile
import zipfile
from collections.abc import Callable
from pathlib import Path

import pytest

from pkgtool.grade.extract import ExtractLimits, SubmissionError, extract
from tests.grade.synthetic import bytes_zip


def _zip(tmp_path: Path, members: dict[str, bytes], **kwargs: str) -> Path:
    archive = tmp_path / "submission.zip"
    archive.write_bytes(bytes_zip(members, **kwargs))
    return archive


def _tar(tmp_path: Path, build: Callable[[tarfile.TarFile], object]) -> Path:
    archive = tmp_path / "submission.tar.gz"
    with tarfile.open(archive, "w:gz") as bundle:
        build(bundle)
    return archive


def _add(bundle: tarfile.TarFile, name: str, data: bytes = b"x", **attrs: object) -> None:
    info = tarfile.TarInfo(name)
    info.size = len(data)
    for key, value in attrs.items():
        setattr(info, key, value)
    bundle.addfile(info, io.BytesIO(data) if info.isreg() else None)


def _dest(tmp_path: Path) -> Path:
    dest = tmp_path / "out" / "inner"
    dest.mkdir(parents=True)
    return dest


def test_a_plain_zip_unpacks_with_executable_bits_kept(tmp_path: Path) -> None:
    archive = tmp_path / "ok.zip"
    with zipfile.ZipFile(archive, "w") as bundle:
        info = zipfile.ZipInfo("pkg/run.sh")
        info.external_attr = 0o100755 << 16
        bundle.writestr(info, "#!/bin/sh\n")
        bundle.writestr("pkg/package.xml", "<package/>")
    dest = _dest(tmp_path)
    extract(archive, dest)
    assert (dest / "pkg" / "package.xml").read_text() == "<package/>"
    assert os.access(dest / "pkg" / "run.sh", os.X_OK)


@pytest.mark.parametrize(("name", "message"), [
    ("../escaped.txt", "points outside the submission"),
    ("pkg/../../escaped.txt", "points outside the submission"),
    ("/etc/escaped.txt", "absolute path"),
    ("C:\\escaped.txt", "absolute path"),
])
def test_zip_entries_leaving_the_folder_are_refused(tmp_path: Path, name: str,
                                                    message: str) -> None:
    archive = _zip(tmp_path, {"pkg/package.xml": b"<package/>", name: b"escaped"})
    dest = _dest(tmp_path)
    with pytest.raises(SubmissionError, match=message):
        extract(archive, dest)
    assert not list(dest.rglob("*")), "nothing may be written before every entry is checked"
    assert not (tmp_path / "out" / "escaped.txt").exists()


def test_zip_symlinks_are_skipped(tmp_path: Path) -> None:
    archive = _zip(tmp_path, {"pkg/a.py": b""}, symlink="/etc/passwd")
    dest = _dest(tmp_path)
    extract(archive, dest)
    assert sorted(p.name for p in dest.rglob("*")) == ["a.py", "pkg"]


def test_a_zip_bomb_is_refused_before_it_expands(tmp_path: Path) -> None:
    archive = _zip(tmp_path, {"bomb.txt": b"0" * (50 * 1024 * 1024)})
    assert archive.stat().st_size < 200_000
    with pytest.raises(SubmissionError, match="zip bomb"):
        extract(archive, _dest(tmp_path))


def test_caps_on_file_count_and_size(tmp_path: Path) -> None:
    archive = _zip(tmp_path, {f"f{i}.txt": b"data" for i in range(20)})
    with pytest.raises(SubmissionError, match="more than 10 files"):
        extract(archive, _dest(tmp_path), ExtractLimits(max_files=10))
    with pytest.raises(SubmissionError, match="unpacks to more than"):
        extract(archive, _dest(tmp_path / "b"), ExtractLimits(max_bytes=40))


@pytest.mark.parametrize(("build", "message"), [
    (lambda t: _add(t, "../escaped.txt"), "outside the submission"),
    (lambda t: _add(t, "/abs.txt"), "absolute path"),
    (lambda t: _add(t, "dev", type=tarfile.CHRTYPE), "refused"),
])
def test_tar_escapes_are_refused(tmp_path: Path, build: Callable[[tarfile.TarFile], None],
                                 message: str) -> None:
    archive = _tar(tmp_path, lambda bundle: (_add(bundle, "pkg/package.xml"), build(bundle)))
    dest = _dest(tmp_path)
    with pytest.raises(SubmissionError, match=message):
        extract(archive, dest)
    assert not list(dest.rglob("*"))


@pytest.mark.parametrize(("kind", "target"), [
    (tarfile.SYMTYPE, "/etc/passwd"), (tarfile.SYMTYPE, "../../x"),
    (tarfile.LNKTYPE, "/etc/passwd")])
def test_tar_links_out_of_the_submission_are_skipped(
        tmp_path: Path, kind: bytes, target: str) -> None:
    archive = _tar(tmp_path, lambda bundle: (
        _add(bundle, "pkg/package.xml"), _add(bundle, "pkg/link", type=kind, linkname=target)))
    dest = _dest(tmp_path)
    extract(archive, dest)
    assert sorted(p.name for p in dest.rglob("*")) == ["package.xml", "pkg"]
    assert not (tmp_path / "out" / "x").exists()


def test_tar_links_inside_the_submission_are_kept(tmp_path: Path) -> None:
    archive = _tar(tmp_path, lambda bundle: (
        _add(bundle, "pkg/setup.py", b"# setup"),
        _add(bundle, "pkg/alias.py", type=tarfile.SYMTYPE, linkname="setup.py")))
    dest = _dest(tmp_path)
    extract(archive, dest)
    assert (dest / "pkg" / "alias.py").read_text() == "# setup"


def test_a_corrupt_archive_is_a_submission_error(tmp_path: Path) -> None:
    archive = tmp_path / "broken.zip"
    archive.write_bytes(b"PK\x03\x04 not really")
    with pytest.raises(SubmissionError, match="not a readable archive"):
        extract(archive, _dest(tmp_path))


def _non_utf8_zip(tmp_path: Path) -> Path:
    """A zip whose name is flagged UTF-8 but holds a byte that is not (what some tools write)."""
    archive = _zip(tmp_path, {"pkg/caf\u00e9.py": b"x"})
    archive.write_bytes(archive.read_bytes().replace("\u00e9".encode(), b"\xff\xa9"))
    return archive


@pytest.mark.parametrize(("build", "reason"), [
    (_non_utf8_zip, "has file names that are not valid UTF-8; rename the files"),
    (lambda tmp: _zip(tmp, {"pkg/" + "n" * 300 + ".py": b"x"}), "longer than 255 bytes"),
    (lambda tmp: _zip(tmp, {"/".join(["d" * 200] * 6) + "/x.py": b"x"}),
     "has a path longer than 1024 bytes"),
    (lambda tmp: _zip(tmp, {"pkg": b"x", "pkg/setup.py": b"x"}),
     "archive entry `pkg/setup.py` is inside `pkg`, which is a file"),
    (lambda tmp: _tar(tmp, lambda t: (_add(t, "pkg", type=tarfile.DIRTYPE),
                                      _add(t, "pkg"))),
     "archive entry `pkg` is a file and a folder; each name may appear once"),
    (lambda tmp: _tar(tmp, lambda t: _add(t, "pkg/fifo", type=tarfile.FIFOTYPE)),
     "is a device file or a FIFO"),
])
def test_unusable_names_and_members_get_a_precise_reason(
        tmp_path: Path, build: Callable[[Path], Path], reason: str) -> None:
    with pytest.raises(SubmissionError) as refused:
        extract(build(tmp_path), _dest(tmp_path))
    assert reason in str(refused.value)
    assert not list(_dest_root(tmp_path).rglob("*.py"))


def _dest_root(tmp_path: Path) -> Path:
    return tmp_path / "out"
