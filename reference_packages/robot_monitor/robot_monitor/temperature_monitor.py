# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Publish the (simulated) motor temperature and warn when it runs hot."""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from robot_monitor.health.temperature import classify, TemperatureLevel, TemperatureSimulation
from sensor_msgs.msg import Temperature


class TemperatureMonitor(Node):
    """Publish ``sensor_msgs/Temperature`` on ``/temperature`` once per period."""

    def __init__(self, **kwargs) -> None:
        super().__init__('temperature_monitor', **kwargs)
        self.motor = TemperatureSimulation(
            ambient_celsius=self.declare_parameter('ambient_celsius', 25.0).value,
            steady_state_celsius=self.declare_parameter('steady_state_celsius', 80.0).value,
            time_constant_ticks=self.declare_parameter('time_constant_ticks', 60.0).value,
        )
        self.warning = self.declare_parameter('warning_celsius', 70.0).value
        self.critical = self.declare_parameter('critical_celsius', 85.0).value
        self.frame_id = self.declare_parameter('frame_id', 'base_link').value
        period = self.declare_parameter('publish_period_sec', 1.0).value
        self.tick = 0
        self.publisher = self.create_publisher(Temperature, '/temperature', 10)
        self.timer = self.create_timer(period, self.publish_temperature)
        self.get_logger().info('Temperature monitor started')

    def publish_temperature(self) -> None:
        """Publish the current temperature and log it when it crosses a threshold."""
        celsius = self.motor.temperature_at(self.tick)
        msg = Temperature()
        msg.header.stamp = self.get_clock().now().to_msg()
        msg.header.frame_id = self.frame_id
        msg.temperature = celsius
        msg.variance = 0.0  # 0 means unknown (sensor_msgs/Temperature)
        self.publisher.publish(msg)
        level = classify(celsius, self.warning, self.critical)
        if level is TemperatureLevel.CRITICAL:
            self.get_logger().error(f'Critical temperature: {celsius:.1f} C')
        elif level is TemperatureLevel.WARNING:
            self.get_logger().warn(f'High temperature: {celsius:.1f} C')
        self.tick += 1


def main(args: list[str] | None = None) -> None:
    """Run the temperature monitor until interrupted."""
    rclpy.init(args=args)
    try:
        node = TemperatureMonitor()
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
