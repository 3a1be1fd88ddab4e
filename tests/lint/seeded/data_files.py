"""Seeded data_files mistakes (DAT): resources that are not installed, or not where expected."""

from __future__ import annotations

from pathlib import Path

from tests.lint.seeded import case, edit, move, remove

SETUP = "setup.py"
PARAMETERS = "config/params.yaml"
MARKER = "('share/ament_index/resource_index/packages', ['resource/' + package_name]),"
LAUNCH = "(os.path.join('share', package_name, 'launch'), glob('launch/*.launch.py')),"
CONFIG = "(os.path.join('share', package_name, 'config'), glob('config/*.yaml')),"


@case("DAT003")
def marker_file_missing(root: Path) -> None:
    remove(root, "resource/base_pkg")
    edit(root, SETUP, MARKER, "")


@case("DAT001", SETUP, "'resource/' + package_name")
def marker_file_deleted(root: Path) -> None:
    remove(root, "resource/base_pkg")


@case("DAT003", SETUP, "resource/base_pkg_marker")
def marker_with_wrong_name(root: Path) -> None:
    move(root, "resource/base_pkg", "resource/base_pkg_marker")
    edit(root, SETUP, "['resource/' + package_name]", "['resource/base_pkg_marker']")


@case("DAT003")
def marker_not_in_data_files(root: Path) -> None:
    edit(root, SETUP, MARKER, "")


@case("DAT003", SETUP, "resource_index/package'")
def marker_destination_typo(root: Path) -> None:
    edit(root, SETUP, "resource_index/packages'", "resource_index/package'")


@case("DAT004")
def package_xml_not_installed(root: Path) -> None:
    edit(root, SETUP, "('share/' + package_name, ['package.xml']),", "")


@case("DAT004", SETUP, "('share', ['package.xml'])")
def package_xml_installed_to_share(root: Path) -> None:
    edit(root, SETUP, "('share/' + package_name, ['package.xml'])", "('share', ['package.xml'])")


@case("DAT001", SETUP, "'package.xm'")
def data_file_source_typo(root: Path) -> None:
    edit(root, SETUP, "['package.xml']", "['package.xm']")


@case("DAT005", "launch/base_pkg.launch.py")
def launch_file_not_installed(root: Path) -> None:
    edit(root, SETUP, LAUNCH, "")


@case("DAT005", "launch/base_pkg_launch.py")
def launch_glob_misses_underscore_names(root: Path) -> None:
    move(root, "launch/base_pkg.launch.py", "launch/base_pkg_launch.py")


@case("DAT005", "launch/base_pkg.launch.py")
def launch_installed_to_share_root(root: Path) -> None:
    edit(root, SETUP, "os.path.join('share', package_name, 'launch')", "'share/launch'")


@case("DAT002", SETUP, "glob('launch/*.launch.xml')")
def launch_glob_wrong_extension(root: Path) -> None:
    edit(root, SETUP, "glob('launch/*.launch.py')", "glob('launch/*.launch.xml')")


@case("DAT006", "launch/base_pkg.launch.py", "'config', 'params.yaml'")
def config_not_installed(root: Path) -> None:
    edit(root, SETUP, CONFIG, "")


@case("DAT006", "launch/base_pkg.launch.py", "'config', 'params.yaml'")
def config_glob_wrong_extension(root: Path) -> None:
    edit(root, SETUP, "glob('config/*.yaml')", "glob('config/*.yml')")


@case("DAT012", "launch/base_pkg.launch.py", "'config', 'param.yaml'")
def launch_reads_misspelled_config(root: Path) -> None:
    edit(root, "launch/base_pkg.launch.py", "'params.yaml'", "'param.yaml'")


@case("DAT007", SETUP, "['launch']")
def folder_as_data_file(root: Path) -> None:
    edit(root, SETUP, "glob('launch/*.launch.py')", "['launch']")


@case("DAT007", SETUP, "glob('launch*')")
def glob_matches_folder(root: Path) -> None:
    edit(root, SETUP, "glob('launch/*.launch.py')", "glob('launch*')")


@case("SYN001", "config/params.yaml", "period: 0.5")
def parameter_file_bad_indentation(root: Path) -> None:
    edit(root, "config/params.yaml", "    period: 0.5", "   period: 0.5")


@case("DAT007", SETUP, "['config']")
def config_folder_as_data_file(root: Path) -> None:
    edit(root, SETUP, "glob('config/*.yaml')", "['config']")


@case("DAT004")
def package_xml_replaced_by_license(root: Path) -> None:
    edit(root, SETUP, "['package.xml']", "['LICENSE']")


@case("DAT009", PARAMETERS, "talkr:")
def parameter_block_for_misspelled_node(root: Path) -> None:
    edit(root, PARAMETERS, "talker:", "talkr:")


@case("DAT010", PARAMETERS, "perod: 0.5")
def misspelled_parameter_in_file(root: Path) -> None:
    edit(root, PARAMETERS, "period: 0.5", "perod: 0.5")


@case("DAT011", PARAMETERS, "period: 1")
def integer_for_a_double_parameter(root: Path) -> None:
    edit(root, PARAMETERS, "period: 0.5", "period: 1")


@case("DAT010", "launch/base_pkg.launch.py", "'perod': 1.0")
def misspelled_parameter_in_launch_dict(root: Path) -> None:
    edit(root, "launch/base_pkg.launch.py", "name='talker',\n            parameters=[params]",
         "name='talker',\n            parameters=[params, {'perod': 1.0}]")


@case("DAT011", "launch/base_pkg.launch.py", "'period': 1}")
def integer_for_a_double_in_launch_dict(root: Path) -> None:
    edit(root, "launch/base_pkg.launch.py", "name='talker',\n            parameters=[params]",
         "name='talker',\n            parameters=[params, {'period': 1}]")
