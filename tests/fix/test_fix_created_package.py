"""End to end: a `pkgtool create`d package with a student's mistakes planted in every file;
`lint --fix` repairs them all, and `lint --strict --style` then finds nothing."""

from __future__ import annotations

import json
from pathlib import Path

from tests.helpers import run_cli

PLANTED = {
    "demo_bot/mover.py": [
        ("from geometry_msgs.msg import Twist\n",
         "from ament_index_python.packages import get_package_share_directory\n"
         "from geometry_msgs.msg import Twist\n"),
        ("from rclpy.node import Node\n",
         "from rclpy.node import Node\nfrom std_msgs import String\n"),
        ("period = self.get_parameter('period').value", "period = self.get_parameter('period')"),
        ("        self.count = 0\n",
         "        self.count = 0\n"
         "        self.notes = get_package_share_directory('demo_bot') + 'config/params.yaml'\n"
         "        self.status = self.create_publisher(String, 'status', 10)\n"),
        ("        msg = Twist()\n",
         "        msg = Twist()\n        msg.linear.x = 1  # forward\n"
         "        if self.count > 100:\n            self.get_logger().err('too many')\n"),
    ],
    "launch/demo_bot.launch.py": [
        ("executable='mover',", "node_executable='mover',"),
        ("parameters=[params],", "parameters=params,\n"
         "            condition=IfCondition(LaunchConfiguration('start_mover')),"),
        ("from launch import LaunchDescription\n",
         "from launch import LaunchDescription\n"
         "from launch.actions import DeclareLaunchArgument\n"
         "from launch.conditions import IfCondition\n"),
        ("from launch.substitutions import PathJoinSubstitution\n",
         "from launch.substitutions import LaunchConfiguration, PathJoinSubstitution\n"),
        ("    return LaunchDescription([\n", "    return LaunchDescription([\n"
         "        DeclareLaunchArgument('start_mover', default_value=True),\n"),
    ],
    "package.xml": [
        ("  <exec_depend>launch_ros</exec_depend>\n", ""),
        ("    <build_type>ament_python</build_type>\n",
         "    <exec_depend>launch_ros</exec_depend>\n"),
        ("<description>The demo_bot ROS 2 Python package.</description>",
         "<description>TODO: Package description</description>"),
    ],
    "setup.py": [("maintainer='Ada'", "maintainer='root'")],
}
FIXED = {"DEP001", "DEP008", "PYC031", "PYC032", "PYC025", "PYC016", "LCH003", "LCH005",
         "LCH010", "MAN015", "MAN017", "MAN024", "SET006"}


def test_fix_repairs_every_planted_mistake_of_a_created_package(tmp_path: Path) -> None:
    created = run_cli("create", "demo_bot", "--maintainer-name", "Ada", "--maintainer-email",
                      "ada@example.com", "--node", "mover:publisher:geometry_msgs/msg/Twist",
                      "--launch", "--config", cwd=tmp_path)
    assert created.exit_code == 0, created.output
    root = tmp_path / "demo_bot"
    for path, changes in PLANTED.items():
        text = (root / path).read_text()
        for old, new in changes:
            assert old in text, (path, old)
            text = text.replace(old, new, 1)
        (root / path).write_text(text)
    planted = run_cli("lint", "--format", "json", "demo_bot", cwd=tmp_path)
    assert {f["rule"] for f in json.loads(planted.stdout)["findings"]} == FIXED
    fixed = run_cli("lint", "--fix", "demo_bot", cwd=tmp_path)
    assert fixed.exit_code == 0, fixed.output
    clean = run_cli("lint", "--strict", "--style", "demo_bot", cwd=tmp_path)
    assert clean.exit_code == 0 and "No findings" in clean.stdout, clean.output
