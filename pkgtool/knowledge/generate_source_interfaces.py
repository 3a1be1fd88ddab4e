"""Generate ``data/source_interfaces.txt`` and ``data/source_message_fields.txt`` from the
interface files of ROS packages that have no PyPI wheel, read from their repositories.

Courses use interface packages no wheel installs (turtlesim, example_interfaces, nav2_msgs,
tf2_msgs, irobot_create_msgs, vision_msgs, ackermann_msgs, control_msgs, moveit_msgs,
geographic_msgs): their ``.msg``, ``.srv`` and ``.action`` files
are read at the commits :data:`PINS` names for each distribution, with the reading of
:mod:`pkgtool.knowledge.interface_definitions` (checked against the generated classes of every
wheel's interface). A package is left out of a distribution when one of its interface files
is not understood (an ``.idl`` file, a line the reading does not know): its names and fields
must be complete or absent. Names and fields the distributions share take both flags; where
they differ, Jazzy's are kept alone.

Run ``python -m pkgtool.knowledge.generate_source_interfaces --mirror DIR`` where ``DIR``
holds ``<owner>+<name>/repo`` git directories of the repositories (the ``fetch`` tool's
layout), or with ``--network`` to clone them into a temporary folder.
"""

from __future__ import annotations

import argparse
import re
import subprocess
import tempfile
from pathlib import Path, PurePosixPath

from pkgtool.knowledge.tables import DATA, flags_of, render, write
from pkgtool.knowledge.generate_rclpy_names import git_text
from pkgtool.knowledge.interface_definitions import definitions

KINDS = ("msg", "srv", "action")
PACKAGES = {"turtlesim": "ros/ros_tutorials", "example_interfaces": "ros2/example_interfaces",
            "nav2_msgs": "ros-navigation/navigation2", "tf2_msgs": "ros2/geometry2",
            "irobot_create_msgs": "iRobotEducation/irobot_create_msgs",
            "vision_msgs": "ros-perception/vision_msgs",
            "ackermann_msgs": "ros-drivers/ackermann_msgs",
            "control_msgs": "ros-controls/control_msgs", "moveit_msgs": "moveit/moveit_msgs",
            "geographic_msgs": "ros-geographic-info/geographic_info"}
"""The packages read, and the repository holding each."""
PINS = {
    "humble": {"ros/ros_tutorials": "ba29c3f376197e3736f497639299f855cbf73390",
               "ros2/example_interfaces": "f8deb566a1facf91bd38b9f00c4cf684c5007d85",
               "ros-navigation/navigation2": "3c3db59d6969d8ecee8e68468693d006397f4a0c",
               "ros2/geometry2": "d0dbd516d1748cfe1b293e0f7d5b2f82ddd3438a",
               "iRobotEducation/irobot_create_msgs": "a4b94407977d5efb16e97fee52e031a7f1f39209",
               "ros-perception/vision_msgs": "e77fa2d97d69abaaa546592892d2d5d16cec9977",
               "ros-drivers/ackermann_msgs": "df2fe51eb04e8bd3c0ba4f8a6ded8aea3815b660",
               "ros-controls/control_msgs": "2e31e46d714819e669e2c3645802df9a9ebd1b43",
               "moveit/moveit_msgs": "45820c507a418256abd3808e86ea8be9235701f0",
               "ros-geographic-info/geographic_info": "2a0ae99219645b8d29772b997ef31f8e17345d52"},
    "jazzy": {"ros/ros_tutorials": "9481d9a4f09d923cc972d017c6acc0e61fa9d7bb",
              "ros2/example_interfaces": "4d7d086e4791e1839fecb9c50a1291d4056b916f",
              "ros-navigation/navigation2": "f4108e5b1c2bce804a1aa0c7be6673a8eb4a1501",
              "ros2/geometry2": "646342c6164e837d69460e3d28e7a025396544f6",
              "ros-perception/vision_msgs": "e77fa2d97d69abaaa546592892d2d5d16cec9977",
              "ros-drivers/ackermann_msgs": "df2fe51eb04e8bd3c0ba4f8a6ded8aea3815b660",
              "ros-controls/control_msgs": "f901df2662f22a39a06aa04a85a34602c47e3cc0",
              "moveit/moveit_msgs": "55f802fe3ac455123efcdba1037d3abf2c8e4dcb",
              "ros-geographic-info/geographic_info": "2a0ae99219645b8d29772b997ef31f8e17345d52"},
}
"""Distribution -> repository -> commit: the head of the distribution's branch, except
ros_tutorials for jazzy (1.8.2, the release its jazzy branch starts from; the mirror holds no
jazzy branch), vision_msgs (4.1.1, the release of both distributions), ackermann_msgs (2.0.2,
the release of both), moveit_msgs (2.2.1 for humble, 2.6.0 for jazzy: the releases) and
geographic_info (its ros2 branch, both distributions' source). irobot_create_msgs has no jazzy
branch: Jazzy is left unknown for it. moveit_msgs' repository is the ``moveit/moveit_msgs``
rosdistro names by its former owner, ``ros-planning``."""

Found = dict[str, dict[str, dict[str, str]]]
"""Distribution -> package -> ``pkg/kind/Class`` -> fields entry."""


def _package_messages(git_dir: Path, commit: str, package: str) -> dict[str, str] | None:
    """The message classes ``package``'s interface files define at ``commit``; None when one
    is not understood or the package has none."""
    paths = git_text(git_dir, "ls-tree", "-r", "--name-only", commit).splitlines()
    folder = next((str(PurePosixPath(path).parent) for path in paths
                   if PurePosixPath(path).name == "package.xml" and
                   re.search(rf"<name>\s*{package}\s*</name>",
                             git_text(git_dir, "show", f"{commit}:{path}"))), None)
    if folder is None:
        return None
    found: dict[str, str] = {}
    for path in paths:
        where = PurePosixPath(path)
        if str(where.parent.parent) != folder or where.parent.name not in KINDS:
            continue
        stem, _, suffix = where.name.rpartition(".")
        if suffix == "idl":
            return None
        if suffix != where.parent.name:
            continue
        defined = definitions(package, suffix, stem, git_text(git_dir, "show", f"{commit}:{path}"))
        if not defined:
            return None
        found.update(defined)
    return found or None


def read_sources(git_dir_of: dict[str, Path]) -> tuple[Found, list[str]]:
    """What every pinned commit defines, and the ``distro repository@commit`` source words."""
    found: Found = {}
    sources = []
    for distro, pins in PINS.items():
        for repository, commit in sorted(pins.items()):
            sources.append(f"{distro} {repository}@{commit}")
            for package in sorted(p for p, r in PACKAGES.items() if r == repository):
                messages = _package_messages(git_dir_of[repository], commit, package)
                if messages is not None:
                    found.setdefault(distro, {})[package] = messages
    return found, sources


def _names(messages: dict[str, str]) -> str:
    """``msg:A,B srv:C`` of a package's message classes."""
    kinds: dict[str, set[str]] = {}
    for name in messages:
        _, kind, cls = name.split("/")
        if kind != "msg":
            cls = cls.rsplit("_", 1)[0]
        kinds.setdefault(kind, set()).add(cls)
    return " ".join(f"{kind}:{','.join(sorted(kinds[kind]))}" for kind in KINDS if kind in kinds)


def tables(found: Found, sources: list[str]) -> dict[str, str]:
    """The texts of both tables."""
    names: dict[str, list[str]] = {}
    fields: dict[str, list[str]] = {}
    jazzy, humble = found.get("jazzy", {}), found.get("humble", {})
    for package in sorted({*jazzy, *humble}):
        texts = {distro: _names(found[distro][package]) for distro in ("humble", "jazzy")
                 if package in found.get(distro, {})}
        shared = [d for d in texts if texts[d] == texts.get("jazzy", texts.get("humble"))]
        names.setdefault(flags_of(shared), []).append(f"{package} {texts[shared[-1]]}")
        for cls in sorted({*jazzy.get(package, {}), *humble.get(package, {})}):
            entries = {d: found[d][package][cls] for d in ("humble", "jazzy")
                       if cls in found.get(d, {}).get(package, {})}
            kept = entries.get("jazzy", entries.get("humble"))
            alike = [d for d in entries if entries[d] == kept]
            fields.setdefault(flags_of(alike), []).append(f"{cls} {kept}".rstrip())
    note = ("read from their repositories' interface files.\nGenerated by `python -m "
            "pkgtool.knowledge.generate_source_interfaces`; do not edit.")
    return {
        "source_interfaces": render(
            "Message, service and action names of ROS interface packages without PyPI wheels,\n"
            + note, sources, sorted(names.items())),
        "source_message_fields": render(
            "The fields (name:rosidl type) and constants of the message classes of ROS interface"
            "\npackages without PyPI wheels, " + note, sources, sorted(fields.items())),
    }


def _git_dirs(mirror: Path | None, work: Path) -> dict[str, Path]:
    """The git directory of every repository: in ``mirror``, else cloned into ``work``."""
    found = {}
    for repository in sorted(set(PACKAGES.values())):
        if mirror is not None:
            found[repository] = mirror / repository.replace("/", "+") / "repo"
        else:
            target = work / repository.replace("/", "+")
            subprocess.run(["git", "clone", "--quiet", "--bare",
                            f"https://github.com/{repository}.git", str(target)], check=True)
            found[repository] = target
    return found


def main(argv: list[str] | None = None) -> None:
    """Write both tables."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    where = parser.add_mutually_exclusive_group(required=True)
    where.add_argument("--mirror", type=Path, help="folder of <owner>+<name>/repo git dirs")
    where.add_argument("--network", action="store_true", help="clone the repositories")
    parser.add_argument("--output", type=Path, default=DATA, help="where to write the tables")
    args = parser.parse_args(argv)
    with tempfile.TemporaryDirectory() as work:
        write(tables(*read_sources(_git_dirs(args.mirror, Path(work)))), args.output)


if __name__ == "__main__":
    main()
