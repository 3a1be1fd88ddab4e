# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Start both health monitors with the parameters of config/params.yaml."""

from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description() -> LaunchDescription:
    params = PathJoinSubstitution([FindPackageShare('robot_monitor'), 'config', 'params.yaml'])
    return LaunchDescription([
        Node(package='robot_monitor', executable='battery_monitor', name='battery_monitor',
             parameters=[params], output='screen'),
        Node(package='robot_monitor', executable='temperature_monitor',
             name='temperature_monitor', parameters=[params], output='screen'),
    ])
