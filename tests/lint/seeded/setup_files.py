"""Seeded setup.py and setup.cfg mistakes (SET, and SYN for files that do not parse)."""

from __future__ import annotations

from pathlib import Path

from tests.lint.seeded import case, edit, remove, write

SETUP = "setup.py"
CFG = "setup.cfg"


@case("SET008", SETUP, "base_pkg.talker:main")
def setup_cfg_missing(root: Path) -> None:
    remove(root, CFG)


@case("SET010", CFG, "script-dir")
def dashed_script_dir(root: Path) -> None:
    edit(root, CFG, "script_dir", "script-dir")


@case("SET010", CFG, "install-scripts")
def dashed_install_scripts(root: Path) -> None:
    edit(root, CFG, "install_scripts", "install-scripts")


@case("SET009", CFG, "install_scripts")
def script_dir_of_another_package(root: Path) -> None:
    edit(root, CFG, "install_scripts=$base/lib/base_pkg", "install_scripts=$base/lib/my_package")


@case("SET009", CFG, "install_scripts")
def script_dir_in_bin(root: Path) -> None:
    edit(root, CFG, "install_scripts=$base/lib/base_pkg", "install_scripts=$base/bin")


@case("SET009", CFG)
def install_section_missing(root: Path) -> None:
    write(root, CFG, """
        [develop]
        script_dir=$base/lib/base_pkg
        """)


@case("SET003", SETUP, "name=package_name")
def setup_name_mismatch(root: Path) -> None:
    edit(root, SETUP, "package_name = 'base_pkg'", "package_name = 'base_package'")
    edit(root, CFG, "lib/base_pkg\n[install]", "lib/base_package\n[install]")
    edit(root, CFG, "install_scripts=$base/lib/base_pkg", "install_scripts=$base/lib/base_package")


@case("SET004", SETUP, "version='0.1.0'")
def setup_version_mismatch(root: Path) -> None:
    edit(root, SETUP, "version='0.0.0'", "version='0.1.0'")


@case("SET005", SETUP, "license='MIT'")
def setup_license_mismatch(root: Path) -> None:
    edit(root, SETUP, "license='Apache-2.0'", "license='MIT'")


@case("SET001", "package.xml")
def setup_py_missing(root: Path) -> None:
    remove(root, SETUP)


@case("SYN001", SETUP, "'listener = base_pkg.listener:main,")
def setup_py_syntax_error(root: Path) -> None:
    edit(root, SETUP, "base_pkg.listener:main',", "base_pkg.listener:main,")


@case("SYN001", CFG, "script_dir")
def setup_cfg_syntax_error(root: Path) -> None:
    edit(root, CFG, "[develop]\n", "")


@case("SET002", SETUP)
def setup_call_misspelled(root: Path) -> None:
    edit(root, SETUP, "\nsetup(", "\nsetuptools.setup(")
    edit(root, SETUP, "from setuptools import find_packages, setup",
         "import setuptools\nfrom setuptools import find_packages")
    edit(root, SETUP, "setuptools.setup(", "setup_package(")


@case("SET007", SETUP, "tests_require")
def tests_require_only(root: Path) -> None:
    edit(root, SETUP, "extras_require={'test': ['pytest']}", "tests_require=['pytest']")


@case("SET011", SETUP, "packages=['base_pkg_nodes']")
def packages_list_typo(root: Path) -> None:
    edit(root, SETUP, "packages=find_packages(exclude=['test'])", "packages=['base_pkg_nodes']")


@case("SET006", SETUP, "maintainer='TODO'")
def setup_maintainer_placeholder(root: Path) -> None:
    edit(root, SETUP, "maintainer='Jane Doe'", "maintainer='TODO'")
    edit(root, SETUP, "maintainer_email='jane@example.com'", "maintainer_email='todo@todo.com'")


@case("PYC006", SETUP, "['package.xml'])")
def data_files_missing_comma(root: Path) -> None:
    edit(root, SETUP, "['package.xml']),", "['package.xml'])")


@case("ENT001", SETUP, "'talker = base_pkg.talker:main'")
def console_scripts_missing_comma(root: Path) -> None:
    edit(root, SETUP, "'talker = base_pkg.talker:main',", "'talker = base_pkg.talker:main'")


@case("ENT005", SETUP, "'talker = base_pkg.talker:main'")
def console_scripts_group_misspelled(root: Path) -> None:
    edit(root, SETUP, "'console_scripts'", "'console_script'")


@case("SET009", CFG, "install_script=")
def install_scripts_key_misspelled(root: Path) -> None:
    edit(root, CFG, "install_scripts=", "install_script=")


@case("PYC001", SETUP, "name=package_nme")
def package_name_variable_typo(root: Path) -> None:
    edit(root, SETUP, "name=package_name,", "name=package_nme,")


@case("SET009", CFG, "script_dir")
def develop_script_dir_of_another_package(root: Path) -> None:
    edit(root, CFG, "script_dir=$base/lib/base_pkg", "script_dir=$base/lib/turtle_demo")


@case("SET009", CFG, "install_scripts")
def install_section_misspelled(root: Path) -> None:
    edit(root, CFG, "[install]", "[instal]")


@case("SET004", SETUP, "version='1.2.0'")
def setup_version_ahead(root: Path) -> None:
    edit(root, SETUP, "version='0.0.0'", "version='1.2.0'")


@case("SET005", SETUP, "license='BSD-3-Clause'")
def setup_license_other(root: Path) -> None:
    edit(root, SETUP, "license='Apache-2.0'", "license='BSD-3-Clause'")


@case("SET007", SETUP, "tests_require")
def tests_require_beside_other_extras(root: Path) -> None:
    edit(root, SETUP, "extras_require={'test': ['pytest']}",
         "tests_require=['pytest'],\n    extras_require={'docs': ['sphinx']}")
