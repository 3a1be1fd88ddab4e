# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

from glob import glob
import os

from setuptools import find_packages, setup

package_name = 'robot_monitor'

setup(
    name=package_name,
    version='0.1.0',
    # find_packages, not [package_name]: the robot_monitor.health subpackage must be installed.
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        (os.path.join('share', package_name, 'launch'), glob('launch/*.launch.py')),
        (os.path.join('share', package_name, 'config'), glob('config/*.yaml')),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='pkgtool developers',
    maintainer_email='dev@example.com',
    description='Health monitoring system for robots: battery and temperature monitor nodes',
    license='Apache-2.0',
    extras_require={'test': ['pytest']},
    entry_points={
        'console_scripts': [
            'battery_monitor = robot_monitor.battery_monitor:main',
            'temperature_monitor = robot_monitor.temperature_monitor:main',
        ],
    },
)
