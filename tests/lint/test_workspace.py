"""Package discovery: packages, workspaces (colcon's skip rules) and files inside packages."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from pkgtool.model.context import read_workspace_package, same_named, workspace_index
from pkgtool.model.files import list_files
from pkgtool.workspace import discover, owning_package
from tests.helpers import write_tree

MANIFEST = "<package format='3'><name>x</name></package>\n"


def _names(root: Path, *paths: str) -> list[str]:
    found = discover(list(paths), cwd=root)
    assert not found.missing
    return [p.relative_to(root).as_posix() for p in found.packages]


@pytest.fixture()
def workspace(tmp_path: Path) -> Path:
    write_tree(tmp_path, {
        "src/alpha/package.xml": MANIFEST,
        "src/alpha/alpha/__init__.py": "",
        "src/alpha/nested/package.xml": MANIFEST,  # colcon does not look inside packages
        "src/group/beta/package.xml": MANIFEST,
        "src/group/pure/setup.py": "from setuptools import setup\nsetup()\n",
        "src/ignored/COLCON_IGNORE": "",
        "src/ignored/gamma/package.xml": MANIFEST,
        "src/ament_ignored/AMENT_IGNORE": "",
        "src/ament_ignored/package.xml": MANIFEST,
        "src/.hidden/delta/package.xml": MANIFEST,
        "venv/pyvenv.cfg": "home = /usr/bin\n",
        "venv/lib/site/package.xml": MANIFEST,
        "build/COLCON_IGNORE": "",  # colcon writes the marker into what it creates
        "build/alpha/package.xml": MANIFEST,
        "install/COLCON_IGNORE": "",
        "install/alpha/share/alpha/package.xml": MANIFEST,
        "log/COLCON_IGNORE": "",
        "log/latest/package.xml": MANIFEST,
        "src/build/zeta/package.xml": MANIFEST,  # only a name: colcon finds it
        "old_install/_setup_util.py": "",  # a catkin install space
        **{f"committed/install/{name}": "" for name in  # colcon's, without COLCON_IGNORE
           ("local_setup.sh", "setup.sh", "local_setup.bash", "setup.bash")},
        "src/scripted/local_setup.sh": "",  # a developer's own script: still searched
        "src/scripted/theta/package.xml": MANIFEST,
        "committed/install/omega/share/omega/package.xml": MANIFEST,
        "committed/build/omega/colcon_build.rc": "",
        "committed/build/omega/package.xml": MANIFEST,  # --symlink-install's links
        "copied/omega/share/ament_index/resource_index/packages/omega": "",
        "copied/omega/share/omega/package.xml": MANIFEST,  # an install's copy
        "isolated/omega/share/omega/package.xml": MANIFEST,  # the same, alone
        "old_install/share/eta/package.xml": MANIFEST,
        "src/node_modules/epsilon/package.xml": MANIFEST,
        "src/conan/mavlink/include/mavlink/package.xml": MANIFEST,  # came with the headers
        "third_party/opencv_build/CMakeCache.txt": "",  # a CMake build tree: generated
        "third_party/opencv_build/python_loader/setup.py": "from setuptools import setup\n",
        "README.md": "workspace\n",
    })
    return tmp_path


def test_workspace_discovery_follows_colcon(workspace: Path) -> None:
    assert _names(workspace, ".") == ["src/alpha", "src/build/zeta", "src/group/beta",
                                      "src/group/pure", "src/scripted/theta"]


def test_no_path_means_the_current_folder(workspace: Path) -> None:
    assert _names(workspace) == _names(workspace, ".")


def test_a_package_folder_is_linted_alone_even_with_an_ignore_marker(workspace: Path) -> None:
    assert _names(workspace, "src/alpha") == ["src/alpha"]
    assert _names(workspace, "src/ament_ignored") == ["src/ament_ignored"]


def test_files_map_to_their_owning_package_once(workspace: Path) -> None:
    files = ["src/alpha/package.xml", "src/alpha/alpha/__init__.py", "src/group/beta/package.xml"]
    assert _names(workspace, *files) == ["src/alpha", "src/group/beta"]


def test_files_outside_packages_or_in_skipped_places_are_ignored(workspace: Path) -> None:
    found = discover(["README.md", "src/ignored/gamma/package.xml", "venv/lib/site/package.xml",
                      "src/.hidden/delta/package.xml", "build/alpha/package.xml"], cwd=workspace)
    assert found.packages == () and found.missing == () and found.empty == ()


def test_missing_paths_are_reported(workspace: Path) -> None:
    found = discover(["src/alpha", "nope", "src/nope.py"], cwd=workspace)
    assert found.missing == ("nope", "src/nope.py")


def test_folder_without_packages_is_reported_as_empty(tmp_path: Path) -> None:
    write_tree(tmp_path, {"docs/index.md": "hi\n"})
    found = discover(["docs"], cwd=tmp_path)
    assert found.packages == () and found.empty == ("docs",)


def test_absolute_paths_and_paths_outside_the_cwd(workspace: Path, tmp_path: Path) -> None:
    elsewhere = workspace / "src" / "group"
    found = discover([str(elsewhere)], cwd=workspace / "src" / "alpha")
    assert [p.name for p in found.packages] == ["beta", "pure"]


def test_symlinked_packages_are_found_once_and_cycles_stop(workspace: Path) -> None:
    (workspace / "src" / "link_to_beta").symlink_to(workspace / "src" / "group" / "beta")
    (workspace / "src" / "group" / "loop").symlink_to(workspace / "src")
    assert len(_names(workspace, ".")) == 5


@pytest.mark.parametrize("link", ["src/a_link", "src/group/zz_link", "a_link"])
def test_a_linked_package_is_reported_at_its_real_path(workspace: Path, link: str) -> None:
    (workspace / link).symlink_to(workspace / "src" / "group" / "beta")
    assert _names(workspace, ".") == ["src/alpha", "src/build/zeta", "src/group/beta",
                                      "src/group/pure", "src/scripted/theta"]


def test_owning_package_stops_at_the_repository_root(tmp_path: Path) -> None:
    write_tree(tmp_path, {"package.xml": MANIFEST, "repo/.git/HEAD": "ref\n",
                          "repo/tools/run.py": "print()\n"})
    assert owning_package(tmp_path / "repo" / "tools" / "run.py") is None


def test_unreadable_folders_are_skipped(workspace: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """chmod cannot lock root out, so the refusal is simulated at os.scandir."""
    locked = str(workspace / "src" / "group")
    scandir = os.scandir

    def refusing(path: object = ".") -> object:
        if os.fspath(path) == locked:  # type: ignore[arg-type]
            raise PermissionError(13, "Permission denied", locked)
        return scandir(path)  # type: ignore[arg-type]

    monkeypatch.setattr(os, "scandir", refusing)
    assert _names(workspace, ".") == ["src/alpha", "src/build/zeta", "src/scripted/theta"]


def test_a_folder_inside_a_package_lints_its_package(workspace: Path) -> None:
    assert _names(workspace, "src/alpha/alpha") == ["src/alpha"]
    found = discover(["."], cwd=workspace / "src" / "alpha" / "alpha")
    assert found.packages == (workspace / "src" / "alpha",) and found.empty == ()


def test_the_workspace_index_reads_the_same_from_the_folders_or_from_a_file_list(
        tmp_path: Path) -> None:
    write_tree(tmp_path, {
        "package.xml": "<package format='3'><name>things</name></package>\n",
        "CMakeLists.txt":
            "foreach(f ${EXTRA})\n  list(APPEND listed \"${f}\")\nendforeach()\n"
            "rosidl_generate_interfaces(${PROJECT_NAME} \"interfaces/msg/Listed.msg\")\n"
            "ament_python_install_package(helpers PACKAGE_DIR python/helpers)\n",
        "msg/Plain.msg": "", "msg/a/b/c/Deep.msg": "", "msg/a/b/c/d/TooDeep.msg": "",
        "msg/.hidden/Hidden.msg": "", "msg/nested/package.xml": "<package/>",
        "msg/nested/Nested.msg": "", "srv/Ask.srv": "", "action/Go.action": "",
        "msg/Shape.idl": "", "msg/motion/Inner.idl": "",
        "things/__init__.py": "", "things/deep/__init__.py": "", "src/lib/__init__.py": "",
        "test/__init__.py": "", "launch/__init__.py": "", "not-a-name/__init__.py": "",
        "empty/readme.txt": "",
    })
    (tmp_path / "linked").symlink_to(tmp_path / "things")
    read = read_workspace_package(tmp_path)
    assert read == read_workspace_package(tmp_path, list_files(tmp_path))
    assert read.name == "things"
    assert read.modules == {"things", "lib", "helpers", "linked"}  # setuptools follows links
    assert {kind: set(names) for kind, names in read.interfaces.items()} == {
        "msg": {"Plain", "Deep", "Shape", "Listed"}, "srv": {"Ask"}, "action": {"Go"}}


def test_a_closed_interface_list_is_all_the_package_generates(tmp_path: Path) -> None:
    """rosidl makes only what ``rosidl_generate_interfaces`` lists: a file of ``msg/`` the
    list leaves out is no interface (IFC006 reports it)."""
    write_tree(tmp_path, {
        "package.xml": "<package format='3'><name>things</name></package>\n",
        "CMakeLists.txt": "rosidl_generate_interfaces(${PROJECT_NAME} \"msg/Listed.msg\")\n",
        "msg/Listed.msg": "", "msg/Unlisted.msg": "", "srv/Ask.srv": ""})
    read = read_workspace_package(tmp_path)
    assert {kind: set(names) for kind, names in read.interfaces.items()} == {"msg": {"Listed"}}


def test_a_depth_limited_listing_is_the_full_one_less_what_lies_deeper(tmp_path: Path) -> None:
    write_tree(tmp_path, {"a/b/c/one.txt": "", "a/two.txt": "", "top.txt": "", "z/x/y.txt": ""})
    depth = {"a": 2, "z": 0}.get
    assert list_files(tmp_path, depth) == ("a/two.txt", "top.txt")
    assert list_files(tmp_path) == ("a/b/c/one.txt", "a/two.txt", "top.txt", "z/x/y.txt")


def test_packages_of_one_name_are_twins_only_under_one_colcon_src(tmp_path: Path) -> None:
    named = "<package format='3'><name>lab</name></package>\n"
    write_tree(tmp_path, {
        "ws/src/lab/package.xml": named, "ws/src/old/lab_v1/package.xml": named,
        "ws/src/ignored/COLCON_IGNORE": "", "ws/src/ignored/lab_v2/package.xml": named,
        "other_ws/src/lab/package.xml": named,  # another workspace linted in the same run
        "book/ch4/lab/package.xml": named, "book/ch5/lab/package.xml": named,  # no src
    })
    roots = [tmp_path / p for p in ("ws/src/lab", "other_ws/src/lab", "book/ch4/lab",
                                    "book/ch5/lab")]
    index = workspace_index(roots)
    assert same_named(tmp_path / "ws/src/lab", index) == ("src/old/lab_v1",)
    assert same_named(tmp_path / "other_ws/src/lab", index) == ()
    assert same_named(tmp_path / "book/ch4/lab", index) == ()


def test_folders_linked_inside_the_repository_are_listed_once_and_never_loop(
        tmp_path: Path) -> None:
    """setuptools installs a package folder linked from elsewhere in the repository."""
    repo = tmp_path / "repo"
    write_tree(repo, {".git/HEAD": "ref", "common/tools/__init__.py": "",
                      "pkg/pkg/__init__.py": "", "outside_link_target/x.py": ""})
    (repo / "pkg" / "pkg" / "tools").symlink_to(repo / "common" / "tools")
    (repo / "pkg" / "pkg" / "again").symlink_to(repo / "common" / "tools")
    (repo / "pkg" / "pkg" / "loop").symlink_to(repo / "pkg")
    (repo / "pkg" / "pkg" / "far").symlink_to(tmp_path)
    assert list_files(repo / "pkg") == ("pkg/__init__.py", "pkg/again/__init__.py")


def test_a_python_project_holding_ros_packages_gives_those_packages(tmp_path: Path) -> None:
    setup = "from setuptools import setup\nsetup(name='tool')\n"
    write_tree(tmp_path, {"setup.py": setup, "tool/__init__.py": "",
                          "ros2/src/arm/package.xml": MANIFEST, "ros2/src/arm/setup.py": setup,
                          "plain/setup.py": setup, "plain/sub/setup.py": setup,
                          "doc_tool/setup.py": setup,
                          "doc_tool/test/packages/bad/package.xml": MANIFEST})
    ros = (tmp_path / "ros2" / "src" / "arm",)
    assert discover(["."], cwd=tmp_path).packages == ros
    assert discover(["ros2"], cwd=tmp_path).packages == ros
    # a Python project with only Python projects below it is one package, as colcon sees it,
    # and so is one whose ROS packages are its test material
    assert discover(["plain"], cwd=tmp_path).packages == (tmp_path / "plain",)
    assert discover(["doc_tool"], cwd=tmp_path).packages == (tmp_path / "doc_tool",)
