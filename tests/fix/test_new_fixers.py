"""The DEP001, DEP002, MAN021, SET, ENT005 and DAT fixers: exact edits, idempotence, refusals."""

from __future__ import annotations

import textwrap
from pathlib import Path

from pkgtool.commands.lint import LintOptions, LintResult, run
from tests.helpers import correct_package_files, write_tree

RCLPY = "  <exec_depend>rclpy</exec_depend>\n"
STD_MSGS = "  <exec_depend>std_msgs</exec_depend>\n"
SETUP_CFG = "[develop]\nscript_dir=$base/lib/pkg\n[install]\ninstall_scripts=$base/lib/pkg\n"
LAUNCH = "        (os.path.join('share', package_name, 'launch'), glob('launch/*.launch.py')),\n"
MARKER = "('share/ament_index/resource_index/packages', ['resource/' + package_name]),\n"


def _package(tmp_path: Path, **changes: tuple[str, str]) -> Path:
    """The correct package ``pkg`` with ``file=(old, new)`` replacements (``.`` for ``/``)."""
    files = correct_package_files("pkg")
    for key, (old, new) in changes.items():
        path = key.replace("__", "/").replace("_dot_", ".")
        text = textwrap.dedent(str(files[path])).lstrip("\n")
        assert old in text, (path, old)
        files[path] = text.replace(old, new, 1)
    root = tmp_path / "pkg"
    write_tree(root, files)
    return root


def _fix(root: Path, code: str, *, unsafe: bool = False) -> LintResult:
    options = LintOptions(isolated=True, fix=True, select=(code,), unsafe_fixes=unsafe)
    return run([str(root)], options=options)


def _read(root: Path, path: str) -> str:
    return (root / path).read_text()


def _fixed_once(root: Path, code: str, path: str, *, unsafe: bool = False,
                allow_left: bool = False) -> str:
    """Fix ``code``, check no finding of it is left (unless ``allow_left``: some are the
    user's) and a second run changes nothing."""
    result = _fix(root, code, unsafe=unsafe)
    assert allow_left or not [f for f in result.findings if f.code == code], result.findings
    text = _read(root, path)
    again = _fix(root, code, unsafe=unsafe)
    assert not again.fixed and _read(root, path) == text
    return text


def test_modules_of_one_key_get_it_declared_once(tmp_path: Path) -> None:
    root = _package(tmp_path)
    (root / "pkg" / "plot.py").write_text("import matplotlib.pyplot\n"
                                          "from mpl_toolkits.mplot3d import Axes3D\n"
                                          "import numpy\n")
    before = _read(root, "package.xml")
    after = _fixed_once(root, "DEP001", "package.xml")
    assert after.count("<exec_depend>python3-matplotlib</exec_depend>") == 1
    assert after.count("<exec_depend>python3-numpy</exec_depend>") == 1
    assert len(after.splitlines()) == len(before.splitlines()) + 2


def test_build_depend_becomes_depend_keeping_its_attributes(tmp_path: Path) -> None:
    root = _package(tmp_path, package_dot_xml=(
        STD_MSGS, '  <build_depend version_gte="1.0.0">std_msgs</build_depend>\n'))
    before = _read(root, "package.xml")
    after = _fixed_once(root, "DEP002", "package.xml")
    assert after == before.replace("<build_depend version_gte", "<depend version_gte").replace(
        "std_msgs</build_depend>", "std_msgs</depend>")


def test_buildtool_depend_gains_an_exec_depend(tmp_path: Path) -> None:
    root = _package(tmp_path, package_dot_xml=(
        STD_MSGS, "  <buildtool_depend>std_msgs</buildtool_depend>\n"))
    after = _fixed_once(root, "DEP002", "package.xml")
    assert "<buildtool_depend>std_msgs</buildtool_depend>" in after
    assert "<exec_depend>std_msgs</exec_depend>" in after


def test_misspelled_dependency_with_one_near_miss_is_written(tmp_path: Path) -> None:
    root = _package(tmp_path, package_dot_xml=(STD_MSGS, "  <exec_depend>std_msg</exec_depend>\n"))
    before = _read(root, "package.xml")
    _fix(root, "MAN021")
    assert _read(root, "package.xml") == before, "an unsafe fix needs --unsafe-fixes"
    assert _fixed_once(root, "MAN021", "package.xml", unsafe=True) == before.replace(
        ">std_msg<", ">std_msgs<")


def test_a_dependency_unlike_any_known_name_is_not_renamed(tmp_path: Path) -> None:
    """`science_interfaces` is close to the released `soccer_interfaces` by ratio, but no typo
    turns one into the other: a package pkgtool cannot see, not a misspelling."""
    root = _package(tmp_path, package_dot_xml=(
        STD_MSGS, "  <exec_depend>science_interfaces</exec_depend>\n"))
    before = _read(root, "package.xml")
    result = _fix(root, "MAN", unsafe=True)
    assert _read(root, "package.xml") == before
    assert [f.code for f in result.findings] == ["MAN022"]


def test_misspelled_dependency_with_two_near_misses_stays(tmp_path: Path) -> None:
    root = _package(tmp_path, package_dot_xml=(
        RCLPY, RCLPY + "  <exec_depend>python3-pyqt</exec_depend>\n"))  # pyqt5 or pyqt6?
    before = _read(root, "package.xml")
    result = _fix(root, "MAN021", unsafe=True)
    assert [f.code for f in result.findings] == ["MAN021"]
    assert _read(root, "package.xml") == before


def test_missing_setup_cfg_is_written(tmp_path: Path) -> None:
    root = _package(tmp_path)
    (root / "setup.cfg").unlink()
    assert _fixed_once(root, "SET008", "setup.cfg") == SETUP_CFG


def test_script_dir_value_is_rewritten_and_comments_stay(tmp_path: Path) -> None:
    root = _package(tmp_path, setup_dot_cfg=("[develop]\n", "# scripts\n[develop]\n"))
    (root / "setup.cfg").write_text(_read(root, "setup.cfg").replace("lib/pkg\n[install]",
                                                                     "lib/other\n[install]"))
    assert _fixed_once(root, "SET009", "setup.cfg") == "# scripts\n" + SETUP_CFG


def test_misspelt_section_is_renamed(tmp_path: Path) -> None:
    root = _package(tmp_path, setup_dot_cfg=("[install]", "[instal]"))
    assert _fixed_once(root, "SET009", "setup.cfg") == SETUP_CFG


def test_dashed_keys_become_underscored(tmp_path: Path) -> None:
    root = _package(tmp_path, setup_dot_cfg=("script_dir", "script-dir"))
    assert _fixed_once(root, "SET010", "setup.cfg") == SETUP_CFG


def test_dashed_key_beside_its_underscored_twin_is_left(tmp_path: Path) -> None:
    root = _package(tmp_path, setup_dot_cfg=("[install]", "script-dir=$base/lib/x\n[install]"))
    before = _read(root, "setup.cfg")
    _fix(root, "SET010")
    assert _read(root, "setup.cfg") == before


def test_setup_name_follows_package_xml_through_its_variable(tmp_path: Path) -> None:
    root = _package(tmp_path, setup_dot_py=("package_name = 'pkg'", "package_name = 'pkg2'"))
    before = _read(root, "setup.py")
    assert _fixed_once(root, "SET003", "setup.py") == before.replace("'pkg2'", "'pkg'")


def test_setup_name_that_also_names_the_installed_code_is_refused(tmp_path: Path) -> None:
    root = _package(tmp_path, package_dot_xml=("<name>pkg</name>", "<name>robot</name>"),
                    setup_dot_py=("find_packages(exclude=['test'])", "[package_name]"))
    before = _read(root, "setup.py")
    result = _fix(root, "SET003")
    assert _read(root, "setup.py") == before  # packages=[package_name] would lose pkg/
    assert any("not fixed: SET003: `pkg` is also the Python package" in n
               for n in result.notes), result.notes


def test_computed_setup_name_is_refused_with_the_reason(tmp_path: Path) -> None:
    root = _package(tmp_path, setup_dot_py=("name=package_name,", "name=package_name.title(),"))
    before = _read(root, "setup.py")
    result = _fix(root, "SET003")
    assert _read(root, "setup.py") == before
    assert any("not fixed: SET003: setup.py computes `name`" in n for n in result.notes), \
        result.notes


def test_version_and_license_come_from_package_xml(tmp_path: Path) -> None:
    root = _package(tmp_path, setup_dot_py=("version='0.1.0'", "version='9.9.9'"))
    before = _read(root, "setup.py")
    assert _fixed_once(root, "SET004", "setup.py") == before.replace("9.9.9", "0.1.0")


def test_misspelt_group_is_renamed_and_a_duplicate_refused(tmp_path: Path) -> None:
    root = _package(tmp_path, setup_dot_py=("'console_scripts'", "'console_script'"))
    before = _read(root, "setup.py")
    assert _fixed_once(root, "ENT005", "setup.py") == before.replace("'console_script'",
                                                                     "'console_scripts'")
    both = _package(tmp_path / "both", setup_dot_py=(
        "'console_scripts': [", "'console_script': ['x = pkg.talker:main'],\n"
        "        'console_scripts': ["))
    kept = _read(both, "setup.py")
    result = _fix(both, "ENT005")
    assert _read(both, "setup.py") == kept
    assert any("merge them by hand" in note for note in result.notes)


def test_tests_require_joins_the_extras(tmp_path: Path) -> None:
    root = _package(tmp_path, setup_dot_py=(
        "    extras_require={'test': ['pytest']},\n",
        "    tests_require=['pytest'],\n    extras_require={'docs': ['sphinx']},\n"))
    after = _fixed_once(root, "SET007", "setup.py")
    assert "tests_require" not in after
    assert "extras_require={'docs': ['sphinx'], 'test': ['pytest']}," in after


def test_missing_marker_is_installed_and_its_file_created(tmp_path: Path) -> None:
    root = _package(tmp_path, setup_dot_py=(MARKER, ""))
    (root / "resource" / "pkg").unlink()
    after = _fixed_once(root, "DAT003", "setup.py")
    assert "('share/ament_index/resource_index/packages', ['resource/' + package_name])," in after
    assert _read(root, "resource/pkg") == ""


def test_data_files_built_by_code_are_refused_with_the_reason(tmp_path: Path) -> None:
    launch = LAUNCH
    root = _package(tmp_path, setup_dot_py=(launch, ""))
    text = _read(root, "setup.py").replace("    data_files=[", "    data_files=[] + [")
    (root / "setup.py").write_text(text)
    result = _fix(root, "DAT005")
    assert _read(root, "setup.py") == text
    assert [f.code for f in result.findings] == ["DAT005"]
    assert any("not fixed: DAT005: setup.py builds data_files with code" in note
               for note in result.notes), result.notes


def test_uninstalled_launch_folder_gets_a_glob(tmp_path: Path) -> None:
    launch = LAUNCH
    original = _read(_package(tmp_path / "original"), "setup.py")
    root = _package(tmp_path, setup_dot_py=(launch, ""))
    assert _fixed_once(root, "DAT005", "setup.py") == original


def test_a_placeholder_license_is_never_written_into_setup_py(tmp_path: Path) -> None:
    root = _package(tmp_path, package_dot_xml=("<license>Apache-2.0</license>",
                                               "<license>TODO: License declaration</license>"))
    before = _read(root, "setup.py")
    result = _fix(root, "SET005")
    assert _read(root, "setup.py") == before
    assert any("is a placeholder (MAN017)" in note for note in result.notes), result.notes
    options = LintOptions(isolated=True, fix=True, select=("SET005", "MAN017"))
    run([str(root)], options=options)  # package.xml takes setup.py's license instead
    assert "<license>Apache-2.0</license>" in _read(root, "package.xml")
    assert _read(root, "setup.py") == before


def test_launch_package_fix_adds_the_package_named_never_the_package_itself(
        tmp_path: Path) -> None:
    src = tmp_path / "ws" / "src"
    root = _package(src)
    write_tree(src / "other", correct_package_files("other"))  # linted together: `pkg`
    (root / "launch" / "tf.launch.xml").write_text(  # is a workspace package, which resolves
        '<launch>\n  <node pkg="tf2_ros" exec="static_transform_publisher"/>\n'
        '  <node pkg="stage_sim" exec="stage"\n'  # no released package: stays reported
        '        args="$(find-pkg-share pkg)/worlds/lab.world"/>\n</launch>\n')
    options = LintOptions(isolated=True, fix=True, select=("LCH002",))
    run([str(src)], options=options)
    fixed = _read(root, "package.xml")
    assert "<exec_depend>tf2_ros</exec_depend>" in fixed
    assert "<exec_depend>pkg</exec_depend>" not in fixed
    left = [f.message for f in run([str(src)], options=options).findings if f.code == "LCH002"]
    assert left == ["`stage_sim` is used by a launch file but not declared in package.xml, "
                    "and no package of jazzy's release or of the packages linted with it has "
                    "that name"]


def test_a_dozen_missing_dependencies_are_all_declared_in_one_run(tmp_path: Path) -> None:
    """Additions to package.xml's list overlap, one per round: --fix keeps going until none
    is left (it stopped after 8 rounds)."""
    modules = ("action_msgs", "builtin_interfaces", "diagnostic_msgs", "geometry_msgs",
               "nav_msgs", "sensor_msgs", "shape_msgs", "std_srvs", "stereo_msgs",
               "trajectory_msgs", "visualization_msgs", "unique_identifier_msgs")
    root = _package(tmp_path)
    imports = "".join(f"import {m}.msg  # noqa: F401\n" for m in modules)
    (root / "pkg" / "imports.py").write_text(imports)
    fixed = _fixed_once(root, "DEP001", "package.xml")
    assert all(f"<exec_depend>{m}</exec_depend>" in fixed for m in modules)
