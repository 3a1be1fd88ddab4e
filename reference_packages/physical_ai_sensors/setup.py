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

from glob import glob
import os

from setuptools import find_packages, setup

package_name = 'physical_ai_sensors'

setup(
    name=package_name,
    version='1.0.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        (os.path.join('share', package_name, 'launch'),
         glob(os.path.join('launch', '*.launch.py'))),
        (os.path.join('share', package_name, 'config'),
         glob(os.path.join('config', '*.yaml'))),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    author='Physical AI Robotics Team',
    maintainer='Physical AI Robotics Team',
    maintainer_email='developer@physicalaitextbook.com',
    description='Utilities for processing sensor data in Physical AI systems',
    license='Apache-2.0',
    extras_require={'test': ['pytest']},
    entry_points={
        'console_scripts': [
            # Sensor processing nodes
            'imu_processor = physical_ai_sensors.nodes.imu_processor:main',
            'camera_subscriber = physical_ai_sensors.nodes.camera_subscriber:main',
            'lidar_preprocessor = physical_ai_sensors.nodes.lidar_preprocessor:main',
            'sensor_fusion = physical_ai_sensors.nodes.sensor_fusion:main',
            # The chapter's first listing names the fusion node sensor_fusion_node: same node
            'sensor_fusion_node = physical_ai_sensors.nodes.sensor_fusion:main',
            'data_logger_node = physical_ai_sensors.nodes.data_logger_node:main',
            # Utility tools
            'data_validator = physical_ai_sensors.utils.data_validator:main',
            'calibration_tool = physical_ai_sensors.utils.calibration_tool:main',
        ],
    },
)
