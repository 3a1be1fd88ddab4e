"""Run flake8 in-process with ament's settings and collect what it reports."""

from __future__ import annotations

import functools
from pathlib import Path
from typing import Any

from pkgtool.ament.settings import AMENT_FLAKE8_ARGS
from pkgtool.records import record


@record
class StyleViolation:
    """One flake8 or pydocstyle report: package-relative path, 1-based line and column."""

    path: str
    line: int
    col: int
    code: str
    text: str


class StyleToolMissing(RuntimeError):
    """flake8 or pydocstyle is not installed (they come with ``pkgtool-ros[style]``)."""


@functools.lru_cache(maxsize=1)
def _guide() -> tuple[Any, list[Any]]:
    """One configured flake8 style guide per process (plugin loading costs ~0.2 s)."""
    try:
        from flake8.api.legacy import StyleGuide
        from flake8.formatting.base import BaseFormatter
        from flake8.main.application import Application
        from flake8.options.parse_args import parse_args
    except ImportError as error:
        raise StyleToolMissing("`flake8` is not installed") from error
    sink: list[Any] = []

    class _Collect(BaseFormatter):  # type: ignore[misc]
        def handle(self, error: Any) -> None:
            sink.append(error)

        def after_init(self) -> None:
            self.output_fd = None

    application = Application()
    application.plugins, application.options = parse_args(["--isolated", "--jobs=1",
                                                           *AMENT_FLAKE8_ARGS])
    application.make_formatter()
    application.make_guide()
    application.make_file_checker_manager([])
    guide = StyleGuide(application)
    guide.init_report(_Collect)
    return guide, sink


def run_flake8(root: Path, files: list[str]) -> list[StyleViolation]:
    """flake8 over ``files`` (relative to ``root``) with ament's configuration, noqa honoured."""
    if not files:
        return []
    guide, sink = _guide()
    sink.clear()
    guide.check_files([str(root / f) for f in files])
    base = root.resolve()
    found = [StyleViolation(Path(e.filename).resolve().relative_to(base).as_posix(),
                            e.line_number, e.column_number, e.code, e.text) for e in sink]
    sink.clear()
    return sorted(found, key=lambda v: (v.path, v.line, v.col, v.code))
