"""Generate the table of the executables common released packages install into ``lib/<pkg>``.

``python -m pkgtool.knowledge.generate_released_executables`` reads, for Humble and Jazzy,
each repository of :data:`REPOSITORIES` at the commit its release tag names (the version
``distribution.yaml`` releases, without its ``-N`` suffix), else at the head of the branch its
``source:`` entry names, from local git mirrors (``--mirrors``: ``<owner>+<name>/repo``, as the
``fetch`` tool lays them out), and writes ``data/released_executables.txt``. A package is
read with the linter's own readers: the console scripts of its setup.py and setup.cfg
(:func:`~pkgtool.model.scripts.script_names`) for an ament_python package, what its
CMakeLists.txt installs into ``lib/<package>`` (:func:`~pkgtool.model.cmake_install
.installed_executables`) otherwise. A package whose executables are not certain is left out:
the table names all of a package's executables or none. Only the table enters this
repository.
"""

from __future__ import annotations

import argparse
import re
import subprocess
from collections.abc import Callable
from pathlib import Path, PurePosixPath

import yaml

from pkgtool.knowledge.generate_rclpy_names import git_text
from pkgtool.knowledge.tables import DATA, render, write
from pkgtool.model.cmake_install import installed_executables
from pkgtool.model.cmake_text import with_included
from pkgtool.model.scripts import library_entries, script_names
from pkgtool.model.setup_cfg import parse_setup_cfg
from pkgtool.model.setup_py import SetupPy, parse_setup_py
from pkgtool.model.span import ParseProblem

DISTROS = ("humble", "jazzy")
REPOSITORIES = (
    "ros/robot_state_publisher", "ros/joint_state_publisher", "ros/ros_tutorials",
    "ros2/demos", "ros2/geometry2", "ros2/rviz", "ros2/teleop_twist_keyboard",
    "ros2/teleop_twist_joy", "ros-drivers/joystick_drivers", "ros-teleop/teleop_tools",
    "ros-teleop/twist_mux", "gazebosim/ros_gz", "ros-simulation/gazebo_ros_pkgs",
    "cra-ros-pkg/robot_localization", "SteveMacenski/slam_toolbox",
    "ros-navigation/navigation2", "ros-controls/ros2_control", "ros-drivers/usb_cam",
    "ros-perception/pointcloud_to_laserscan", "ros-perception/depthimage_to_laserscan",
    "ros-perception/image_common", "ros-perception/image_pipeline",
    "RobotWebTools/rosbridge_suite", "ros-tooling/topic_tools", "foxglove/ros-foxglove-bridge",
    "ros-visualization/rqt_graph", "ros-visualization/rqt_plot",
    "ros-visualization/rqt_reconfigure", "ros-visualization/rqt_tf_tree",
    "ros-drivers/nmea_navsat_driver")
"""Repositories of the released packages launch files start most, read from their mirrors."""
ROSDISTRO = Path("/work/shared/data/rosdistro")
MIRRORS = Path("/work/.mirror")
_NAME = re.compile(r"<name>\s*([^<\s]+)\s*</name>")
Show = Callable[[str], "str | None"]
"""A file's text at the commit read, by its path in the repository (None: no such file)."""


def _released(rosdistro: Path, distro: str) -> dict[str, tuple[str, str]]:
    """GitHub ``owner/name`` -> (source branch, released version) for ``distro``."""
    data = yaml.safe_load((rosdistro / distro / "distribution.yaml").read_text())
    found: dict[str, tuple[str, str]] = {}
    for entry in data["repositories"].values():
        source, release = entry.get("source") or {}, entry.get("release") or {}
        url = str(source.get("url", ""))
        if "github.com/" in url and source.get("version"):
            slug = url.split("github.com/")[1].removesuffix(".git")
            found[slug] = (str(source["version"]), str(release.get("version", "")).split("-")[0])
    return found


def _commit(git: Path, branch: str, version: str) -> str | None:
    """The commit of the release tag ``version`` when the mirror has it, else of ``branch``,
    else of the newest earlier release of the same minor version (``3.3.3`` for ``3.3.4``:
    a patch release adds no executable); None when it has none of them."""
    series = [t for t in git_text(git, "tag", "--list", f"{version.rpartition('.')[0]}.*")
              .split() if _older(t, version)] if version.count(".") == 2 else []
    newest = sorted(series, key=lambda t: [int(p) for p in t.split(".")])[-1:]
    for ref in [f"refs/tags/{version}"] * bool(version) + [
            f"refs/heads/{branch}", f"refs/remotes/origin/{branch}",
            *(f"refs/tags/{t}" for t in newest)]:
        done = subprocess.run(["git", f"--git-dir={git}", "rev-parse", "--verify", "-q",
                               f"{ref}^{{commit}}"], capture_output=True, text=True)
        if done.returncode == 0:
            return done.stdout.strip()
    return None


def _older(tag: str, version: str) -> bool:
    """True when ``tag`` is a plain ``X.Y.Z`` version below ``version``."""
    parts = tag.split(".")
    return len(parts) == 3 and all(p.isdigit() for p in parts) and \
        [int(p) for p in parts] < [int(p) for p in version.split(".")]


def package_executables(paths: list[str], show: Show) -> dict[str, frozenset[str]]:
    """Package -> the executables it certainly installs, for each package.xml among the
    repository's ``paths`` (files read with ``show``)."""
    found: dict[str, frozenset[str]] = {}
    for path in paths:
        where = PurePosixPath(path)
        manifest = show(path) if where.name == "package.xml" else None
        name = _NAME.search(manifest or "")
        if manifest is None or name is None:
            continue
        folder = "" if str(where.parent) == "." else f"{where.parent}/"
        executables = _python_executables(name.group(1), show, folder) \
            if "<build_type>ament_python</build_type>" in manifest else \
            _cmake_executables(show, folder)
        if executables is not None:
            found[name.group(1)] = executables
    return found


def _git_files(git: Path, commit: str) -> tuple[list[str], Show]:
    """The paths of the commit's files, and a reader of their texts."""
    paths = git_text(git, "ls-tree", "-r", "--name-only", commit).splitlines()
    present = set(paths)

    def show(path: str) -> str | None:
        return git_text(git, "show", f"{commit}:{path}") if path in present else None
    return paths, show


def _python_executables(name: str, show: Show, folder: str) -> frozenset[str] | None:
    setup_text, cfg_text = show(f"{folder}setup.py"), show(f"{folder}setup.cfg")
    if setup_text is None:
        return None
    destinations = parse_setup_py("setup.py", setup_text, ())
    scripts = parse_setup_py("setup.py", setup_text, None)
    setup_cfg = parse_setup_cfg("setup.cfg", cfg_text) if cfg_text is not None else None
    if not isinstance(destinations, SetupPy) or not isinstance(scripts, SetupPy) or \
            isinstance(setup_cfg, ParseProblem) or destinations.is_unresolved("data_files") \
            or library_entries(destinations, name):
        return None
    return script_names(scripts, setup_cfg)


def _cmake_executables(show: Show, folder: str) -> frozenset[str] | None:
    text = show(f"{folder}CMakeLists.txt")
    return None if text is None else installed_executables(
        with_included(text, lambda relative: show(f"{folder}{relative}")))


def table(mirrors: Path, rosdistro: Path) -> str:
    """The text of the table: ``<distro>:<package> <executable> ...`` per known package."""
    lines: list[str] = []
    sources: list[str] = []
    for distro in DISTROS:
        released = _released(rosdistro, distro)
        for repository in REPOSITORIES:
            if repository not in released:
                continue
            git = mirrors / repository.replace("/", "+") / "repo"
            git = git / ".git" if (git / ".git").is_dir() else git  # a clone with a work tree
            commit = _commit(git, *released[repository])
            if commit is None:
                print(f"{distro}: {repository} has neither the release tag nor the branch")
                continue
            sources.append(f"{distro} {repository}@{commit}")
            for package, names in sorted(package_executables(*_git_files(git, commit)).items()):
                lines.append(f"{distro}:{package} {' '.join(sorted(names))}".rstrip())
    return render("Released packages -> the executables they install into lib/<package>, by "
                  "distribution\n(``<distro>:<package>``; a package not listed is not known). "
                  "Generated by\n`python -m pkgtool.knowledge.generate_released_executables`; "
                  "do not edit.", sources, [("-", sorted(set(lines)))])


def main(argv: list[str] | None = None) -> None:
    """Write the table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mirrors", type=Path, default=MIRRORS)
    parser.add_argument("--rosdistro", type=Path, default=ROSDISTRO)
    parser.add_argument("--output", type=Path, default=DATA)
    args = parser.parse_args(argv)
    write({"released_executables": table(args.mirrors, args.rosdistro)}, args.output)


if __name__ == "__main__":
    main()
