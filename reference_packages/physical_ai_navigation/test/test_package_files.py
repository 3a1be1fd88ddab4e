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
The package as a whole: entry points, launch file and config, and a safe main().

The chapter's main() referenced the node in ``finally`` even when the node was never
constructed; here construction errors surface as themselves and Ctrl-C ends cleanly.
"""

import ast
import importlib
from pathlib import Path

from physical_ai_navigation.nodes import path_planner
from physical_ai_navigation.utils.node_runner import run_node
import pytest
import rclpy
from rclpy.context import Context
import yaml

ROOT = Path(__file__).resolve().parents[1]
NODE_CLASSES = {
    'path_planner_node': 'physical_ai_navigation.nodes.path_planner:PathPlannerNode',
    'path_follower_node': 'physical_ai_navigation.nodes.path_follower:PathFollowerNode',
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
    assert set(scripts) == {'path_planner', 'path_follower'}
    for target in scripts.values():
        assert callable(load(target)), target


def test_launch_file_and_config_match_the_nodes():
    tree = ast.parse((ROOT / 'launch' / 'navigation.launch.py').read_text())
    executables = next(
        [element.value for element in node.value.elts] for node in ast.walk(tree)
        if isinstance(node, ast.Assign) and getattr(node.targets[0], 'id', '') == 'executables')
    assert set(executables) <= set(console_scripts())
    params_file = ROOT / 'config' / 'navigation_params.yaml'
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
    with pytest.raises(ValueError, match='planner must be one of'):
        path_planner.main(['--ros-args', '-p', 'planner:=bfs'])
    assert not rclpy.ok()


def test_main_ends_cleanly_on_keyboard_interrupt():
    def interrupt():
        raise KeyboardInterrupt

    def interrupted_node():
        node = path_planner.PathPlannerNode()
        node.create_timer(0.01, interrupt)
        return node

    assert run_node(interrupted_node, args=[]) == 0
    assert not rclpy.ok()
