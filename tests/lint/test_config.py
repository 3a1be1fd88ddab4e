"""``[tool.pkgtool]``: validation, layering (workspace < package < CLI), per-file ignores."""

from __future__ import annotations

from pathlib import Path

import pytest

from pkgtool import config
from pkgtool.config import ConfigError, ConfigFinder, Layer, expand, parse_table, settings_for
from pkgtool.findings import Severity
from pkgtool.rules.registry import load_all
from tests.helpers import write_tree

CLI = Layer("the command line")


def _codes(*layers: Layer) -> set[str]:
    return {r.code for r in settings_for(layers).rules}


def _layer(table: dict[str, object], base: Path = Path("/ws")) -> Layer:
    return parse_table(table, source="pyproject.toml", base=base)


def test_defaults_are_the_default_enabled_rules() -> None:
    assert _codes(CLI) == {c for c, r in load_all().items() if r.default_enabled}


def test_select_replaces_then_extend_select_adds_then_ignore_removes() -> None:
    workspace = _layer({"select": ["SYN"], "ignore": ["SYN002"]})
    assert _codes(workspace) == {"SYN001", "SYN003", "SYN004", "SYN005", "SYN006", "SYN007",
                                 "SYN008"}
    package = _layer({"extend-select": ["unreadable-file"]})
    assert _codes(workspace, package) == {"SYN001", "SYN002", "SYN003", "SYN004", "SYN005",
                                          "SYN006", "SYN007", "SYN008"}
    command_line = Layer("the command line", select=("SYN001",))
    assert _codes(workspace, package, command_line) == {"SYN001"}


def test_all_selects_rules_that_are_off_by_default() -> None:
    assert _codes(Layer("cli", select=("ALL",))) == set(load_all())


def test_strict_and_severity_take_the_innermost_value() -> None:
    outer = _layer({"strict": True, "severity": {"SYN001": "warning", "SYN002": "info"}})
    inner = _layer({"strict": False, "severity": {"unparsable-file": "error"}})
    settings = settings_for([outer, inner, CLI])
    assert settings.strict is False
    assert settings.severities == {"SYN001": Severity.ERROR, "SYN002": Severity.INFO}
    assert settings_for([outer, inner, Layer("cli", strict=True)]).strict is True


def test_rosdistro_takes_the_innermost_value_and_defaults_to_jazzy() -> None:
    assert settings_for([CLI]).rosdistro == "jazzy"
    outer, inner = _layer({"rosdistro": "humble"}), _layer({"rosdistro": "rolling"})
    assert settings_for([outer, CLI]).rosdistro == "humble"
    assert settings_for([outer, inner, CLI]).rosdistro == "rolling"
    assert settings_for([outer, Layer("cli", rosdistro="kilted")]).rosdistro == "kilted"


@pytest.mark.parametrize(("table", "named"), [
    ({"selct": ["SYN"]}, "`selct`"),
    ({"extend_select": ["SYN"]}, "Did you mean `extend-select`?"),
    ({"select": ["NOPE001"]}, "`NOPE001`"),
    ({"ignore": "SYN001"}, "`ignore`"),
    ({"strict": "yes"}, "`strict`"),
    ({"rosdistro": "jazy"}, "Did you mean `jazzy`?"),
    ({"rosdistro": 3}, "`rosdistro`"),
    ({"severity": {"XYZ123": "warning"}}, "`XYZ123`"),
    ({"severity": {"SYN001": "fatal"}}, "`SYN001`"),
    ({"per-file-ignores": {"test/*": ["BAD999"]}}, "`BAD999`"),
    ({"per-file-ignores": {"test/*": "SYN001"}}, "`test/*`"),
])
def test_invalid_tables_name_the_offending_key(table: dict[str, object], named: str) -> None:
    with pytest.raises(ConfigError, match="pyproject.toml") as raised:
        _layer(table)
    assert named in str(raised.value)


def test_a_family_selects_its_rules_and_a_known_family_without_rules_selects_none(
        monkeypatch: pytest.MonkeyPatch) -> None:
    assert expand("syn", where="x") == {c for c in load_all() if c.startswith("SYN")} != set()
    monkeypatch.setitem(config.FAMILIES, "NEW", "a family whose first rule is not written yet")
    assert expand("NEW", where="x") == frozenset()
    with pytest.raises(ConfigError, match="Unknown rule selector `XYZ` in x"):
        expand("XYZ", where="x")


def test_per_file_ignores_are_relative_to_their_file(tmp_path: Path) -> None:
    layer = _layer({"per-file-ignores": {"src/*/test/*": ["SYN001"], "*.launch.py": ["SYN"],
                                         "docs": ["SYN002"]}}, base=tmp_path)
    settings = settings_for([layer])
    assert settings.ignores(tmp_path / "src/pkg/test/test_a.py", "SYN001")
    assert not settings.ignores(tmp_path / "src/pkg/test/test_a.py", "SYN002")
    assert settings.ignores(tmp_path / "src/pkg/launch/x.launch.py", "SYN003")
    assert settings.ignores(tmp_path / "docs/conf.py", "SYN002")
    assert not settings.ignores(tmp_path.parent / "other/src/pkg/test/a.py", "SYN001")


def test_finder_layers_workspace_then_package_then_cli(tmp_path: Path) -> None:
    write_tree(tmp_path, {
        "pyproject.toml": '[tool.pkgtool]\nselect = ["SYN"]\nstrict = true\n',
        "src/a/package.xml": "<package/>\n",
        "src/a/pyproject.toml": '[tool.pkgtool]\nignore = ["SYN003"]\n',
        "src/b/package.xml": "<package/>\n",
        "src/b/pyproject.toml": "[project]\nname = 'b'\n",  # not ours: the workspace applies
    })
    finder = ConfigFinder(Layer("cli", ignore=("SYN002",)))
    a = finder.settings(tmp_path / "src/a")
    assert {r.code for r in a.rules} == {"SYN001", "SYN004", "SYN005", "SYN006", "SYN007",
                                         "SYN008"} and a.strict
    b = finder.settings(tmp_path / "src/b")
    assert {r.code for r in b.rules} == {"SYN001", "SYN003", "SYN004", "SYN005", "SYN006",
                                         "SYN007", "SYN008"}
    isolated = ConfigFinder(CLI, isolated=True).settings(tmp_path / "src/a")
    assert isolated.strict is False and "SYN003" in {r.code for r in isolated.rules}


def test_invalid_toml_names_the_file(tmp_path: Path) -> None:
    write_tree(tmp_path, {"pyproject.toml": "[tool.pkgtool\nselect = 1\n",
                          "pkg/package.xml": "<package/>\n"})
    with pytest.raises(ConfigError, match="not valid TOML"):
        ConfigFinder(CLI).settings(tmp_path / "pkg")


@pytest.mark.parametrize(("condition", "value"), [
    ("$ROS_VERSION == 2", True), ("$ROS_VERSION == 1", False),
    ("$ROS_VERSION == 2 and $ROS_DISTRO != humble", True),
    ("$ROS_DISTRO == humble or $ROS_DISTRO == jazzy and $ROS_VERSION == 1", False),
    ("($ROS_DISTRO == humble or $ROS_DISTRO == jazzy) and $ROS_VERSION == 2", True),
    ("$UNSET == ''", None), ("$ROS_VERSION ==", None), ("$ROS_DISTRO >= humble", None),
])
def test_rep149_conditions_for_a_jazzy_target(condition: str, value: bool | None) -> None:
    from pkgtool.model.condition import environment, evaluate

    assert evaluate(condition, environment("jazzy")) is value


def test_the_python_a_project_declares_is_read_from_the_nearest_pyproject(tmp_path: Path) -> None:
    write_tree(tmp_path, {
        "pyproject.toml": '[tool.pixi.feature.ros.dependencies]\npython = "3.14*"\n'
                          '[tool.pkgtool]\nstrict = true\n',
        "src/a/package.xml": "<package/>\n",
        "src/a/pyproject.toml": "[tool.black]\nline-length = 99\n",  # declares no Python
        "src/b/package.xml": "<package/>\n",
        "src/b/pyproject.toml": "[project]\nname = 'b'\nrequires-python = '>=3.10'\n",
    })
    finder = ConfigFinder(CLI)
    assert finder.settings(tmp_path / "src/a").python == (3, 14)
    assert finder.settings(tmp_path / "src/a").strict  # the configuration is still found
    assert finder.settings(tmp_path / "src/b").python == (3, 10)
    assert ConfigFinder(CLI, isolated=True).settings(tmp_path / "src/a").python is None
    assert tmp_path / "pyproject.toml" in finder.consulted()


@pytest.mark.parametrize(("text", "python"), [
    ("[tool.mypy]\npython_version = '3.14'\n", (3, 14)),
    ("[tool.ruff]\ntarget-version = 'py313'\n", (3, 13)),
    ("[project]\nrequires-python = '>=3.12,<3.15'\n", (3, 12)),
    ("[tool.pixi.dependencies]\npython = '>=3.14'\n", (3, 14)),
    ("[tool.black]\nline-length = 99\n", None),
    ("[project\nrequires-python = '>=3.14'\n", None),  # no TOML: nothing declared
])
def test_declared_python(text: str, python: tuple[int, int] | None) -> None:
    from pkgtool.model.declared_python import declared_python

    assert declared_python(text) == python


def test_annotations_are_not_evaluated_on_a_declared_python_3_14(tmp_path: Path) -> None:
    """PEP 649: from Python 3.14 a class named in its own methods' annotations is no
    NameError, so PYC001 is silent there; on the distributions' Pythons it is one."""
    from pkgtool.commands.lint import LintOptions, run
    from tests.helpers import correct_package_files

    files = correct_package_files("geo")
    files["geo/rotation.py"] = ("class Rotation:\n"
                                "    def inverse(self) -> Rotation:\n"
                                "        return self\n")
    write_tree(tmp_path / "ws", {f"src/geo/{k}": v for k, v in files.items()})

    def undefined(cache: bool) -> list[str]:
        found = run([str(tmp_path / "ws" / "src" / "geo")], options=LintOptions(
            cache=cache, cache_dir=str(tmp_path / "cache")))
        return [f.message for f in found.findings if f.code == "PYC001"]

    assert undefined(cache=True) == ["Undefined name `Rotation`"]
    (tmp_path / "ws" / "pyproject.toml").write_text("[tool.mypy]\npython_version = '3.14'\n")
    assert undefined(cache=False) == undefined(cache=True) == []  # the cache keys the Python
