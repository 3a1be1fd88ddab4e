"""What setup.py installs: module names to files, data_files destinations to sources."""

from __future__ import annotations

from pathlib import Path

import pytest

from pkgtool.model.installed import (
    installed_data, installed_modules, is_ament_python, keyword_known, package_folder,
    why_not_installed,
)
from tests.helpers import MINIMAL_MANIFEST, make_package

SETUP = "from setuptools import find_packages, find_namespace_packages, setup\n{}\n"


def package(tmp_path: Path, setup_body: str, *files: str, cfg: str | None = None):  # noqa: ANN201
    tree: dict[str, str | bytes] = {"package.xml": MINIMAL_MANIFEST.format(name="demo"),
                                    "setup.py": SETUP.format(setup_body)}
    tree.update({f: "def main():\n    pass\n" for f in files})
    if cfg is not None:
        tree["setup.cfg"] = cfg
    return make_package(tmp_path / "demo", tree)


def test_package_folder_follows_setuptools() -> None:
    assert package_folder("a.b", {}) == "a/b"
    assert package_folder("a.b", {"": "src"}) == "src/a/b"
    assert package_folder("a.b", {"a": "lib/a_impl"}) == "lib/a_impl/b"
    assert package_folder("", {"": "src"}) == "src"
    assert package_folder("", {}) == ""


def test_explicit_list_installs_only_direct_modules(tmp_path: Path) -> None:
    pkg = package(tmp_path, "setup(packages=['demo'], py_modules=['tool'])",
                  "demo/__init__.py", "demo/talker.py", "demo/nodes/__init__.py",
                  "demo/nodes/x.py", "tool.py", "setup_helpers.py")
    assert installed_modules(pkg) == {"demo": "demo/__init__.py",
                                      "demo.talker": "demo/talker.py", "tool": "tool.py"}
    assert "drops subpackages" in why_not_installed(pkg, "demo.nodes.x")[0]
    assert why_not_installed(pkg, "setup_helpers") == (
        "`setup_helpers.py` is a top-level module, and `py_modules` does not list "
        "`setup_helpers`", True)
    assert why_not_installed(pkg, "demo.absent")[1] is False


def test_src_layout_and_namespace_packages(tmp_path: Path) -> None:
    src = package(tmp_path / "a", "setup(packages=find_packages('src'), package_dir={'': 'src'})",
                  "src/demo/__init__.py", "src/demo/core/__init__.py", "src/demo/core/run.py")
    assert installed_modules(src) == {"demo": "src/demo/__init__.py",
                                      "demo.core": "src/demo/core/__init__.py",
                                      "demo.core.run": "src/demo/core/run.py"}
    namespace = package(tmp_path / "b",
                        "setup(packages=find_namespace_packages(include=['demo*']))",
                        "demo/nodes/run.py", "other/x.py")
    assert installed_modules(namespace) == {"demo.nodes.run": "demo/nodes/run.py"}


def test_unknown_when_packages_are_dynamic_or_auto_discovered(tmp_path: Path) -> None:
    assert installed_modules(package(tmp_path / "a", "setup(packages=discover())")) is None
    assert installed_modules(package(tmp_path / "b", "setup(name='demo')")) is None
    from_cfg = package(tmp_path / "c", "setup()", cfg="[options]\npackages = find:\n")
    assert not keyword_known(from_cfg, "packages") and installed_modules(from_cfg) is None
    assert keyword_known(from_cfg, "data_files")


def test_installed_data_maps_destinations(tmp_path: Path) -> None:
    pkg = package(tmp_path, "from glob import glob\nsetup(data_files=["
                            "('share/demo', ['package.xml']), ('share/demo/launch', "
                            "glob('launch/*.py')), ('share/demo', ['missing.txt'])])",
                  "launch/a.launch.py", "launch/b_launch.py")
    assert installed_data(pkg) == {"share/demo/package.xml": "package.xml",
                                   "share/demo/launch/a.launch.py": "launch/a.launch.py",
                                   "share/demo/launch/b_launch.py": "launch/b_launch.py"}
    dynamic = package(tmp_path / "x", "setup(data_files=files())")
    assert installed_data(dynamic) is None


def test_build_type_decides_ament_python(tmp_path: Path) -> None:
    pkg = package(tmp_path, "setup()")
    assert is_ament_python(pkg)
    cmake = make_package(tmp_path / "cmake", {
        "package.xml": MINIMAL_MANIFEST.format(name="demo").replace("ament_python",
                                                                    "ament_cmake"),
        "CMakeLists.txt": "project(demo)\n",
        "setup.py": "from setuptools import setup\nsetup()\n"})
    assert not is_ament_python(cmake)


_QUIET = ("class Quiet(object):\n    def run(self):\n        print('installing')\n"
          "        super().run()\n")
_PROTOC = ("import subprocess\n\n\ndef protoc():\n    subprocess.check_call(['protoc'])\n\n\n"
           "class Protoc(object):\n    def run(self):\n        protoc()\n        super().run()\n")


@pytest.mark.parametrize("defined, commands, modules_known, data_known", [
    ("", "{}", True, True),  # nothing replaced
    (_QUIET, "{'install': Quiet}", True, False),  # may copy more files, makes no module
    (_QUIET, "dict(develop=Quiet)", True, False),
    (_PROTOC, "{'develop': Protoc}", False, False),  # runs a generator first
    ("from elsewhere import Install\n", "{'install': Install}", False, False),  # unknown
    (_QUIET, "{'build_py': Quiet}", False, False),  # may build other modules
    ("", "COMMANDS", False, False),  # not a dict display: anything
])
def test_custom_commands_make_what_they_may_change_unknown(
        tmp_path: Path, defined: str, commands: str, modules_known: bool, data_known: bool
) -> None:
    pkg = package(tmp_path, f"{defined}\nsetup(packages=['demo'], data_files=[], "
                            f"cmdclass={commands})", "demo/__init__.py")
    assert (installed_modules(pkg) is not None) is modules_known
    assert (installed_data(pkg) is not None) is data_known
    assert keyword_known(pkg, "entry_points")
