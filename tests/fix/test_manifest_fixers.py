"""The MAN015, MAN017, MAN024, DEP007 and DEP008 fixers: exactly the fix is written (comments
and layout stay), a second run changes nothing, a refusal writes nothing."""

from __future__ import annotations

from pathlib import Path

from tests.fix.test_new_fixers import STD_MSGS, _fix, _fixed_once, _package, _read

EXPORT = "  <export>\n    <build_type>ament_python</build_type>\n  </export>\n"


def test_dependency_in_export_moves_beside_the_others(tmp_path: Path) -> None:
    """numpy joins the run dependencies (after them: they are not sorted); std_msgs is
    declared already, so its copy in `<export>` is inert: no finding, left as written."""
    root = _package(tmp_path, package_dot_xml=(
        EXPORT, "  <export>\n    <build_type>ament_python</build_type>\n"
        "    <exec_depend>python3-numpy</exec_depend>  <!-- for the maths -->\n"
        "    <exec_depend>std_msgs</exec_depend>\n  </export>\n"))
    before = _read(root, "package.xml")
    after = _fixed_once(root, "MAN024", "package.xml")
    assert after == before.replace(
        "    <exec_depend>python3-numpy</exec_depend>  <!-- for", "    <!-- for").replace(
        "  <exec_depend>launch_ros</exec_depend>\n",
        "  <exec_depend>launch_ros</exec_depend>\n  <exec_depend>python3-numpy</exec_depend>\n")


def test_missing_build_type_gets_an_export(tmp_path: Path) -> None:
    root = _package(tmp_path, package_dot_xml=(EXPORT, ""))
    before = _read(root, "package.xml")
    assert _fixed_once(root, "MAN015", "package.xml") == before.replace(
        "</package>", EXPORT + "</package>")


def test_missing_build_type_joins_the_export(tmp_path: Path) -> None:
    root = _package(tmp_path, package_dot_xml=(
        EXPORT, "  <export>  <!-- tools -->\n  </export>\n"))
    before = _read(root, "package.xml")
    assert _fixed_once(root, "MAN015", "package.xml") == before.replace(
        "<!-- tools -->\n", "<!-- tools -->\n    <build_type>ament_python</build_type>\n")


def test_build_type_of_a_package_without_setup_py_is_refused(tmp_path: Path) -> None:
    root = _package(tmp_path, package_dot_xml=(EXPORT, ""))
    (root / "setup.py").unlink()
    before = _read(root, "package.xml")
    result = _fix(root, "MAN015")
    assert _read(root, "package.xml") == before
    assert any("not fixed: MAN015: the package has neither" in n for n in result.notes)


def test_placeholder_license_takes_the_spdx_id_of_setup_py_s(tmp_path: Path) -> None:
    root = _package(tmp_path, package_dot_xml=(
        "<license>Apache-2.0</license>", "<license>TODO: License declaration</license>"),
        setup_dot_py=("license='Apache-2.0'", "license='Apache License 2.0'"))
    before = _read(root, "package.xml")
    assert _fixed_once(root, "MAN017", "package.xml") == before.replace(
        "TODO: License declaration", "Apache-2.0")


def test_placeholders_take_setup_py_values_and_others_are_refused(tmp_path: Path) -> None:
    root = _package(tmp_path, package_dot_xml=(
        "<description>A package for tests.</description>",
        "<description>TODO: Package description</description>"))
    before = _read(root, "package.xml")
    assert _fixed_once(root, "MAN017", "package.xml") == before.replace(
        "TODO: Package description", "A package for tests.")
    todo = _package(tmp_path / "todo", package_dot_xml=(
        "<license>Apache-2.0</license>", "<license>TODO: License declaration</license>"),
        setup_dot_py=("license='Apache-2.0'", "license='TODO: License declaration'"))
    kept = _read(todo, "package.xml")
    result = _fix(todo, "MAN017")
    assert _read(todo, "package.xml") == kept
    assert any("only the author knows the package's license" in n for n in result.notes)


def test_interface_imported_from_its_package_comes_from_the_msg_module(tmp_path: Path) -> None:
    root = _package(tmp_path, package_dot_xml=(STD_MSGS, STD_MSGS + "  <exec_depend>std_srvs"
                                               "</exec_depend>\n"))
    body = ("from std_msgs import String as Text  # the text\n"
            "from std_msgs import Bool, Int32\n"
            "from std_srvs.msg import (Trigger)\n"
            "from std_msgs.msg import Strin\n"
            "\nprint(Text, Bool, Int32, Trigger, Strin)\n")
    (root / "pkg" / "node.py").write_text(body)
    after = _fixed_once(root, "DEP008", "pkg/node.py", allow_left=True)
    assert after == body.replace("from std_msgs import", "from std_msgs.msg import").replace(
        "std_srvs.msg", "std_srvs.srv")


def test_sibling_module_is_imported_through_its_package(tmp_path: Path) -> None:
    root = _package(tmp_path)
    (root / "pkg" / "helpers.py").write_text("def clamp(x):\n    return x\n")
    body = ("import helpers as h  # aliased\n"
            "from helpers import (clamp)\n"
            "import helpers.x, rclpy\n"
            "\n\ndef main():\n    print(h, clamp)\n")  # no code at the top: not a script
    (root / "pkg" / "node.py").write_text(body)
    after = _fixed_once(root, "DEP007", "pkg/node.py", allow_left=True)
    assert after == body.replace("import helpers as h", "from pkg import helpers as h").replace(
        "from helpers import", "from pkg.helpers import")
