"""Submissions as Moodle and Canvas download them, labelled by student.

Moodle's "Download all submissions", unpacked, holds one folder per student named
``Full Name_123456_assignsubmission_file_`` with the uploaded files inside. Canvas's
``submissions.zip``, unpacked, holds one file per student named
``lastfirst_[LATE_]123456_7890123_original-name.zip``. Both become one submission labelled
``<name>_<id>``; any other entry keeps the plain label of :mod:`pkgtool.grade.batch`.
"""

from __future__ import annotations

import re
from pathlib import Path

from pkgtool.grade.extract import is_archive
from pkgtool.lazy_regex import lazy_pattern

_MOODLE = lazy_pattern(r"(?P<name>.+?)_(?P<id>\d+)_assignsubmission_[a-z]+_?")
_CANVAS = lazy_pattern(r"(?P<name>[A-Za-z0-9-]+?)_(?:LATE_)?(?P<id>\d+)_\d+_.+", re.IGNORECASE)


def lms_submission(entry: Path) -> tuple[str, Path] | None:
    """``(label, path)`` when ``entry`` is a Moodle student folder or a Canvas file, else None.

    A Moodle folder holding only the uploaded archive is unpacked as that archive when graded
    (:func:`pkgtool.grade.extract.lone_archive`).
    """
    if entry.is_dir() and not entry.is_symlink():
        found = _MOODLE.fullmatch(entry.name)
        return None if found is None else (f"{found['name']}_{found['id']}", entry)
    found = _CANVAS.fullmatch(entry.name)
    if found is None or not is_archive(entry):
        return None
    return f"{found['name']}_{found['id']}", entry
