# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Keep every test in this process: discovery OFF, own domain id, logs in a temp folder."""

import os
import tempfile
import time

import pytest
import rclpy
from rclpy.context import Context
from rclpy.executors import SingleThreadedExecutor

os.environ['ROS_AUTOMATIC_DISCOVERY_RANGE'] = 'OFF'
os.environ['ROS_DOMAIN_ID'] = '31'
# pkgtool's colcon runs set ROS_LOG_DIR; any other run gets a folder removed at exit.
if 'ROS_LOG_DIR' not in os.environ:
    _LOG_DIR = tempfile.TemporaryDirectory(prefix='robot_monitor-ros-log-')
    os.environ['ROS_LOG_DIR'] = _LOG_DIR.name


def pytest_configure(config):
    """Silence lark's DeprecationWarnings, raised when rclpy parses interface definitions."""
    for module in ('sre_parse', 'sre_constants'):
        config.addinivalue_line(
            'filterwarnings', f"ignore:module '{module}' is deprecated:DeprecationWarning")


class RosHarness:
    """An initialised rclpy context plus one executor that spins the test's nodes."""

    def __init__(self, context: Context) -> None:
        self.context = context
        self.executor = SingleThreadedExecutor(context=context)

    def add(self, node):
        """Spin ``node`` with this harness's executor and return it."""
        self.executor.add_node(node)
        return node

    def node(self, name: str):
        """Create a plain helper node in this context."""
        return self.add(rclpy.create_node(name, context=self.context))

    def spin_until(self, predicate, timeout_sec: float = 5.0, tick=None) -> bool:
        """Spin until ``predicate()`` holds; call ``tick()`` before each spin."""
        deadline = time.monotonic() + timeout_sec
        while time.monotonic() < deadline:
            if tick is not None:
                tick()
            self.executor.spin_once(timeout_sec=0.05)
            if predicate():
                return True
        return predicate()

    def close(self) -> None:
        """Destroy every node and the executor."""
        for node in self.executor.get_nodes():
            self.executor.remove_node(node)
            node.destroy_node()
        self.executor.shutdown()


@pytest.fixture
def ros():
    """Yield a RosHarness whose context is shut down after the test, even when it fails."""
    context = Context()
    rclpy.init(context=context)
    harness = RosHarness(context)
    try:
        yield harness
    finally:
        harness.close()
        rclpy.try_shutdown(context=context)
