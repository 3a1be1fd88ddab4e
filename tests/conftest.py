"""Test-session set-up: every ROS process started from the tests stays off the real network."""

from __future__ import annotations

import atexit
import os
import shutil
import tempfile

import pytest

from pkgtool.ros.domains import lease_domain

# Before anything imports rclpy: no multicast on the machine's interfaces, logs in a temp dir.
os.environ["ROS_AUTOMATIC_DISCOVERY_RANGE"] = "LOCALHOST"
os.environ["ROS_DOMAIN_ID"] = str(lease_domain())  # held by this process until it exits
os.environ["ROS_LOG_DIR"] = tempfile.mkdtemp(prefix="pkgtool-ros-log-")
atexit.register(shutil.rmtree, os.environ["ROS_LOG_DIR"], ignore_errors=True)
os.environ.pop("RMW_IMPLEMENTATION", None)

pytest_plugins = ["pkgtool.testing.ros_fixtures"]


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item: pytest.Item, call: pytest.CallInfo) -> object:
    """An ``oracle`` test that skips has checked nothing: report it as a failure."""
    outcome = yield
    report = outcome.get_result()
    if report.skipped and item.get_closest_marker("oracle") is not None:
        report.outcome = "failed"
        report.longrepr = f"oracle test skipped, which counts as a failure: {report.longrepr}"
