# Copyright 2026 pkgtool developers
# SPDX-License-Identifier: Apache-2.0

"""Packaging: subpackages, launch/config installation, entry points and the shipped YAML."""

import ast
import importlib
from pathlib import Path

from ament_index_python.packages import (
    get_package_prefix, get_package_share_directory, PackageNotFoundError)
import pytest
from rclpy.parameter import Parameter
from robot_monitor.battery_monitor import BatteryMonitor
from robot_monitor.temperature_monitor import TemperatureMonitor
from setuptools import find_packages
import yaml

ROOT = Path(__file__).resolve().parents[1]
NODES = {'battery_monitor': BatteryMonitor, 'temperature_monitor': TemperatureMonitor}


def _setup_keywords() -> dict:
    tree = ast.parse((ROOT / 'setup.py').read_text())
    call = next(n for n in ast.walk(tree)
                if isinstance(n, ast.Call) and getattr(n.func, 'id', '') == 'setup')
    return {k.arg: k.value for k in call.keywords}


def _console_scripts() -> dict[str, str]:
    entry_points = ast.literal_eval(_setup_keywords()['entry_points'])
    pairs = (line.split('=') for line in entry_points['console_scripts'])
    return {name.strip(): target.strip() for name, target in pairs}


def test_seed_mistake_setup_py_installs_subpackages():
    # Lesson 3.1 wrote packages=[package_name], which silently drops robot_monitor.health.
    packages = _setup_keywords()['packages']
    assert isinstance(packages, ast.Call) and packages.func.id == 'find_packages'
    found = find_packages(where=str(ROOT), exclude=['test'])
    assert 'robot_monitor.health' in found
    assert set(found) != {'robot_monitor'}


def _installed_prefix() -> Path:
    try:
        return Path(get_package_prefix('robot_monitor'))
    except PackageNotFoundError:
        pytest.skip('robot_monitor is not installed: run the tests through colcon test')


def test_seed_mistake_installed_package_contains_the_subpackage():
    installed = list(_installed_prefix().glob('lib/python3*/site-packages/robot_monitor'))
    if not installed:
        pytest.skip('a --symlink-install build imports the sources directly')
    assert (installed[0] / 'health' / 'battery.py').is_file()
    assert (installed[0] / 'health' / 'temperature.py').is_file()


def test_launch_and_config_are_installed_in_share():
    _installed_prefix()
    share = Path(get_package_share_directory('robot_monitor'))
    assert (share / 'launch' / 'robot_monitor.launch.py').is_file()
    assert (share / 'config' / 'params.yaml').is_file()
    assert (share / 'package.xml').is_file()


def test_console_scripts_point_at_callables():
    scripts = _console_scripts()
    assert set(scripts) == set(NODES)
    for target in scripts.values():
        module, function = target.split(':')
        assert callable(getattr(importlib.import_module(module), function))


def test_launch_file_starts_the_registered_executables():
    launch = ROOT / 'launch' / 'robot_monitor.launch.py'
    calls = [n for n in ast.walk(ast.parse(launch.read_text())) if isinstance(n, ast.Call)]
    started = {k.value.value for c in calls for k in c.keywords if k.arg == 'executable'}
    assert started == set(_console_scripts())


def test_data_files_globs_match_the_launch_and_config_files():
    patterns = [n.value for n in ast.walk(_setup_keywords()['data_files'])
                if isinstance(n, ast.Constant) and isinstance(n.value, str) and '*' in n.value]
    assert sorted(patterns) == ['config/*.yaml', 'launch/*.launch.py']
    for pattern in patterns:
        assert list(ROOT.glob(pattern)), pattern


def test_config_yaml_loads_into_both_nodes(ros):
    params_file = ROOT / 'config' / 'params.yaml'
    config = yaml.safe_load(params_file.read_text())
    assert set(config) == set(NODES)
    for name, node_class in NODES.items():
        node = node_class(context=ros.context,
                          cli_args=['--ros-args', '--params-file', str(params_file)])
        try:
            for key, value in config[name]['ros__parameters'].items():
                assert node.has_parameter(key), f'{name} does not declare {key}'
                assert node.get_parameter(key).value == value
                assert node.get_parameter(key).type_ != Parameter.Type.NOT_SET
        finally:
            node.destroy_node()
