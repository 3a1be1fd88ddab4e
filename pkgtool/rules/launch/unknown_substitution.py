"""LCH015: an XML or YAML launch file writes a substitution ROS 2's launch does not have."""

from __future__ import annotations

from collections.abc import Iterator
from difflib import get_close_matches

from pkgtool.findings import Hit, Severity
from pkgtool.knowledge.launch_api import FRONTEND_SUBSTITUTIONS, ROS1_SUBSTITUTIONS
from pkgtool.model.package import Package
from pkgtool.model.text_comments import without_comments
from pkgtool.model.span import Span
from pkgtool.rules.registry import rule
from pkgtool.lazy_regex import lazy_pattern

SUBSTITUTION = lazy_pattern(r"\$\(\s*([A-Za-z_][\w-]*)")
"""The start of a ``$(name ...)`` substitution, and its name."""


def ros2_substitution(name: str) -> str | None:
    """The substitution to write instead of ``name``, which ROS 2's launch does not have: the
    ROS 2 one of a ROS 1 one, or the one known substitution spelled almost the same; None
    for a known name, or one neither (a substitution a launch extension may expose)."""
    if name in FRONTEND_SUBSTITUTIONS:
        return None
    if name in ROS1_SUBSTITUTIONS:
        return ROS1_SUBSTITUTIONS[name]
    close = get_close_matches(name.replace("_", "-"), sorted(FRONTEND_SUBSTITUTIONS), n=1,
                              cutoff=0.75)
    return close[0] if close else None


@rule("LCH015", "unknown-substitution", Severity.ERROR,
      fix="Write the substitution ROS 2's launch has")
def unknown_substitution(package: Package) -> Iterator[Hit]:
    """An XML or YAML launch file writes a substitution that ROS 2's launch does not have.

    ## What it does
    Reads every `$(name ...)` of the package's XML and YAML launch files and reports a name
    that is none of the substitutions `launch` and `launch_ros` provide (`var`, `env`,
    `find-pkg-share`, `find-pkg-prefix`, `find-exec`, `exec-in-pkg`, `command`, `eval`,
    `anon`, `dirname`, `filename`, `param`, and the boolean ones of recent distributions)
    when it is a ROS 1 roslaunch substitution (`$(find pkg)`, `$(arg name)`, `$(optenv X)`)
    or a misspelling of one of them (`$(find-package-share pkg)`, `$(find_pkg_share pkg)`).
    Other unknown names are left alone: a launch extension may provide them.

    ## Why is this bad?
    `ros2 launch` refuses the whole file when it parses it ("Unknown substitution: find"),
    so none of its nodes start. ROS 1 files carried over to ROS 2 keep roslaunch's
    substitutions, which ROS 2 renamed.

    ## Example
    ```xml
    <param from="$(find my_robot)/config/params.yaml"/>
    <node pkg="my_robot" exec="driver" name="$(arg robot_name)"/>
    ```

    ## Use instead
    ```xml
    <param from="$(find-pkg-share my_robot)/config/params.yaml"/>
    <node pkg="my_robot" exec="driver" name="$(var robot_name)"/>
    ```
    """
    for launch in package.launch_files:
        text = package.texts.get(launch.path)
        if launch.kind not in ("xml", "yaml") or launch.problem is not None or text is None:
            continue
        for found in SUBSTITUTION.finditer(without_comments(text, launch.kind)):
            name = found.group(1)
            meant = ros2_substitution(name)
            if meant is None:
                continue
            alone = len(text[found.end():text.find(")", found.end())].split()) < 2
            roslaunch = " (a ROS 1 roslaunch substitution)" if name in ROS1_SUBSTITUTIONS else ""
            yield Hit(Span.of_offset(launch.path, text, found.start()),
                      f"`$({name} ...)` is no substitution of ROS 2's launch{roslaunch}: "
                      f"`ros2 launch` refuses the file (Unknown substitution: {name})",
                      "Write `$(env NAME '')` (`env` fails on an unset variable without a "
                      "default)" if name == "optenv" and alone else f"Write `$({meant} ...)`")
