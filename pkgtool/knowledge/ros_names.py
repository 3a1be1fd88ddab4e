"""Which Python import names belong to ROS packages, told apart without a package index.

A name is ROS when it is a known ROS Python package or follows the naming conventions of ROS
interface and core packages (``*_msgs``, ``rcl_*``, ``tf2_*``, ...). Everything else that is
neither standard library nor curated in :mod:`pkgtool.knowledge.rosdep` is unknown.
"""

from __future__ import annotations

ROS_PYTHON_PACKAGES = frozenset({
    "action_msgs", "angles", "builtin_interfaces", "controller_manager", "cv_bridge",
    "diagnostic_updater", "image_geometry", "interactive_markers", "launch", "laser_geometry",
    "message_filters", "python_qt_binding", "qt_gui", "qt_gui_py_common", "rclpy",
    "rpyutils", "sensor_msgs_py", "sros2", "teleop_twist_keyboard", "tf_transformations",
    "turtlesim", "urdf_parser_py", "xacro",
})
"""ROS packages (as import names) that the naming patterns below do not catch."""

ROS_SUFFIXES = ("_msgs", "_srvs", "_interfaces")
ROS_PREFIXES = ("rclpy", "rcl_", "rcutils", "rosidl_", "ament_", "tf2_", "ros2", "rosbag2_",
                "rmw_", "rqt_", "nav2_", "launch_", "moveit", "ros_gz", "gazebo_", "webots_ros2")

LAUNCH_RUNTIME = frozenset({"launch", "launch_ros", "launch_xml", "launch_yaml",
                            "ament_index_python"})
"""Packages every ``ros2 launch`` run has: the ros2launch package depends on all of them."""


def looks_like_ros(top_level: str) -> bool:
    """True when ``top_level`` names a ROS package by convention or by the curated list."""
    return (top_level in ROS_PYTHON_PACKAGES or top_level.endswith(ROS_SUFFIXES)
            or top_level.startswith(ROS_PREFIXES))
