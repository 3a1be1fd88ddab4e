"""``grade --export-gradescope``: the autograder.zip that Gradescope builds its image from.

The zip holds ``setup.sh`` and ``run_autograder`` (from ``templates/gradescope/``), the rubric
with its hidden tests (``rubric/``), ``requirements.txt`` (the pinned versions of
``requirements/lock.txt`` that pkgtool with its ``ros`` and ``style`` extras needs) and
pkgtool's own wheel built from this source checkout (``wheels/``). The same checkout and
rubric give the same bytes: entries are sorted, dated 1980-01-01 and built with
``SOURCE_DATE_EPOCH`` set.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import tempfile
import zipfile
from importlib import metadata
from pathlib import Path

from packaging.requirements import Requirement

from pkgtool.compat import tomllib
from pkgtool.grade.rubric import RubricError, load_rubric
from pkgtool.resources import resource_dir
from pkgtool.lazy_regex import lazy_pattern

EXTRAS = ("ros", "style")
"""The extras grading needs: ROS 2 and colcon to build and test, the style checkers."""
_PINNED = lazy_pattern(r"^([A-Za-z0-9][A-Za-z0-9._-]*)==(\S+)", re.MULTILINE)
_EPOCH = "315532800"  # 1980-01-01, the earliest date a zip entry can hold
UV_VERSION = "0.13.9"
BUILD_BACKEND = ("setuptools==68.1.2", "wheel==0.45.1")
"""Pinned in the wheel's isolated build so that the same checkout gives the same bytes."""
TIMEOUT_S = 3000
"""run_autograder's limit on one grading (Gradescope's own default limit is longer)."""


class BundleError(Exception):
    """The bundle cannot be built; the message says why and what to do."""


def checkout() -> Path:
    """pkgtool's source checkout (the wheel is built from it), or BundleError."""
    root = Path(__file__).resolve().parents[2]
    if not all((root / name).is_file() for name in ("pyproject.toml", "requirements/lock.txt")):
        raise BundleError("--export-gradescope builds pkgtool's wheel from its source checkout, "
                          "and this pkgtool is installed without one: run it from a clone.")
    return root


def _name(text: str) -> str:
    return re.sub(r"[-_.]+", "-", text).lower()


def needed(distribution: str = "pkgtool-ros", extras: tuple[str, ...] = EXTRAS) -> set[str]:
    """Normalised names of what ``distribution[extras]`` needs, read from installed metadata."""
    seen: set[str] = set()
    todo = [(distribution, frozenset(extras))]
    while todo:
        name, wanted = todo.pop()
        try:
            requires = metadata.requires(name) or []
        except metadata.PackageNotFoundError:
            continue
        for text in requires:
            requirement = Requirement(text)
            marker = requirement.marker
            if marker and not any(marker.evaluate({"extra": e}) for e in (*wanted, "")):
                continue
            key = _name(requirement.name)
            if key not in seen:
                seen.add(key)
                todo.append((requirement.name, frozenset(requirement.extras)))
    return seen


def requirements(lock: str) -> str:
    """The lines of the lock that grading needs, as ``name==version``."""
    names = needed()
    pins = [f"{name}=={version}" for name, version in _PINNED.findall(lock)
            if _name(name) in names]
    return "# pkgtool-ros[" + ",".join(EXTRAS) + "] as locked in requirements/lock.txt\n" + \
        "\n".join(sorted(pins, key=str.lower)) + "\n"


_NOT_SOURCE = shutil.ignore_patterns(".git", ".venv", "build", "dist", "*.egg-info", "__pycache__",
                                     ".test-artifacts", ".pkgtool_cache")


def _wheel(root: Path, folder: Path) -> Path:
    """pkgtool's wheel, built from a copy of the checkout (which is left untouched)."""
    source = folder / "source"
    shutil.copytree(root, source, ignore=_NOT_SOURCE, symlinks=True)
    constraints = folder / "build-constraints.txt"
    constraints.write_text("".join(f"{pin}\n" for pin in BUILD_BACKEND), encoding="utf-8")
    env = {**os.environ, "SOURCE_DATE_EPOCH": _EPOCH, "PIP_CONSTRAINT": str(constraints)}
    done = subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-deps", "--quiet",
                           "-w", str(folder), str(source)],
                          env=env, capture_output=True, text=True, timeout=600, check=False)
    wheels = sorted(folder.glob("pkgtool_ros-*.whl"))
    if done.returncode != 0 or len(wheels) != 1:
        raise BundleError(f"Building pkgtool's wheel failed:\n{done.stderr[-2000:]}")
    return wheels[0]


def _rubric_files(rubric: Path) -> dict[str, bytes]:
    """``rubric/rubric.toml`` with each hidden-test folder copied beside it and renamed."""
    import tomli_w

    try:
        load_rubric(rubric)
    except RubricError as error:
        raise BundleError(str(error)) from None
    data = tomllib.loads(rubric.read_text(encoding="utf-8"))
    files: dict[str, bytes] = {}
    for index, criterion in enumerate(data.get("criteria", [])):
        if criterion.get("kind") != "hidden":
            continue
        folder = (rubric.parent / criterion["path"]).resolve()
        name = f"hidden_{index + 1}"
        criterion["path"] = name
        for path in sorted(folder.rglob("*")):
            if path.is_file() and not path.is_symlink() and "__pycache__" not in path.parts:
                files[f"rubric/{name}/{path.relative_to(folder).as_posix()}"] = path.read_bytes()
    files["rubric/rubric.toml"] = tomli_w.dumps(data).encode()
    return files


def _add(archive: zipfile.ZipFile, name: str, data: bytes, executable: bool = False) -> None:
    info = zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0))
    info.compress_type = zipfile.ZIP_DEFLATED
    info.external_attr = ((0o100755 if executable else 0o100644) & 0xFFFF) << 16
    archive.writestr(info, data, compresslevel=9)


def build(rubric: Path, output: Path) -> list[str]:
    """Write the bundle for ``rubric`` to ``output``; returns the names it holds."""
    root = checkout()
    files = _rubric_files(rubric)
    templates = resource_dir("templates") / "gradescope"
    for name in ("setup.sh", "run_autograder", "ensure_results.py"):
        text = (templates / name).read_text(encoding="utf-8")
        files[name] = (text.replace("{{ uv_version }}", UV_VERSION)
                       .replace("{{ timeout }}", str(TIMEOUT_S)).encode())
    files["requirements.txt"] = requirements(
        (root / "requirements" / "lock.txt").read_text(encoding="utf-8")).encode()
    with tempfile.TemporaryDirectory(prefix="pkgtool-bundle-") as scratch:
        wheel = _wheel(root, Path(scratch))
        files[f"wheels/{wheel.name}"] = wheel.read_bytes()
    partial = output.with_name(output.name + ".partial")
    with zipfile.ZipFile(partial, "w") as archive:
        for name in sorted(files):
            _add(archive, name, files[name], executable=name in ("setup.sh", "run_autograder"))
    partial.replace(output)
    return sorted(files)
