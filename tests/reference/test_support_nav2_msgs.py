"""The nav2_msgs support package builds with colcon and carries Nav2's Jazzy NavigateToPose."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

from pkgtool.resources import resource_dir
from pkgtool.ros.colcon import colcon_build, colcon_env
from pkgtool.ros.domains import leased_domain

pytestmark = [pytest.mark.ros, pytest.mark.colcon, pytest.mark.slow]

# nav2_msgs/action/NavigateToPose.action on the jazzy branch of ros-navigation/navigation2.
JAZZY_FIELDS = {
    "Goal": {"pose": "geometry_msgs/PoseStamped", "behavior_tree": "string"},
    "Result": {"error_code": "uint16", "error_msg": "string"},
    "Feedback": {
        "current_pose": "geometry_msgs/PoseStamped",
        "navigation_time": "builtin_interfaces/Duration",
        "estimated_time_remaining": "builtin_interfaces/Duration",
        "number_of_recoveries": "int16",
        "distance_remaining": "float",
    },
}

_PROBE = """
import json
from nav2_msgs.action import NavigateToPose
print(json.dumps({
    'fields': {part: getattr(NavigateToPose, part).get_fields_and_field_types()
               for part in ('Goal', 'Result', 'Feedback')},
    'NONE': NavigateToPose.Result.NONE,
}))
"""


@pytest.fixture(scope="module")
def installed(tmp_path_factory: pytest.TempPathFactory) -> Iterator[tuple[Path, dict[str, str]]]:
    workspace = tmp_path_factory.mktemp("nav2_msgs_ws")
    shutil.copytree(resource_dir("reference_packages") / "_support" / "nav2_msgs",
                    workspace / "src" / "nav2_msgs")
    with leased_domain() as domain_id:
        env = colcon_env(workspace, domain_id=domain_id)
        build = colcon_build(workspace, base_paths=[workspace / "src"], env=env, timeout=900)
        assert build.ok, build.output[-4000:]
        yield workspace / "install" / "nav2_msgs", env


def test_generated_interface_has_the_jazzy_fields(installed: tuple[Path, dict[str, str]]) -> None:
    prefix, env = installed
    site = next(prefix.glob("lib/python3*/site-packages"))
    run_env = dict(env, PYTHONPATH=str(site), AMENT_PREFIX_PATH=os.pathsep.join(
        [str(prefix), env["AMENT_PREFIX_PATH"]]),
        LD_LIBRARY_PATH=os.pathsep.join([str(prefix / "lib"), env.get("LD_LIBRARY_PATH", "")]))
    done = subprocess.run([sys.executable, "-c", _PROBE], env=run_env, capture_output=True,
                          text=True, timeout=120, check=False)
    assert done.returncode == 0, done.stderr
    probe = json.loads(done.stdout)
    assert probe["fields"] == JAZZY_FIELDS
    assert probe["NONE"] == 0


def test_action_is_registered_in_the_ament_index(installed: tuple[Path, dict[str, str]]) -> None:
    prefix, _ = installed
    index = prefix / "share" / "ament_index" / "resource_index"
    marker = index / "rosidl_interfaces" / "nav2_msgs"
    assert "action/NavigateToPose.action" in marker.read_text().split()
