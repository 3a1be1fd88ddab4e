# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Keep every test in this process: discovery OFF, own domain id, logs in a temp folder."""

import os
import tempfile
import threading
import time

import pytest
import rclpy
from rclpy.context import Context
from rclpy.executors import MultiThreadedExecutor, SingleThreadedExecutor

os.environ['ROS_AUTOMATIC_DISCOVERY_RANGE'] = 'OFF'
os.environ['ROS_DOMAIN_ID'] = '36'
# pkgtool's colcon runs set ROS_LOG_DIR; any other run gets a folder removed at exit.
if 'ROS_LOG_DIR' not in os.environ:
    _LOG_DIR = tempfile.TemporaryDirectory(prefix='my_robot_pkg-ros-log-')
    os.environ['ROS_LOG_DIR'] = _LOG_DIR.name


def pytest_configure(config):
    """Silence lark's DeprecationWarnings, raised when rclpy parses interface definitions."""
    for module in ('sre_parse', 'sre_constants'):
        config.addinivalue_line(
            'filterwarnings', f"ignore:module '{module}' is deprecated:DeprecationWarning")


class RosHarness:
    """An initialised rclpy context, an executor for the test's nodes and background spinners."""

    def __init__(self, context: Context) -> None:
        self.context = context
        self.executor = SingleThreadedExecutor(context=context)
        self._owned = []
        self._background = []

    def own(self, node):
        """Destroy ``node`` when the test ends, without spinning it."""
        self._owned.append(node)
        return node

    def add(self, node):
        """Spin ``node`` with this harness's executor (see ``spin_until``) and return it."""
        self.executor.add_node(node)
        return self.own(node)

    def node(self, name: str):
        """Create a plain helper node in this context."""
        return self.add(rclpy.create_node(name, context=self.context))

    def spin_in_background(self, node):
        """Spin ``node`` in a thread of its own until the test ends; return it."""
        executor = MultiThreadedExecutor(context=self.context)
        executor.add_node(node)
        thread = threading.Thread(target=executor.spin, daemon=True)
        thread.start()
        self._background.append((executor, thread))
        return self.own(node)

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
        """Stop the background threads, then destroy every node and executor."""
        for executor, thread in self._background:
            executor.shutdown()
            thread.join(timeout=5.0)
        self.executor.shutdown()
        for node in self._owned:
            node.destroy_node()


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
