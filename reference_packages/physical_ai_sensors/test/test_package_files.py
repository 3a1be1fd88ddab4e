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

"""
The package as a whole: entry points, launch file, config, and the chapter's mistakes fixed.

The chapter's setup.py registered console scripts whose modules it never wrote, imported the
undeclared tf_transformations, and its main() referenced the node in ``finally`` even when the
node was never constructed. Each of these is checked here.
"""

import ast
import importlib
from pathlib import Path

from physical_ai_sensors.nodes import imu_processor
from physical_ai_sensors.nodes.lidar_preprocessor import LidarPreprocessorNode
from physical_ai_sensors.utils.node_runner import run_node
import pytest
import rclpy
from rclpy.context import Context
from rclpy.exceptions import InvalidParameterTypeException
import yaml

ROOT = Path(__file__).resolve().parents[1]
NODE_CLASSES = {
    'imu_processor_node': 'physical_ai_sensors.nodes.imu_processor:IMUProcessorNode',
    'lidar_preprocessor_node': 'physical_ai_sensors.nodes.lidar_preprocessor:'
                               'LidarPreprocessorNode',
    'sensor_fusion_node': 'physical_ai_sensors.nodes.sensor_fusion:SensorFusionNode',
    'data_validator_node': 'physical_ai_sensors.utils.data_validator:DataValidatorNode',
}


def load(target: str):
    module, _, attribute = target.partition(':')
    return getattr(importlib.import_module(module.strip()), attribute.strip())


def console_scripts() -> dict:
    tree = ast.parse((ROOT / 'setup.py').read_text())
    for node in ast.walk(tree):
        if isinstance(node, ast.Dict):
            for key, value in zip(node.keys, node.values):
                if isinstance(key, ast.Constant) and key.value == 'console_scripts':
                    entries = [e.value.split('=', 1) for e in value.elts]
                    return {name.strip(): target.strip() for name, target in entries}
    raise AssertionError('setup.py has no console_scripts')


def test_every_console_script_has_a_real_main():
    scripts = console_scripts()
    assert {'imu_processor', 'camera_subscriber', 'lidar_preprocessor', 'sensor_fusion',
            'data_validator', 'calibration_tool', 'sensor_fusion_node',
            'data_logger_node'} == set(scripts)
    for target in scripts.values():
        assert callable(load(target)), target


def test_no_module_uses_tf_transformations():
    for path in (ROOT / 'physical_ai_sensors').rglob('*.py'):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, (ast.Import, ast.ImportFrom)):
                names = [getattr(node, 'module', '') or ''] + [a.name for a in node.names]
                assert not any(n.startswith('tf_transformations') for n in names), path


def test_launch_file_starts_installed_executables_with_configured_parameters():
    tree = ast.parse((ROOT / 'launch' / 'sensor_processing.launch.py').read_text())
    executables = next(
        [element.value for element in node.value.elts] for node in ast.walk(tree)
        if isinstance(node, ast.Assign) and getattr(node.targets[0], 'id', '') == 'executables')
    assert set(executables) <= set(console_scripts())
    config = yaml.safe_load((ROOT / 'config' / 'sensor_params.yaml').read_text())
    node_names = {f'{name}_node' for name in executables}
    assert node_names == set(config)


def test_config_parameters_are_declared_with_matching_types():
    params_file = ROOT / 'config' / 'sensor_params.yaml'
    config = yaml.safe_load(params_file.read_text())
    context = Context()
    rclpy.init(context=context, args=['--ros-args', '--params-file', str(params_file)])
    try:
        for node_name, section in config.items():
            node = load(NODE_CLASSES[node_name])(context=context)
            for name, value in section['ros__parameters'].items():
                assert node.has_parameter(name), f'{node_name} does not declare {name}'
                assert node.get_parameter(name).value == value
            node.destroy_node()
    finally:
        rclpy.shutdown(context=context)


def test_main_raises_the_real_error_when_the_node_cannot_be_built():
    with pytest.raises(InvalidParameterTypeException):
        imu_processor.main(['--ros-args', '-p', 'publish_frequency:=fast'])
    assert not rclpy.ok()


def test_main_ends_cleanly_on_keyboard_interrupt():
    def interrupted_node():
        node = LidarPreprocessorNode()
        node.create_timer(0.01, interrupt)
        return node

    def interrupt():
        raise KeyboardInterrupt

    assert run_node(interrupted_node, args=[]) == 0
    assert not rclpy.ok()
