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

"""Run a node from a console script: clean shutdown whatever happens."""

from collections.abc import Callable

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.task import Future


def run_node(factory: Callable[[], Node], args=None,
             until: Callable[[Node], Future] | None = None) -> int:
    """
    Initialise rclpy, build the node and spin it (until the future ``until`` returns is done).

    Ctrl-C ends the node quietly. When the node cannot be constructed, the real error is raised
    after rclpy is shut down; the node is only destroyed if it exists.
    """
    rclpy.init(args=args)
    node = None
    try:
        node = factory()
        if until is None:
            rclpy.spin(node)
        else:
            rclpy.spin_until_future_complete(node, until(node))
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        if node is not None:
            node.destroy_node()
        rclpy.try_shutdown()
    return 0
