"""The reference catalogue matches the shipped packages, and `reference list` shows it."""

from __future__ import annotations

from pathlib import Path

import pytest
from typer.testing import CliRunner

from pkgtool.cli import _register, app
from pkgtool.commands.reference import SUPPORT_FOLDER, RequestError, catalog
from pkgtool.model.package import load_package
from pkgtool.resources import resource_dir

_register()
ROOT = resource_dir("reference_packages")


def _scripts(name: str) -> set[str]:
    setup = load_package(ROOT / name).setup_py
    assert setup is not None
    return {entry.name for entry in setup.console_scripts}


@pytest.mark.parametrize("entry", catalog(), ids=lambda e: e.name)
def test_every_catalogued_package_exists_with_the_listed_nodes(entry) -> None:
    assert (ROOT / entry.name / "package.xml").is_file()
    assert load_package(ROOT / entry.name).name == entry.name
    assert set(entry.nodes) == _scripts(entry.name)
    for support in entry.support:
        assert (ROOT / SUPPORT_FOLDER / support / "package.xml").is_file()


def test_catalogue_names_each_package_once_and_every_folder_is_catalogued() -> None:
    names = [entry.name for entry in catalog()]
    assert len(names) == len(set(names))
    folders = {p.parent.name for p in ROOT.glob("*/package.xml")}
    assert folders == set(names)
    assert {"physical_ai_sensors", "physical_ai_camera", "physical_ai_navigation"} <= set(names)


def test_unreadable_catalogue_is_a_sentence_not_a_traceback(tmp_path: Path) -> None:
    (tmp_path / "catalog.toml").write_text("[[package]]\nname = 'x'\n")
    with pytest.raises(RequestError, match="cannot be read"):
        catalog(tmp_path)


def test_list_shows_name_document_and_nodes() -> None:
    result = CliRunner().invoke(app, ["reference", "list"], env={"COLUMNS": "200"})
    assert result.exit_code == 0, result.output
    for entry in catalog():
        line = next(line for line in result.output.splitlines() if f" {entry.name} " in line)
        assert entry.document in line and entry.nodes[0] in line
