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

"""Data validator tool: checks sensor streams and reports their health on /diagnostics."""

from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus, KeyValue
from physical_ai_sensors.utils.data_validation import image_problems, imu_problems, scan_problems
from physical_ai_sensors.utils.node_runner import run_node
from rclpy.node import Node
from sensor_msgs.msg import Image, Imu, LaserScan

_CHECKS = (('imu', Imu, '/imu/raw', imu_problems),
           ('scan', LaserScan, '/scan', scan_problems),
           ('camera', Image, '/camera/image_raw', image_problems))


class StreamHealth:
    """Counts of valid and invalid messages of one stream, and the last problems seen."""

    def __init__(self) -> None:
        """Start with nothing received."""
        self.valid = 0
        self.invalid = 0
        self.last_problems: list[str] = []

    def record(self, problems: list[str]) -> None:
        """Count one message with its problems (none when valid)."""
        if problems:
            self.invalid += 1
        else:
            self.valid += 1
        self.last_problems = problems

    def status(self, name: str) -> DiagnosticStatus:
        """Return the diagnostic status: STALE before any message, ERROR on problems."""
        status = DiagnosticStatus(name=f'physical_ai_sensors: {name}', hardware_id=name)
        if self.valid + self.invalid == 0:
            status.level, status.message = DiagnosticStatus.STALE, 'no data received'
        elif self.last_problems:
            status.level, status.message = DiagnosticStatus.ERROR, '; '.join(self.last_problems)
        else:
            status.level, status.message = DiagnosticStatus.OK, 'ok'
        status.values = [KeyValue(key='valid', value=str(self.valid)),
                         KeyValue(key='invalid', value=str(self.invalid))]
        return status


class DataValidatorNode(Node):
    """Validate IMU, scan and camera messages; publish a DiagnosticArray every period."""

    def __init__(self, **kwargs) -> None:
        """Subscribe to each sensor stream and start the report timer."""
        super().__init__('data_validator_node', **kwargs)
        self.declare_parameter('report_period', 1.0)  # seconds
        self.health = {name: StreamHealth() for name, *_ in _CHECKS}
        self.subscriptions_by_name = {
            name: self.create_subscription(msg_type, topic, self._checker(name, check), 10)
            for name, msg_type, topic, check in _CHECKS}
        self.diagnostics_pub = self.create_publisher(DiagnosticArray, '/diagnostics', 10)
        self.timer = self.create_timer(self.get_parameter('report_period').value, self.report)

    def _checker(self, name: str, check):
        def callback(msg) -> None:
            self.health[name].record(check(msg))
        return callback

    def report(self) -> None:
        """Publish the health of every stream."""
        array = DiagnosticArray()
        array.header.stamp = self.get_clock().now().to_msg()
        array.status = [health.status(name) for name, health in self.health.items()]
        self.diagnostics_pub.publish(array)


def main(args=None) -> int:
    """Run the data validator."""
    return run_node(DataValidatorNode, args)


if __name__ == '__main__':
    main()
