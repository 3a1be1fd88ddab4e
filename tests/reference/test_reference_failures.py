"""A real `pkgtool reference test` run that must fail: lint findings and a failing test count."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from typer.testing import CliRunner

from pkgtool.cli import _register, app
from pkgtool.resources import resource_dir

pytestmark = [pytest.mark.ros, pytest.mark.colcon, pytest.mark.slow]
_register()
NAME = "physical_ai_camera"


@pytest.fixture
def broken_root(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A reference folder whose one package imports an undeclared module and fails a test."""
    root = tmp_path / "reference_packages"
    package = root / NAME
    shutil.copytree(resource_dir("reference_packages") / NAME, package)
    (root / "catalog.toml").write_text(
        f'[[package]]\nname = "{NAME}"\ndocument = "000"\n'
        'nodes = ["image_subscriber", "object_detector"]\n')
    for test in (package / "test").glob("test_*.py"):
        if test.name != "test_image_processor.py":
            test.unlink()
    (package / "test" / "test_broken.py").write_text(
        "def test_wrong_expectation():\n    assert 1 * 0.1 == 0.01\n")
    module = package / NAME / "utils" / "color_detection.py"
    module.write_text(module.read_text().replace("import cv2\n", "import cv2\nimport yaml\n", 1))
    monkeypatch.setattr("pkgtool.commands.reference._root", lambda: root)
    return root


def test_failures_are_counted_shown_and_exit_1(broken_root: Path, tmp_path: Path) -> None:
    keep = tmp_path / "workspace"
    result = CliRunner().invoke(app, ["reference", "test", NAME, "--jobs", "1", "--keep",
                                      str(keep)], env={"COLUMNS": "160"})
    assert result.exit_code == 1, result.output
    row = next(line for line in result.output.splitlines() if f" {NAME} " in line)
    cells = [cell.strip() for cell in row.split("│") if cell.strip()]
    assert cells[:3] == [NAME, "1", "ok"]
    assert int(cells[3]) >= 10 and cells[4] == "1"  # passed / failed, from pytest's JUnit XML
    assert "DEP001" in result.output and "yaml" in result.output
    assert "test_wrong_expectation: failed" in result.output
    assert (keep / "build" / NAME / "pytest.xml").is_file()
    assert f"workspace kept in {keep}" in result.output
