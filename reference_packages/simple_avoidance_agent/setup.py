# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

from setuptools import find_packages, setup

package_name = 'simple_avoidance_agent'

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
    description='LaserScan-driven obstacle avoidance agents that publish velocity commands',
    license='Apache-2.0',
    extras_require={'test': ['pytest']},
    entry_points={
        'console_scripts': [
            'avoidance_agent = simple_avoidance_agent.avoidance_agent:main',
            'advanced_avoidance_agent = simple_avoidance_agent.advanced_avoidance_agent:main',
        ],
    },
)
