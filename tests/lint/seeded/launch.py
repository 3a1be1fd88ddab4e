"""Seeded launch file mistakes (LCH, and SYN/DAT where a launch file is concerned)."""

from __future__ import annotations

from pathlib import Path

from tests.lint.seeded import case, edit, write

PY = "launch/base_pkg.launch.py"
XML_LAUNCH = "launch/extra.launch.xml"
YAML_LAUNCH = "launch/extra.launch.yaml"
XML = "package.xml"


def _other_launch(root: Path, relpath: str, text: str) -> None:
    """Add a launch file and install every file of ``launch/``."""
    write(root, relpath, text)
    edit(root, "setup.py", "glob('launch/*.launch.py')", "glob('launch/*.launch.*')")


@case("LCH001", PY, "executable='talker.py'")
def executable_with_py_suffix(root: Path) -> None:
    edit(root, PY, "executable='talker'", "executable='talker.py'")


@case("LCH001", PY, "executable='talker_node'")
def executable_is_not_a_console_script(root: Path) -> None:
    edit(root, PY, "executable='talker'", "executable='talker_node'")


@case("LCH001", PY, "executable='talker'")
def console_scripts_key_misspelled(root: Path) -> None:
    edit(root, "setup.py", "'console_scripts'", "'console_script'")


@case("LCH002", PY, "package='turtlesim'")
def node_of_undeclared_package(root: Path) -> None:
    edit(root, PY, "package='base_pkg',\n            executable='srv'",
         "package='turtlesim',\n            executable='turtlesim_node'")


@case("LCH002", PY, "FindPackageShare('base_pkgs')")
def find_package_share_typo(root: Path) -> None:
    edit(root, PY, "FindPackageShare('base_pkg')", "FindPackageShare('base_pkgs')")


@case("LCH003", PY, "from launch_ros.actions import Node")
def launch_ros_undeclared(root: Path) -> None:
    edit(root, XML, "  <exec_depend>launch_ros</exec_depend>\n", "")


@case("LCH003", PY, "from launch import LaunchDescription")
def launch_undeclared(root: Path) -> None:
    edit(root, XML, "  <exec_depend>launch</exec_depend>\n", "")


@case("SYN001", PY, "name='talker'")
def python_launch_syntax_error(root: Path) -> None:
    edit(root, PY, "name='talker',", "name='talker'")


@case("LCH001", XML_LAUNCH, "exec=\"talkr\"")
def xml_launch_executable_typo(root: Path) -> None:
    _other_launch(root, XML_LAUNCH, """
        <launch>
          <node pkg="base_pkg" exec="talkr" name="talker"/>
        </launch>
        """)


@case("LCH002", XML_LAUNCH, "pkg=\"demo_nodes_py\"")
def xml_launch_undeclared_package(root: Path) -> None:
    _other_launch(root, XML_LAUNCH, """
        <launch>
          <node pkg="demo_nodes_py" exec="listener" name="listener"/>
        </launch>
        """)


@case("SYN001", XML_LAUNCH, "</launch>")
def xml_launch_not_well_formed(root: Path) -> None:
    _other_launch(root, XML_LAUNCH, """
        <launch>
          <node pkg="base_pkg" exec="talker" name="talker">
        </launch>
        """)


@case("DAT012", XML_LAUNCH, "config/parameters.yaml")
def xml_launch_reads_missing_config(root: Path) -> None:
    _other_launch(root, XML_LAUNCH, """
        <launch>
          <node pkg="base_pkg" exec="talker" name="talker">
            <param from="$(find-pkg-share base_pkg)/config/parameters.yaml"/>
          </node>
        </launch>
        """)


@case("LCH001", YAML_LAUNCH, "exec: listner")
def yaml_launch_executable_typo(root: Path) -> None:
    _other_launch(root, YAML_LAUNCH, """
        launch:
        - node:
            pkg: base_pkg
            exec: listner
            name: listener
        """)


@case("LCH002", YAML_LAUNCH, "pkg: turtlesim")
def yaml_launch_undeclared_package(root: Path) -> None:
    _other_launch(root, YAML_LAUNCH, """
        launch:
        - node:
            pkg: turtlesim
            exec: turtlesim_node
        """)


@case("SYN001", YAML_LAUNCH, "exec: talker")
def yaml_launch_bad_indentation(root: Path) -> None:
    _other_launch(root, YAML_LAUNCH, """
        launch:
        - node:
            pkg: base_pkg
           exec: talker
        """)


@case("LCH002", PY, "'nav2_bringup'")
def include_from_undeclared_package(root: Path) -> None:
    edit(root, PY, "    return LaunchDescription([\n", """\
    nav2 = PathJoinSubstitution(
        [FindPackageShare('nav2_bringup'), 'launch', 'navigation_launch.py'])
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource(nav2)),
""")
    edit(root, PY, "from launch import LaunchDescription\n",
         "from launch import LaunchDescription\nfrom launch.actions import "
         "IncludeLaunchDescription\nfrom launch.launch_description_sources import "
         "PythonLaunchDescriptionSource\n")


@case("LCH004", PY, "def generate_launch_descriptions")
def launch_function_misspelled(root: Path) -> None:
    edit(root, PY, "def generate_launch_description", "def generate_launch_descriptions")


@case("LCH005", PY, "node_executable='talker'")
def foxy_node_arguments(root: Path) -> None:
    edit(root, PY, "executable='talker',\n            name='talker'",
         "node_executable='talker',\n            node_name='talker'")


@case("LCH005", PY)
def node_keyword_misspelt(root: Path) -> None:
    edit(root, PY, "name='talker'", "nam='talker'")


@case("LCH005", XML_LAUNCH, "type=\"talker\"")
def xml_launch_ros1_node_type(root: Path) -> None:
    _other_launch(root, XML_LAUNCH, """
        <launch>
          <node pkg="base_pkg" type="talker" name="talker"/>
        </launch>
        """)


@case("LCH005", XML_LAUNCH, "executable=\"talker\"")
def xml_launch_python_attribute_names(root: Path) -> None:
    _other_launch(root, XML_LAUNCH, """
        <launch>
          <node package="base_pkg" executable="talker" name="talker"/>
        </launch>
        """)


@case("LCH003", PY, "from ament_index_python")
def launch_ament_index_undeclared(root: Path) -> None:
    edit(root, PY, "from launch import LaunchDescription\n",
         "from ament_index_python.packages import get_package_share_directory\n"
         "from launch import LaunchDescription\n")
    edit(root, PY, "    params = PathJoinSubstitution(\n",
         "    share = get_package_share_directory('base_pkg')\n"
         "    params = PathJoinSubstitution(\n")
    edit(root, PY, "FindPackageShare('base_pkg'), 'config'", "share, 'config'")
    edit(root, PY, "from launch_ros.substitutions import FindPackageShare\n", "")


@case("LCH005", PY, "Node(")
def node_without_executable(root: Path) -> None:
    edit(root, PY, "            executable='talker',\n", "")


@case("DAT012", PY, "'robot.launch.py'")
def include_of_own_launch_file_that_does_not_exist(root: Path) -> None:
    edit(root, PY, "    return LaunchDescription([\n", """\
    robot = PathJoinSubstitution([FindPackageShare('base_pkg'), 'launch', 'robot.launch.py'])
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource(robot)),
""")
    edit(root, PY, "from launch import LaunchDescription\n",
         "from launch import LaunchDescription\nfrom launch.actions import "
         "IncludeLaunchDescription\nfrom launch.launch_description_sources import "
         "PythonLaunchDescriptionSource\n")


@case("LCH005", PY, "parameters=params")
def parameters_not_a_list(root: Path) -> None:
    listener = "\n        ),\n        Node(\n            package='base_pkg',\n" \
        "            executable='listener'"
    edit(root, PY, "parameters=[params]," + listener, "parameters=params," + listener)


@case("LCH006", PY, "def generate_launch_description")
def launch_description_not_returned(root: Path) -> None:
    edit(root, PY, "    return LaunchDescription([", "    LaunchDescription([")


@case("LCH005", PY, "remappings=('chatter', 'talk')")
def remapping_pair_not_in_list(root: Path) -> None:
    edit(root, PY, "            name='talker',\n",
         "            name='talker',\n            remappings=('chatter', 'talk'),\n")


@case("LCH005", PY, "remappings=[('chatter')]")
def remapping_without_its_pair(root: Path) -> None:
    edit(root, PY, "            name='listener',\n",
         "            name='listener',\n            remappings=[('chatter')],\n")


@case("LCH007", PY, "talker = Node(")
def node_left_out_of_the_description(root: Path) -> None:
    edit(root, PY, "    return LaunchDescription([\n        Node(\n"
         "            package='base_pkg',\n            executable='talker',\n"
         "            name='talker',\n            parameters=[params],\n        ),\n",
         "    talker = Node(\n        package='base_pkg',\n        executable='talker',\n"
         "        name='talker',\n        parameters=[params],\n    )\n"
         "    return LaunchDescription([\n")


@case("LCH008", PY, "LaunchConfiguration('use_sim_tim')")
def launch_argument_read_misspelled(root: Path) -> None:
    _use_sim_time_argument(root, default="'false'", read="use_sim_tim")


def _use_sim_time_argument(root: Path, *, default: str, read: str) -> None:
    """Declare ``use_sim_time`` with the ``default`` source text; the talker reads ``read``."""
    edit(root, PY, "from launch import LaunchDescription\n", "from launch import "
         "LaunchDescription\nfrom launch.actions import DeclareLaunchArgument\n")
    edit(root, PY, "from launch.substitutions import PathJoinSubstitution",
         "from launch.substitutions import LaunchConfiguration, PathJoinSubstitution")
    edit(root, PY, "    return LaunchDescription([\n",
         "    return LaunchDescription([\n"
         f"        DeclareLaunchArgument('use_sim_time', default_value={default}),\n")
    edit(root, PY, "name='talker',\n            parameters=[params]",
         "name='talker',\n"
         f"            parameters=[params, {{'use_sim_time': LaunchConfiguration('{read}')}}]")


@case("LCH009", PY, "from launch.actions import Node")
def node_imported_from_launch_actions(root: Path) -> None:
    edit(root, PY, "from launch_ros.actions import Node\n", "")
    edit(root, PY, "from launch import LaunchDescription\n",
         "from launch import LaunchDescription\nfrom launch.actions import Node\n")


@case("LCH009", PY, "from launch.substitutions import FindPackageShare")
def find_package_share_imported_from_launch(root: Path) -> None:
    edit(root, PY, "from launch_ros.substitutions import FindPackageShare\n", "")
    edit(root, PY, "from launch.substitutions import PathJoinSubstitution",
         "from launch.substitutions import FindPackageShare, PathJoinSubstitution")


@case("LCH010", PY, "launch_arguments={'use_sim_time': 'true'}")
def include_arguments_as_dict(root: Path) -> None:
    write(root, "launch/robot.launch.py", (root / PY).read_text())
    edit(root, PY, "    return LaunchDescription([\n", """\
    robot = PathJoinSubstitution([FindPackageShare('base_pkg'), 'launch', 'robot.launch.py'])
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource(robot),
                                 launch_arguments={'use_sim_time': 'true'}),
""")
    edit(root, PY, "from launch import LaunchDescription\n",
         "from launch import LaunchDescription\nfrom launch.actions import "
         "IncludeLaunchDescription\nfrom launch.launch_description_sources import "
         "PythonLaunchDescriptionSource\n")


@case("LCH010", PY, "default_value=False")
def launch_argument_default_not_text(root: Path) -> None:
    _use_sim_time_argument(root, default="False", read="use_sim_time")


@case("LCH011", PY, "namespace=namespace + '/sensors'")
def launch_configuration_joined_with_plus(root: Path) -> None:
    edit(root, PY, "from launch import LaunchDescription\n", "from launch import "
         "LaunchDescription\nfrom launch.actions import DeclareLaunchArgument\n")
    edit(root, PY, "from launch.substitutions import PathJoinSubstitution",
         "from launch.substitutions import LaunchConfiguration, PathJoinSubstitution")
    edit(root, PY, "    return LaunchDescription([\n",
         "    namespace = LaunchConfiguration('namespace')\n"
         "    return LaunchDescription([\n"
         "        DeclareLaunchArgument('namespace', default_value='robot'),\n")
    edit(root, PY, "name='talker',\n", "name='talker',\n"
         "            namespace=namespace + '/sensors',\n")


@case("PYC032", PY, "share + 'config/params.yaml'")
def share_folder_joined_without_slash(root: Path) -> None:
    edit(root, XML, "  <exec_depend>launch</exec_depend>\n",
         "  <exec_depend>ament_index_python</exec_depend>\n  <exec_depend>launch</exec_depend>\n")
    edit(root, PY, "from launch import LaunchDescription\n",
         "from ament_index_python.packages import get_package_share_directory\n"
         "from launch import LaunchDescription\n")
    edit(root, PY, "from launch.substitutions import PathJoinSubstitution\n", "")
    edit(root, PY, "from launch_ros.substitutions import FindPackageShare\n", "")
    edit(root, PY, "    params = PathJoinSubstitution(\n"
         "        [FindPackageShare('base_pkg'), 'config', 'params.yaml'])\n",
         "    share = get_package_share_directory('base_pkg')\n"
         "    params = share + 'config/params.yaml'\n")


@case("LCH012", PY, "parameters=['config/params.yaml']")
def parameter_file_relative_to_the_source_folder(root: Path) -> None:
    edit(root, PY, "parameters=[params],", "parameters=['config/params.yaml'],")


@case("LCH006", PY, "return [")
def launch_function_returns_the_list(root: Path) -> None:
    edit(root, PY, "    return LaunchDescription([\n", "    return [\n")
    edit(root, PY, "    ])\n", "    ]\n")
    edit(root, PY, "from launch import LaunchDescription\n", "")


@case("LCH012", XML_LAUNCH, "<param from=\"config/params.yaml\"/>")
def xml_parameter_file_relative_to_the_source_folder(root: Path) -> None:
    _other_launch(root, XML_LAUNCH, """
        <launch>
          <node pkg="base_pkg" exec="talker" name="talker">
            <param from="config/params.yaml"/>
          </node>
        </launch>
        """)


@case("LCH012", YAML_LAUNCH, "from: config/params.yaml")
def yaml_parameter_file_relative_to_the_source_folder(root: Path) -> None:
    _other_launch(root, YAML_LAUNCH, """
        launch:
        - node:
            pkg: base_pkg
            exec: talker
            name: talker
            param:
            - from: config/params.yaml
        """)


@case("LCH005", XML_LAUNCH, "namespace=\"my robot\"")
def xml_launch_namespace_with_a_space(root: Path) -> None:
    _other_launch(root, XML_LAUNCH, """
        <launch>
          <node pkg="base_pkg" exec="talker" name="talker" namespace="my robot"/>
        </launch>
        """)


@case("DAT009", "config/params.yaml", "talker:")
def namespace_added_to_node_only(root: Path) -> None:
    edit(root, PY, "name='talker',", "name='talker',\n            namespace='robot1',")


@case("LCH015", XML_LAUNCH, "$(find base_pkg)")
def ros1_find_substitution(root: Path) -> None:
    _other_launch(root, XML_LAUNCH, """
<launch>
  <node pkg="base_pkg" exec="talker" name="talker">
    <param from="$(find base_pkg)/config/params.yaml"/>
  </node>
</launch>
""")
