# Copyright 2026 Physical AI Robotics Team
#
# Licensed under the Apache License, Version 2.0 (the "License");
# you may not use this file except in compliance with the License.
# You may obtain a copy of the License at
#
#     http://www.apache.org/licenses/LICENSE-2.0
#
# Unless required by applicable law or agreed to in writing, software
# distributed under the License is distributed on an "AS IS" BASIS,
# WITHOUT WARRANTIES OR CONDITIONS OF ANY KIND, either express or implied.
# See the License for the specific language governing permissions and
# limitations under the License.

"""Test set-up: isolated in-process ROS 2 and a small harness to drive nodes through topics."""

import os
import tempfile
import time

import pytest
import rclpy
from rclpy.context import Context
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter

# Before any rclpy.init: no discovery beyond this process, a domain of our own, logs in a temp
# folder (colcon test runs these tests; nothing may reach the network or ~/.ros).
os.environ['ROS_AUTOMATIC_DISCOVERY_RANGE'] = 'OFF'
os.environ.setdefault('ROS_DOMAIN_ID', '72')
# pkgtool's colcon runs set ROS_LOG_DIR; any other run gets a folder removed at exit.
if 'ROS_LOG_DIR' not in os.environ:
    _LOG_DIR = tempfile.TemporaryDirectory(prefix='physical_ai_camera-log-')
    os.environ['ROS_LOG_DIR'] = _LOG_DIR.name


class RosHarness:
    """Start nodes under test in one context, publish to them and collect what they publish."""

    def __init__(self, context: Context) -> None:
        """Create the executor and a probe node for test publishers and subscriptions."""
        self.context = context
        self.executor = SingleThreadedExecutor(context=context)
        self.probe = Node('test_probe', context=context)
        self.nodes = [self.probe]
        self.executor.add_node(self.probe)

    def start(self, node_class, **parameters):
        """Construct ``node_class`` with parameter overrides and spin it with the probe."""
        overrides = [Parameter(name, value=value) for name, value in parameters.items()]
        node = node_class(context=self.context, parameter_overrides=overrides)
        self.nodes.append(node)
        self.executor.add_node(node)
        return node

    def publisher(self, msg_type, topic: str, qos=10):
        """Return a probe publisher, once the node under test has subscribed."""
        publisher = self.probe.create_publisher(msg_type, topic, qos)
        assert self.spin_until(lambda: publisher.get_subscription_count() > 0), topic
        return publisher

    def collect(self, msg_type, topic: str, qos=10) -> list:
        """Return a list that fills with the messages published on ``topic``."""
        received = []
        self.probe.create_subscription(msg_type, topic, received.append, qos)
        return received

    def spin_until(self, predicate, timeout: float = 5.0, action=None) -> bool:
        """Spin until ``predicate()`` holds (calling ``action()`` each round); its last value."""
        deadline = time.monotonic() + timeout
        while not predicate() and time.monotonic() < deadline:
            if action is not None:
                action()
            self.executor.spin_once(timeout_sec=0.02)
        return bool(predicate())

    def close(self) -> None:
        """Destroy every node."""
        self.executor.shutdown()
        for node in self.nodes:
            node.destroy_node()


@pytest.fixture
def ros():
    """Give the test its own rclpy context and harness, shut down afterwards."""
    context = Context()
    rclpy.init(context=context)
    harness = RosHarness(context)
    try:
        yield harness
    finally:
        harness.close()
        rclpy.shutdown(context=context)
