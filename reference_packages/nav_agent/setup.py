# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

from setuptools import find_packages, setup

package_name = 'nav_agent'

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
    description='High-level task agent: a Nav2 NavigateToPose action client',
    license='Apache-2.0',
    extras_require={'test': ['pytest']},
    entry_points={
        'console_scripts': [
            'nav_commander = nav_agent.nav_commander:main',
        ],
    },
)
