# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Exercise 2.3: answer std_srvs/Trigger calls on ``/robot_status``."""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from std_srvs.srv import Trigger

STATUS_MESSAGE = 'Robot is Online and ready.'


class RobotStatusService(Node):
    """Report that the robot is online and ready."""

    def __init__(self, **kwargs) -> None:
        super().__init__('robot_status_server', **kwargs)
        self.srv = self.create_service(Trigger, 'robot_status', self.status_callback)
        self.get_logger().info(
            f'Robot Status Service ready at {self.resolve_service_name("robot_status")}.')

    def status_callback(self, request: Trigger.Request,
                        response: Trigger.Response) -> Trigger.Response:
        """Fill ``response`` with success and the status message."""
        response.success = True
        response.message = STATUS_MESSAGE
        self.get_logger().info('Received status request. Responding: Online and ready.')
        return response


def main(args: list[str] | None = None) -> None:
    """Serve ``/robot_status`` until interrupted."""
    rclpy.init(args=args)
    try:
        node = RobotStatusService()
        try:
            rclpy.spin(node)
        finally:
            node.destroy_node()
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
