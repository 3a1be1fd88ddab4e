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

The chapter's image_subscriber called cv2 without importing it, its corner detector used
np.int0 (removed in NumPy 2), it depended on cv_bridge, and main() referenced the node in
``finally`` even when the node was never constructed.
"""

import ast
import importlib
from pathlib import Path

from physical_ai_camera.nodes import object_detector
from physical_ai_camera.utils.node_runner import run_node
import pytest
import rclpy
from rclpy.context import Context
import yaml

ROOT = Path(__file__).resolve().parents[1]
SOURCES = sorted((ROOT / 'physical_ai_camera').rglob('*.py'))
NODE_CLASSES = {
    'image_subscriber_node': 'physical_ai_camera.nodes.image_subscriber:ImageSubscriberNode',
    'object_detector_node': 'physical_ai_camera.nodes.object_detector:ObjectDetectorNode',
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


def imported_names(tree: ast.AST) -> set:
    names = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names |= {alias.asname or alias.name.split('.')[0] for alias in node.names}
        elif isinstance(node, ast.ImportFrom):
            names |= {alias.asname or alias.name for alias in node.names}
            names.add((node.module or '').split('.')[0])
    return names


def test_every_console_script_has_a_real_main():
    scripts = console_scripts()
    assert set(scripts) == {'image_subscriber', 'object_detector'}
    for target in scripts.values():
        assert callable(load(target)), target


@pytest.mark.parametrize('path', SOURCES, ids=lambda p: p.name)
def test_modules_import_what_they_use_and_avoid_removed_apis(path):
    tree = ast.parse(path.read_text())
    imported = imported_names(tree)
    used = {node.value.id for node in ast.walk(tree)
            if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name)}
    assert 'cv2' not in used or 'cv2' in imported, 'cv2 is used without being imported'
    assert 'cv_bridge' not in imported
    numpy_attributes = {node.attr for node in ast.walk(tree)
                        if isinstance(node, ast.Attribute)
                        and getattr(node.value, 'id', '') in ('np', 'numpy')}
    assert not numpy_attributes & {'int0', 'float_', 'bool8'}, 'NumPy 1 alias used'


def test_launch_file_and_config_match_the_nodes():
    tree = ast.parse((ROOT / 'launch' / 'camera_processing.launch.py').read_text())
    executables = next(
        [element.value for element in node.value.elts] for node in ast.walk(tree)
        if isinstance(node, ast.Assign) and getattr(node.targets[0], 'id', '') == 'executables')
    assert set(executables) <= set(console_scripts())
    params_file = ROOT / 'config' / 'camera_params.yaml'
    config = yaml.safe_load(params_file.read_text())
    assert set(config) == {f'{name}_node' for name in executables}
    context = Context()
    rclpy.init(context=context, args=['--ros-args', '--params-file', str(params_file)])
    try:
        for node_name, section in config.items():
            node = load(NODE_CLASSES[node_name])(context=context)
            for name, value in section['ros__parameters'].items():
                assert node.get_parameter(name).value == value, (node_name, name)
            node.destroy_node()
    finally:
        rclpy.shutdown(context=context)


def test_main_raises_the_real_error_when_the_node_cannot_be_built():
    with pytest.raises(ValueError, match='three values'):
        object_detector.main(['--ros-args', '-p', 'lower_hsv:=[1, 2]'])
    assert not rclpy.ok()


def test_main_ends_cleanly_on_keyboard_interrupt():
    def interrupt():
        raise KeyboardInterrupt

    def interrupted_node():
        node = object_detector.ObjectDetectorNode()
        node.create_timer(0.01, interrupt)
        return node

    assert run_node(interrupted_node, args=[]) == 0
    assert not rclpy.ok()
