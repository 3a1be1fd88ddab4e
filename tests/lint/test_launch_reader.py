"""The static launch reader: one test per construct, and bad input never raises."""

from __future__ import annotations

import ast
import textwrap

import pytest

from pkgtool.model.launch import LaunchFile, is_launch_file
from pkgtool.model.launch_python import read_python_launch
from pkgtool.model.launch_reader import read_launch


def _py(body: str) -> LaunchFile:
    return read_launch("launch/demo.launch.py", textwrap.dedent(body))


def _nodes(launch: LaunchFile) -> list[tuple[str | None, str | None, int]]:
    return [(n.package, n.executable, n.span.line) for n in launch.nodes]


def _files(launch: LaunchFile) -> list[tuple[str | None, tuple[str, ...], int]]:
    return [(f.package, f.parts, f.span.line) for f in launch.files]


def _parameter_files(launch: LaunchFile) -> list[tuple[str | None, tuple[str, ...], int]]:
    return [(f.package, f.parts, f.span.line) for n in launch.nodes for f in n.parameter_files]


def test_launch_file_names() -> None:
    assert all(is_launch_file(p) for p in ("launch/a.launch.py", "b_launch.py", "c.launch.xml",
                                           "d.launch.yaml", "e_launch.yml"))
    assert not any(is_launch_file(p) for p in ("launch/helpers.py", "launch.py", "a.yaml"))


def test_python_node_keywords() -> None:
    launch = _py("""
        from launch_ros.actions import Node
        Node(package='demo_nodes_cpp', executable='talker')
        """)
    assert launch.kind == "python" and launch.problem is None
    assert _nodes(launch) == [("demo_nodes_cpp", "talker", 3)]


def test_python_node_through_module_attribute_and_legacy_keyword() -> None:
    launch = _py("""
        import launch_ros.actions
        launch_ros.actions.Node(package='turtlesim', node_executable='turtlesim_node')
        """)
    assert _nodes(launch) == [("turtlesim", "turtlesim_node", 3)]


def test_python_lifecycle_and_composable_nodes() -> None:
    launch = _py("""
        LifecycleNode(package='nav2_map_server', executable='map_server', name='m')
        ComposableNodeContainer(package='rclcpp_components', executable='component_container',
            composable_node_descriptions=[ComposableNode(package='image_proc', plugin='a::B')])
        """)
    assert _nodes(launch) == [("nav2_map_server", "map_server", 2),
                              ("rclcpp_components", "component_container", 3),
                              ("image_proc", None, 4)]


def test_python_module_level_and_function_level_names_resolve() -> None:
    launch = _py("""
        package_name = 'demo'
        EXECUTABLE = 'tal' + 'ker'

        def generate_launch_description():
            exe = f'{EXECUTABLE}'
            return [Node(package=package_name, executable=exe)]
        """)
    assert _nodes(launch) == [("demo", "talker", 7)]


def test_python_ambiguous_and_dynamic_names_stay_unknown() -> None:
    launch = _py("""
        name = 'a'
        name = 'b'

        def generate_launch_description(context=None, package='x'):
            return [Node(package=name, executable=LaunchConfiguration('exe')),
                    Node(package=package, executable=unknown_name)]
        """)
    assert _nodes(launch) == [(None, None, 6), (None, None, 7)]


def test_python_share_lookups_give_package_refs() -> None:
    launch = _py("""
        from ament_index_python.packages import get_package_share_directory
        get_package_share_directory('a_pkg')
        FindPackageShare('b_pkg')
        FindPackageShare(package='c_pkg')
        get_package_prefix('d_pkg')
        get_package_share_directory(LaunchConfiguration('p'))
        """)
    assert [(p.package, p.span.line) for p in launch.packages] == [
        ("a_pkg", 3), ("b_pkg", 4), ("c_pkg", 5), ("d_pkg", 6)]


def test_python_os_path_join_of_share_directory_is_a_file_ref() -> None:
    launch = _py("""
        import os
        def generate_launch_description():
            share = get_package_share_directory('demo')
            params = os.path.join(share, 'config', 'params.yaml')
            return [Node(package='demo', executable='talker', parameters=[params])]
        """)
    assert _files(launch) == [("demo", ("config", "params.yaml"), 5)]


def test_python_path_join_substitution_and_pathlib() -> None:
    launch = _py("""
        from pathlib import Path
        urdf = PathJoinSubstitution([FindPackageShare('desc'), 'urdf', 'robot.urdf'])
        rviz = Path(get_package_share_directory('desc')) / 'rviz' / 'view.rviz'
        world = get_package_share_path('sim') / 'worlds/empty.world'
        use(urdf, rviz, world)
        """)
    assert _files(launch) == [("desc", ("urdf", "robot.urdf"), 3),
                              ("desc", ("rviz", "view.rviz"), 4),
                              ("sim", ("worlds", "empty.world"), 5)]


def test_python_concatenation_and_f_strings() -> None:
    launch = _py("""
        share = get_package_share_directory('demo')
        a = share + '/config/a.yaml'
        b = f'{share}/config/b.yaml'
        c = share + 'config'
        use(a, b, c)
        """)
    assert _files(launch) == [("demo", ("config", "a.yaml"), 3), ("demo", ("config", "b.yaml"), 4)]


def test_python_module_level_paths_nothing_reads_are_not_read() -> None:
    text = textwrap.dedent("""
        share = get_package_share_directory('demo')
        LEGACY = share + '/config/legacy.yaml'
        TABLE = os.path.join(share, 'config', 'table.yaml')
        USED = os.path.join(share, 'config', 'used.yaml')
        print(USED)
        """)
    tree = ast.parse(text)
    assert [f.parts for f in read_python_launch("m.py", tree)[2]] == [("config", "used.yaml")]
    exported = [f.parts for f in read_python_launch("m.py", tree, frozenset({"TABLE"}))[2]]
    assert exported == [("config", "table.yaml"), ("config", "used.yaml")]


def test_python_include_launch_description() -> None:
    launch = _py("""
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            [FindPackageShare('nav2_bringup'), '/launch/navigation_launch.py']))
        IncludeLaunchDescription(PythonLaunchDescriptionSource(os.path.join(
            get_package_share_directory('other'), 'launch', 'x.launch.py')))
        """)
    assert [p.package for p in launch.packages] == ["nav2_bringup", "other"]
    assert [(f.package, f.parts) for f in launch.files] == [
        ("nav2_bringup", ("launch", "navigation_launch.py")), ("other", ("launch", "x.launch.py"))]


def test_python_directory_refs_are_dropped_when_a_file_below_is_used() -> None:
    launch = _py("""
        config = os.path.join(get_package_share_directory('demo'), 'config')
        params = os.path.join(config, 'params.yaml')
        use(params)
        """)
    assert _files(launch) == [("demo", ("config", "params.yaml"), 3)]


def test_python_unknown_or_absolute_parts_give_no_file_ref() -> None:
    launch = _py("""
        share = get_package_share_directory('demo')
        os.path.join(share, LaunchConfiguration('file'))
        os.path.join(share, '/etc/passwd')
        os.path.join(share, '..', 'other', 'x.yaml')
        """)
    assert launch.files == () and [p.package for p in launch.packages] == ["demo"]


def test_python_node_parameter_files() -> None:
    launch = _py("""
        import os
        from ament_index_python.packages import get_package_share_directory
        from launch_ros.actions import Node
        share = get_package_share_directory('demo')
        params = [os.path.join(share, 'config', 'a.yaml')]
        Node(package='demo', executable='t', parameters=[
            os.path.join(share, 'config', 'b.yaml'), {'x': 1}, LaunchConfiguration('p')])
        Node(package='demo', executable='t', parameters=params)
        """)
    assert _parameter_files(launch) == [("demo", ("config", "b.yaml"), 8),
                                        ("demo", ("config", "a.yaml"), 9)]


def test_python_execute_process_ros2_run() -> None:
    launch = _py("ExecuteProcess(cmd=['ros2', 'run', 'turtlesim', 'turtlesim_node'])\n")
    assert _nodes(launch) == [("turtlesim", "turtlesim_node", 1)]


def _unused(launch: LaunchFile) -> list[tuple[str | None, bool]]:
    return [(n.package, n.unused) for n in launch.nodes]


def test_python_node_assigned_to_a_name_never_read_is_unused() -> None:
    launch = _py("""
        def generate_launch_description():
            rviz = Node(package='rviz2', executable='rviz2',
                        arguments=[FindPackageShare('viewer'), get_package_share_directory('b')])
            container = ComposableNodeContainer(package='rclcpp_components', executable='c',
                composable_node_descriptions=[ComposableNode(package='image_proc', plugin='P')])
            ros2 = ExecuteProcess(cmd=['ros2', 'run', 'turtlesim', 'turtlesim_node'])
            talker = Node(package='demo', executable='talker')
            return LaunchDescription([talker])
        """)
    assert _unused(launch) == [("rviz2", True), ("rclcpp_components", True),
                               ("image_proc", True), ("turtlesim", True), ("demo", False)]
    assert [(p.package, p.unused) for p in launch.packages] == [("viewer", True), ("b", False)]


@pytest.mark.parametrize("use", [
    "ld.add_action(node)", "return [node]", "return LaunchDescription([node])",
    "def later(context):\n    return [node]", "global node", "del node", "print(locals())",
    "other = node", "node.name"])
def test_python_node_read_in_any_way_is_used(use: str) -> None:
    body = textwrap.indent(use, "    ")
    launch = _py(f"def generate_launch_description():\n"
                 f"    node = Node(package='rviz2', executable='rviz2')\n{body}\n")
    assert _unused(launch) == [("rviz2", False)]


@pytest.mark.parametrize("text", [
    "node = Node(package='rviz2', executable='rviz2')\n",
    "def f():\n    a = b = Node(package='rviz2', executable='rviz2')\n",
    "def f():\n    node: Node = Node(package='rviz2', executable='rviz2')\n",
    "def f():\n    node = [Node(package='rviz2', executable='rviz2')]\n",
    "def f():\n    done = ld.add_action(Node(package='rviz2', executable='rviz2'))\n",
    "def f():\n    node = Node(package='rviz2', arguments=[(p := 'x')])\n    return p\n",
    "def f():\n    node = Node(package='rviz2', executable='rviz2')\n"
    "    def g():\n        nonlocal node\n",
    "class A:\n    node = Node(package='rviz2', executable='rviz2')\n"])
def test_python_node_outside_a_plain_local_assignment_is_used(text: str) -> None:
    assert _unused(_py(text)) == [("rviz2", False)]


def test_python_launch_file_keeps_its_imports() -> None:
    launch = _py("""
        from launch import LaunchDescription
        import launch_ros.actions
        """)
    assert launch.python is not None
    assert [i.module for i in launch.python.imports] == ["launch", "launch_ros.actions"]


def test_python_syntax_error_is_a_problem() -> None:
    launch = _py("def generate_launch_description(:\n")
    assert launch.problem is not None and launch.problem.kind == "python-syntax"
    assert launch.problem.span.line == 1 and launch.nodes == ()


def test_python_self_referencing_name_does_not_recurse_forever() -> None:
    launch = _py("""
        a = b
        b = a
        Node(package=a, executable='x')
        """)
    assert _nodes(launch) == [(None, "x", 4)]


def test_xml_nodes_includes_and_params() -> None:
    launch = read_launch("launch/demo.launch.xml", textwrap.dedent("""\
        <launch>
          <arg name="use_sim" default="false"/>
          <node pkg="demo" exec="talker" name="talker">
            <param from="$(find-pkg-share demo)/config/params.yaml"/>
          </node>
          <node pkg="$(var package)" exec="x"/>
          <include file="$(find-pkg-share nav2_bringup)/launch/navigation_launch.py"/>
          <node_container pkg="rclcpp_components" exec="component_container" name="c">
            <composable_node pkg="image_proc" plugin="image_proc::RectifyNode"/>
          </node_container>
          <executable cmd="echo $(find-pkg-prefix demo)"/>
        </launch>
        """))
    assert launch.kind == "xml" and launch.problem is None
    assert _nodes(launch) == [("demo", "talker", 3), (None, "x", 6),
                              ("rclcpp_components", "component_container", 8),
                              ("image_proc", None, 9)]
    assert [(p.package, p.span.line) for p in launch.packages] == [
        ("demo", 4), ("nav2_bringup", 7), ("demo", 11)]
    assert _files(launch) == [("demo", ("config", "params.yaml"), 4),
                              ("nav2_bringup", ("launch", "navigation_launch.py"), 7)]
    assert _parameter_files(launch) == [("demo", ("config", "params.yaml"), 4)]


@pytest.mark.parametrize(("text", "kind"), [
    ("<launch><node pkg='a'></launch>", "xml-syntax"),
    ("<!DOCTYPE launch [<!ENTITY x 'y'>]><launch/>", "xml-entity"),
])
def test_xml_problems(text: str, kind: str) -> None:
    launch = read_launch("launch/demo.launch.xml", text)
    assert launch.problem is not None and launch.problem.kind == kind and launch.nodes == ()


def test_yaml_nodes_and_substitutions() -> None:
    launch = read_launch("launch/demo.launch.yaml", textwrap.dedent("""\
        launch:
        - arg:
            name: use_sim
        - node:
            pkg: demo
            exec: talker
            param:
            - from: $(find-pkg-share demo)/config/params.yaml
        - include:
            file: "$(find-pkg-share nav2_bringup)/launch/navigation_launch.py"
        """))
    assert launch.kind == "yaml" and launch.problem is None
    assert _nodes(launch) == [("demo", "talker", 4)]
    assert [p.package for p in launch.packages] == ["demo", "nav2_bringup"]
    assert _files(launch) == [("demo", ("config", "params.yaml"), 8),
                              ("nav2_bringup", ("launch", "navigation_launch.py"), 10)]
    assert _parameter_files(launch) == [("demo", ("config", "params.yaml"), 8)]


def test_yaml_syntax_error_has_a_line() -> None:
    launch = read_launch("launch/demo.launch.yaml", "launch:\n- node: [\n")
    assert launch.problem is not None and launch.problem.kind == "yaml-syntax"
    assert launch.problem.span.line == 3


def test_yaml_aliases_are_walked_once() -> None:
    lines, previous = ["a: &a ['$(find-pkg-share x)']"], "a"
    for level in range(8):  # 9**8 references if expanded
        lines.append(f"l{level}: &l{level} [{', '.join([f'*{previous}'] * 9)}]")
        previous = f"l{level}"
    text = "\n".join(lines) + "\n"
    launch = read_launch("launch/bomb.launch.yaml", text)
    assert launch.problem is None and [p.package for p in launch.packages] == ["x"]


def test_deeply_nested_python_is_not_a_crash() -> None:
    launch = _py("x = " + "+".join(["'a'"] * 2000) + "\n")
    assert launch.problem is None or launch.problem.kind == "python-syntax"


def test_doubling_names_stay_bounded() -> None:
    lines = ["a0 = 'x'"] + [f"a{i} = a{i - 1} + a{i - 1}" for i in range(1, 64)]
    launch = _py("\n".join(lines) + "\nNode(package=a63, executable=a3)\n")
    assert _nodes(launch) == [(None, "x" * 8, 65)]


def test_a_yaml_alias_holding_itself_is_a_syntax_problem() -> None:
    """A mapping that holds itself through an alias never ends: rules walking it would
    recurse forever, so the file is a syntax problem (SYN001) where that mapping starts; an
    alias used twice side by side is no loop."""
    from pkgtool.model.launch_reader import yaml_problem
    from pkgtool.model.span import ParseProblem

    found = yaml_problem("p.yaml", "a: &x\n  b: 1\n  c: *x\n")
    assert isinstance(found, ParseProblem) and found.span.line == 1
    shared = yaml_problem("p.yaml", "d: &x {r: 1}\nn:\n  p: *x\n  q: *x\n")
    assert isinstance(shared, list)
