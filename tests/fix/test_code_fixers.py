"""The PYC001, PYC016, PYC025, PYC031, PYC032, PYC046, PYC058, LCH005, LCH010, SET006 and
ENT002 fixers: exactly the fix is written (comments and layout stay), a second run changes
nothing, a refusal writes nothing."""

from __future__ import annotations

from pathlib import Path

from tests.fix.test_new_fixers import _fix, _fixed_once, _package, _read

NODE = "pkg/node.py"
LAUNCH = "launch/pkg.launch.py"
HEAD = """import rclpy
from ament_index_python.packages import get_package_share_directory
from geometry_msgs.msg import Twist
from rclpy.node import Node


class Mover(Node):
    def __init__(self):
        super().__init__('mover')
        self.declare_parameter('period', 0.5)
        self.declare_parameter('limit', 3)
"""
LAUNCH_HEAD = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
"""


def _with(tmp_path: Path, path: str, text: str) -> Path:
    root = _package(tmp_path)
    (root / path).write_text(text)
    return root


def test_misspelt_logger_method_is_renamed_and_unknown_ones_stay(tmp_path: Path) -> None:
    body = HEAD + ("        self.get_logger().err( 'a' )  # keep\n"
                   "        self.get_logger().warnning('b')\n"
                   "        self.get_logger().exception('c')\n")
    root = _with(tmp_path, NODE, body)
    assert _fixed_once(root, "PYC016", NODE, allow_left=True) == body.replace(
        ".err(", ".error(").replace(".warnning(", ".warning(")


def test_int_for_a_float_field_becomes_a_float(tmp_path: Path) -> None:
    body = HEAD + ("        cmd = Twist()\n"
                   "        turns = 3\n"
                   "        cmd.linear.x = 1_000  # metres\n"
                   "        cmd.linear.y = - 2\n"
                   "        cmd.angular.z = turns\n"
                   "        cmd.linear.z = 0x1\n")
    root = _with(tmp_path, NODE, body)
    after = _fixed_once(root, "PYC025", NODE, allow_left=True)
    assert after == body.replace("1_000 ", "1_000.0 ").replace("- 2\n", "- 2.0\n").replace(
        "= turns\n", "= float(turns)\n")


def test_time_given_to_a_stamp_is_converted(tmp_path: Path) -> None:
    body = HEAD.replace("Twist", "TwistStamped") + (
        "        cmd = TwistStamped()\n"
        "        cmd.header.stamp = self.get_clock().now()\n")
    root = _with(tmp_path, NODE, body)
    assert _fixed_once(root, "PYC025", NODE) == body.replace("now()\n", "now().to_msg()\n")


def test_parameter_object_gets_value_and_a_comparison_only_when_unsafe(tmp_path: Path) -> None:
    body = HEAD + ("        period = self.get_parameter('period')\n"
                   "        self.timer = self.create_timer(period * 2, self.tick)\n"
                   "        self.limit = self.get_parameter('limit')\n"
                   "        self.count = 0\n"
                   "\n"
                   "    def tick(self):\n"
                   "        if self.count > self.limit:\n"
                   "            self.count = 0\n")
    root = _with(tmp_path, NODE, body)
    safe = body.replace("(period * 2", "(period.value * 2")
    result = _fix(root, "PYC031")
    assert _read(root, NODE) == safe
    assert [f.code for f in result.findings] == ["PYC031"]
    assert _fixed_once(root, "PYC031", NODE, unsafe=True) == safe.replace(
        "> self.limit:", "> self.limit.value:")


def test_missing_separator_is_inserted_in_both_quotings(tmp_path: Path) -> None:
    body = HEAD + ("        share = get_package_share_directory('pkg')\n"
                   "        self.a = share + \"config/a.yaml\"\n"
                   "        self.b = get_package_share_directory('pkg') + r'b.yaml'\n"
                   "        self.c = f'{share}c/{self.a}'\n")
    root = _with(tmp_path, NODE, body)
    assert _fixed_once(root, "PYC032", NODE) == body.replace(
        '"config', '"/config').replace("r'b", "r'/b").replace("}c/", "}/c/")


def test_launch_keywords_are_renamed_unless_the_new_one_is_there(tmp_path: Path) -> None:
    body = LAUNCH_HEAD + (
        "    return LaunchDescription([\n"
        "        Node(package='pkg', node_executable='talker',  # the talker\n"
        "             node_namespace='robot'),\n"
        "        Node(package='pkg', executable='talker', name='a', node_name='b'),\n"
        "        Node(package='pkg', executable='talker', parameters='p.yaml'),\n"
        "    ])\n")
    root = _with(tmp_path, LAUNCH, body)
    after = _fixed_once(root, "LCH005", LAUNCH, allow_left=True)
    assert after == body.replace("node_executable=", "executable=").replace(
        "node_namespace=", "namespace=").replace("='p.yaml'", "=['p.yaml']")


def test_xml_node_attributes_get_their_ros2_names(tmp_path: Path) -> None:
    text = ('<launch>\n  <!-- the talker -->\n'
            '  <node pkg="pkg" type="talker"\n        ns="r1" output="screen"/>\n</launch>\n')
    root = _with(tmp_path, "launch/pkg.launch.xml", text)
    assert _fixed_once(root, "LCH005", "launch/pkg.launch.xml") == text.replace(
        'type="', 'exec="').replace('ns="', 'namespace="')


def test_launch_actions_get_the_arguments_they_take(tmp_path: Path) -> None:
    body = LAUNCH_HEAD + (
        "    other = None\n"
        "    return LaunchDescription([\n"
        "        DeclareLaunchArgument('sim', default_value=True),\n"
        "        DeclareLaunchArgument('robot', \"bot\"),\n"
        "        DeclareLaunchArgument('world', desc='w'),\n"
        "        IncludeLaunchDescription(other, launch_arguments={'a': 'b'}),\n"
        "    ])\n")
    root = _with(tmp_path, LAUNCH, body)
    assert _fixed_once(root, "LCH010", LAUNCH) == body.replace(
        "default_value=True", "default_value='true'").replace(
        "'robot', \"bot\"", "'robot', default_value=\"bot\"").replace(
        "desc=", "description=").replace("{'a': 'b'}", "{'a': 'b'}.items()")


def test_setup_maintainer_follows_package_xml(tmp_path: Path) -> None:
    root = _package(tmp_path, setup_dot_py=("maintainer='Dev',", "maintainer='root',  # me"))
    before = _read(root, "setup.py")
    assert _fixed_once(root, "SET006", "setup.py") == before.replace("'root'", "'Dev'")


def test_setup_maintainer_with_two_candidates_is_refused(tmp_path: Path) -> None:
    root = _package(tmp_path, setup_dot_py=("maintainer='Dev',", "maintainer='root',"),
                    package_dot_xml=("</maintainer>\n", "</maintainer>\n  <maintainer "
                                     "email=\"b@example.com\">B</maintainer>\n"))
    before = _read(root, "setup.py")
    result = _fix(root, "SET006")
    assert _read(root, "setup.py") == before
    assert any("SET006: package.xml has 2 maintainers" in note for note in result.notes), \
        result.notes


def test_standard_module_used_by_name_gets_its_import(tmp_path: Path) -> None:
    body = HEAD + ("        self.length = math.hypot(3.0, 4.0)  # metres\n"
                   "        self.home = os.path.join('a', 'b')\n")
    root = _with(tmp_path, NODE, body)
    assert _fixed_once(root, "PYC001", NODE) == body.replace(
        "import rclpy\n", "import math\nimport os\n\nimport rclpy\n")


def test_standard_module_name_bound_or_used_otherwise_is_left(tmp_path: Path) -> None:
    body = HEAD + ("        self.a = time.monotonic()\n"
                   "        self.b = json\n"
                   "        self.c = sys.no_such_function()\n"
                   "\n"
                   "    def wait(self, time):\n"
                   "        return time\n")
    root = _with(tmp_path, NODE, body)
    result = _fix(root, "PYC001")
    assert _read(root, NODE) == body
    assert sorted(f.message for f in result.findings) == [
        "Undefined name `json`", "Undefined name `sys`", "Undefined name `time`"]


def test_console_script_gets_its_package_prefix(tmp_path: Path) -> None:
    script = ("'talker = pkg.talker:main',", "'talker=talker:main',  # the node")
    root = _package(tmp_path, setup_dot_py=script)
    before = _read(root, "setup.py")
    assert _fixed_once(root, "ENT002", "setup.py") == before.replace(
        "'talker=talker:main'", "'talker=pkg.talker:main'")


def test_method_used_without_a_call_is_called_and_a_test_only_when_unsafe(
        tmp_path: Path) -> None:
    body = HEAD + ("        self.create_timer(1.0, self.tick)\n"
                   "\n"
                   "    def tick(self):\n"
                   "        stamp = self.get_clock().now.nanoseconds  # keep\n"
                   "        while rclpy.ok:\n"
                   "            break\n"
                   "        self.get_logger().info(str(stamp))\n")
    root = _with(tmp_path, NODE, body)
    safe = body.replace("now.nanoseconds", "now().nanoseconds")
    result = _fix(root, "PYC046")
    assert _read(root, NODE) == safe
    assert [f.code for f in result.findings] == ["PYC046"]
    assert _fixed_once(root, "PYC046", NODE, unsafe=True) == safe.replace(
        "rclpy.ok:", "rclpy.ok():")


def test_string_with_fields_gets_its_f_prefix_unless_joined(tmp_path: Path) -> None:
    body = HEAD + ("        self.create_timer(1.0, self.tick)\n"
                   "\n"
                   "    def tick(self):\n"
                   "        count = 3\n"
                   "        self.get_logger().info('Count {count}')  # keep\n"
                   "        self.get_logger().info(r'Path {count}\\n')\n"
                   "        self.get_logger().info('Count ' '{count}')\n")
    root = _with(tmp_path, NODE, body)
    assert _read(root, NODE) == body and _fix(root, "PYC058").findings  # unsafe: not by default
    fixed = _fixed_once(root, "PYC058", NODE, unsafe=True, allow_left=True)
    assert fixed == body.replace("('Count {", "(f'Count {").replace("(r'Path", "(fr'Path")
