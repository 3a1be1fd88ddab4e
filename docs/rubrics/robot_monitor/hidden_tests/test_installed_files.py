"""What colcon must install besides the code: manifest, launch file and configuration."""

import glob
import os

from ament_index_python.packages import get_package_share_directory


def _share():
    return get_package_share_directory('robot_monitor')


def test_package_xml_is_installed():
    assert os.path.isfile(os.path.join(_share(), 'package.xml'))


def test_a_launch_file_is_installed():
    assert glob.glob(os.path.join(_share(), 'launch', '*.py')), 'no launch file in share/launch'


def test_a_yaml_configuration_is_installed():
    assert glob.glob(os.path.join(_share(), 'config', '*.yaml')), 'no YAML in share/config'
