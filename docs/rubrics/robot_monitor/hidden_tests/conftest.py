"""Instructor harness: start the student's installed console scripts, listen with real rclpy.

pkgtool runs these tests in its sandbox with ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST and a
domain id of the job's own, so the node under test and this listener find each other and
nothing else. Every node started here is stopped after its test.
"""

import os
import signal
import subprocess
import time

from ament_index_python.packages import get_package_prefix
import pytest
import rclpy
from rclpy.context import Context
from rclpy.executors import SingleThreadedExecutor

PACKAGE = 'robot_monitor'


def pytest_configure(config):
    """Silence lark's DeprecationWarnings, raised when rclpy parses interface definitions."""
    for module in ('sre_parse', 'sre_constants'):
        config.addinivalue_line(
            'filterwarnings', f"ignore:module '{module}' is deprecated:DeprecationWarning")


@pytest.fixture
def start_node():
    """Start ``lib/robot_monitor/<name>`` as `ros2 run` would; stop it after the test."""
    started = []

    def start(name):
        script = os.path.join(get_package_prefix(PACKAGE), 'lib', PACKAGE, name)
        assert os.access(script, os.X_OK), f'`{name}` is not installed in lib/{PACKAGE}'
        process = subprocess.Popen([script], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                   text=True, start_new_session=True)
        started.append(process)
        return process

    yield start
    for process in started:
        if process.poll() is None:
            os.killpg(process.pid, signal.SIGINT)
            try:
                process.wait(timeout=5)
            except subprocess.TimeoutExpired:
                os.killpg(process.pid, signal.SIGKILL)
                process.wait()


@pytest.fixture
def exit_message():
    """Say why a started node is gone: status and last output line first, then all output."""
    def message(name, process):
        output = process.stdout.read() if process.stdout else ''
        last = (output.strip().splitlines() or ['no output'])[-1].strip()
        return f'`{name}` exited with status {process.returncode}: {last}\n{output}'

    return message


class Listener:
    """A node of the test's own that collects messages and looks at the ROS graph."""

    def __init__(self, context):
        self.node = rclpy.create_node('instructor_listener', context=context)
        self.executor = SingleThreadedExecutor(context=context)
        self.executor.add_node(self.node)

    def collect(self, msg_type, topic):
        """Subscribe and return the list the messages will be appended to."""
        received = []
        self.node.create_subscription(msg_type, topic, received.append, 10)
        return received

    def spin_until(self, predicate, timeout_sec):
        """Spin until ``predicate()`` holds or the time is up; return whether it held."""
        deadline = time.monotonic() + timeout_sec
        while time.monotonic() < deadline:
            self.executor.spin_once(timeout_sec=0.1)
            if predicate():
                return True
        return predicate()


@pytest.fixture
def listener():
    """A Listener in a fresh rclpy context, shut down after the test."""
    context = Context()
    rclpy.init(context=context)
    helper = Listener(context)
    try:
        yield helper
    finally:
        helper.executor.shutdown()
        helper.node.destroy_node()
        rclpy.try_shutdown(context=context)
