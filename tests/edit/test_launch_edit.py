"""Launch files, parameter files and setup.cfg edited in place."""

from __future__ import annotations

import pytest

from pkgtool.edit import EditError, apply_edits
from pkgtool.edit import launch, params, setup_cfg
from pkgtool.edit.source import Source
from pkgtool.model.launch import parse_launch

PY_LAUNCH = '''\
"""Launch."""

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    params = 'x.yaml'
    return LaunchDescription([
        Node(
            package='demo',
            executable='talker',
            parameters=[params],
        ),  # the talker
    ])
'''


def _add(path: str, text: str) -> str:
    result = apply_edits(text, launch.add_node(Source(path, text), "demo", "listener"))
    nodes = parse_launch(path, result).nodes
    assert [(n.package, n.executable) for n in nodes][-1] == ("demo", "listener")
    assert launch.add_node(Source(path, result), "demo", "listener") == []
    return result


def test_python_launch_gets_a_node_like_its_siblings() -> None:
    assert _add("launch/a.launch.py", PY_LAUNCH) == PY_LAUNCH.replace(
        "        ),  # the talker\n", "        ),  # the talker\n        Node(\n"
        "            package='demo',\n            executable='listener',\n"
        "            name='listener',\n            parameters=[params],\n        ),\n")


def test_python_launch_without_nodes_imports_node() -> None:
    text = ("from launch import LaunchDescription\n\n\ndef generate_launch_description():\n"
            "    return LaunchDescription([])\n")
    result = _add("a.launch.py", text)
    assert "from launch import LaunchDescription\nfrom launch_ros.actions import Node\n" in result


def test_python_launch_built_by_add_action_is_refused() -> None:
    text = ("from launch import LaunchDescription\n\n\ndef generate_launch_description():\n"
            "    ld = LaunchDescription()\n    return ld\n")
    with pytest.raises(EditError, match="by hand"):
        launch.add_node(Source("a.launch.py", text), "demo", "listener")


def test_xml_launch_gets_a_node_element() -> None:
    text = '<launch>\r\n  <node pkg="demo" exec="talker"/>\r\n</launch>\r\n'
    assert _add("a.launch.xml", text) == text.replace(
        'talker"/>\r\n', 'talker"/>\r\n  <node pkg="demo" exec="listener" name="listener"/>\r\n')
    empty = "<launch>\n</launch>\n"
    assert _add("b.launch.xml", empty) == \
        '<launch>\n  <node pkg="demo" exec="listener" name="listener"/>\n</launch>\n'


def test_yaml_launch_gets_a_node_item() -> None:
    text = "launch:\n  - node:\n      pkg: demo\n      exec: talker\n\n# end\n"
    assert _add("a.launch.yaml", text) == text.replace(
        "exec: talker\n", "exec: talker\n  - node:\n      pkg: demo\n      exec: listener\n"
        "      name: listener\n")


def test_params_block_is_appended_once() -> None:
    text = "# Parameters\ntalker:\n  ros__parameters:\n    topic: chatter"
    block = "listener:\n  ros__parameters:\n    topic: chatter\n"
    source = Source("config/params.yaml", text)
    result = apply_edits(text, params.add_block(source, "listener", block))
    assert result == text + "\n" + block
    assert params.add_block(Source("p.yaml", result), "listener", block) == []
    with pytest.raises(EditError, match="block mapping"):
        params.add_block(Source("p.yaml", "- a\n"), "listener", block)


def test_setup_cfg_options_are_set_and_removed_in_place() -> None:
    text = "[develop]\r\nscript-dir = $base/lib/demo  \r\n; note\r\n[install]\r\nx=1\r\n"
    source = Source("setup.cfg", text)
    fixed = apply_edits(text, setup_cfg.set_option(source, "develop", "script_dir",
                                                   "$base/lib/demo"))
    assert fixed == text.replace("script-dir = $base/lib/demo  ", "script_dir = $base/lib/demo")
    added = apply_edits(text, setup_cfg.set_option(source, "install", "install_scripts", "$b"))
    assert added == text.replace("x=1\r\n", "x=1\r\ninstall_scripts=$b\r\n")
    new = apply_edits(text, setup_cfg.set_option(source, "egg_info", "tag_build", ""))
    assert new == text + "[egg_info]\r\ntag_build=\r\n"
    removed = apply_edits(text, setup_cfg.remove_option(source, "install", "x"))
    assert removed == "[develop]\r\nscript-dir = $base/lib/demo  \r\n; note\r\n[install]\r\n"
    assert setup_cfg.set_option(Source("setup.cfg", fixed), "develop", "script_dir",
                                "$base/lib/demo") == []


def test_an_inline_launch_list_is_split_for_the_multi_line_node() -> None:
    text = ("from launch import LaunchDescription\nfrom launch_ros.actions import Node\n\n\n"
            "def generate_launch_description():\n"
            "    return LaunchDescription([Node(package='demo', executable='talker')])\n")
    assert _add("a.launch.py", text).endswith(
        "    return LaunchDescription([\n        Node(package='demo', executable='talker'),\n"
        "        Node(\n            package='demo',\n            executable='listener',\n"
        "            name='listener',\n        ),\n    ])\n")
