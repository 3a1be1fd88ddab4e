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

"""Launch the image subscriber and the object detector with config/camera_params.yaml."""

import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    """Start the camera processing nodes."""
    params = os.path.join(get_package_share_directory('physical_ai_camera'),
                          'config', 'camera_params.yaml')
    executables = ('image_subscriber', 'object_detector')
    return LaunchDescription([
        Node(package='physical_ai_camera', executable=executable, parameters=[params],
             output='screen')
        for executable in executables
    ])
