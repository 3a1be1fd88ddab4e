"""One root cause, one finding: consequences fold into the finding that states their cause."""

from __future__ import annotations

import shutil
from pathlib import Path

from pkgtool.commands.lint import LintOptions, run
from pkgtool.findings import Severity

FIXTURE = Path(__file__).parents[1] / "fixtures" / "SET003" / "bad" / \
    "package_xml_name_differs_everywhere"


def _lint(root: Path, **options: object):  # type: ignore[no-untyped-def]
    return run([str(root)], options=LintOptions(isolated=True, **options)).findings


def test_a_name_mistake_is_one_error_listing_its_places() -> None:
    (finding,) = _lint(FIXTURE)
    assert finding.code == "SET003" and finding.severity is Severity.ERROR  # worst of its parts
    assert [(s.path, s.line) for s in finding.related] == [
        ("setup.cfg", 2), ("setup.cfg", 4), ("setup.py", 12), ("setup.py", 13)]
    assert "`setup.cfg:2` (SET009)" in finding.message


def test_without_the_stated_cause_each_consequence_stands_alone() -> None:
    found = _lint(FIXTURE, ignore=("SET003",))
    assert sorted(f.code for f in found) == ["DAT003", "DAT004", "SET009", "SET009"]
    assert all(not f.related for f in found)


def test_fix_follows_package_xml_and_creates_the_marker(tmp_path: Path) -> None:
    root = tmp_path / "pkg"
    shutil.copytree(FIXTURE, root)
    assert not _lint(root, fix=True)
    assert (root / "resource" / "goodpkg").read_bytes() == b""
    assert "$base/lib/goodpkg" in (root / "setup.cfg").read_text()


def test_launch_files_using_the_setup_name_are_places_of_the_name_mistake(
        tmp_path: Path) -> None:
    root = tmp_path / "pkg"
    shutil.copytree(FIXTURE, root)
    (root / "launch").mkdir()
    (root / "launch" / "talk.launch.py").write_text(
        "from launch import LaunchDescription\nfrom launch_ros.actions import Node\n\n\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([Node(package='good_pkg', executable='talker')])\n")
    setup = root / "setup.py"
    setup.write_text(setup.read_text().replace(
        "        ('share/' + package_name, ['package.xml']),\n",
        "        ('share/' + package_name, ['package.xml']),\n"
        "        ('share/' + package_name + '/launch', ['launch/talk.launch.py']),\n"))
    (finding,) = _lint(root, ignore=("LCH003",))  # launch and launch_ros: not declared
    assert finding.code == "SET003"
    assert "`launch/talk.launch.py:1` (DAT005), `launch/talk.launch.py:6` (LCH002)" in \
        finding.message


MISSPELLED = Path(__file__).parents[1] / "fixtures" / "MAN021" / "bad" / \
    "misspelling_and_its_consequences"


def test_a_misspelt_run_dependency_holds_what_it_leaves_undeclared() -> None:
    found = {(f.code, f.span.line): f for f in _lint(MISSPELLED)}
    assert sorted(found) == [("DEP001", 4), ("MAN021", 9), ("MAN021", 10), ("MAN021", 13)]
    assert [(s.path, s.line) for s in found["MAN021", 10].related] == [
        ("launch/robot.launch.py", 10)]
    assert "`demo/talker.py:2` (DEP001), `test/test_window.py:2` (DEP003)" in \
        found["MAN021", 13].message
    assert not found["MAN021", 9].related  # a build_depend: the import still lacks a run key


def test_without_the_misspelling_rule_the_undeclared_names_stand_alone() -> None:
    found = _lint(MISSPELLED, ignore=("MAN021",))
    assert sorted((f.code, f.span.line) for f in found) == [
        ("DEP001", 2), ("DEP001", 4), ("DEP003", 2), ("LCH002", 10)]


def test_a_pip_name_for_a_rosdep_key_holds_the_import_it_leaves_undeclared(
        tmp_path: Path) -> None:
    root = tmp_path / "demo"
    shutil.copytree(MISSPELLED, root)
    (root / "demo" / "machine.py").write_text("import transitions\n\nprint(transitions)\n")
    manifest = root / "package.xml"
    manifest.write_text(manifest.read_text().replace(
        "</package>", "  <exec_depend>transitions</exec_depend>\n</package>"))
    found = [f for f in _lint(root) if "transitions" in f.message]
    assert [(f.code, f.span.path) for f in found] == [("MAN018", "package.xml")]
    assert "`demo/machine.py:1` (DEP001)" in found[0].message


def test_a_run_dependency_inside_export_holds_the_import_it_leaves_undeclared(
        tmp_path: Path) -> None:
    root = tmp_path / "demo"
    shutil.copytree(MISSPELLED, root)
    (root / "demo" / "filters.py").write_text("import numpy\n\nprint(numpy)\n")
    manifest = root / "package.xml"
    manifest.write_text(manifest.read_text().replace(
        "<export>", "<export>\n    <exec_depend>python3-numpy</exec_depend>"))
    found = [f for f in _lint(root) if "numpy" in f.message]
    assert [(f.code, f.span.path) for f in found] == [("MAN024", "package.xml")]
    assert "`demo/filters.py:1` (DEP001)" in found[0].message
