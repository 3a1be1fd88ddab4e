# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Publish the (simulated) battery voltage and warn when it runs low."""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from robot_monitor.health.battery import BatterySimulation, is_low
from std_msgs.msg import Float32


class BatteryMonitor(Node):
    """Publish the battery voltage on ``/battery/voltage`` once per period."""

    def __init__(self, **kwargs) -> None:
        super().__init__('battery_monitor', **kwargs)
        self.battery = BatterySimulation(
            initial_voltage=self.declare_parameter('initial_voltage', 12.6).value,
            drain_per_tick=self.declare_parameter('drain_per_tick', 0.01).value,
        )
        self.low_voltage = self.declare_parameter('low_voltage_threshold', 10.0).value
        period = self.declare_parameter('publish_period_sec', 1.0).value
        self.tick = 0
        self.publisher = self.create_publisher(Float32, '/battery/voltage', 10)
        self.timer = self.create_timer(period, self.publish_battery_status)
        self.get_logger().info('Battery monitor started')

    def publish_battery_status(self) -> None:
        """Publish the current voltage, then let the simulated battery drain one step."""
        voltage = self.battery.voltage_at(self.tick)
        self.publisher.publish(Float32(data=voltage))
        if is_low(voltage, self.low_voltage):
            self.get_logger().warn(f'Low battery: {voltage:.2f}V')
        self.tick += 1


def main(args: list[str] | None = None) -> None:
    """Run the battery monitor until interrupted."""
    rclpy.init(args=args)
    try:
        node = BatteryMonitor()
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
