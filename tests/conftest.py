"""Test-session set-up: every ROS process started from the tests stays off the real network."""

from __future__ import annotations

import atexit
import os
import shutil
import tempfile

from pkgtool.ros.domains import lease_domain

# Before anything imports rclpy: no multicast on the machine's interfaces, logs in a temp dir.
os.environ["ROS_AUTOMATIC_DISCOVERY_RANGE"] = "LOCALHOST"
os.environ["ROS_DOMAIN_ID"] = str(lease_domain())  # held by this process until it exits
os.environ["ROS_LOG_DIR"] = tempfile.mkdtemp(prefix="pkgtool-ros-log-")
atexit.register(shutil.rmtree, os.environ["ROS_LOG_DIR"], ignore_errors=True)
os.environ.pop("RMW_IMPLEMENTATION", None)

pytest_plugins = ["pkgtool.testing.ros_fixtures"]
