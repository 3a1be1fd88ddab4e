# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

from setuptools import find_packages, setup

package_name = 'my_robot_pkg'

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='pkgtool developers',
    maintainer_email='dev@example.com',
    description='Robot state logger and robot status service agents',
    license='Apache-2.0',
    extras_require={'test': ['pytest']},
    entry_points={
        'console_scripts': [
            'joint_state_logger = my_robot_pkg.joint_state_logger:main',
            'robot_status_server = my_robot_pkg.robot_status_server:main',
        ],
    },
)
