"""Seeded mistakes in node code (PYC, and SYN for code that does not parse)."""

from __future__ import annotations

from pathlib import Path

from tests.lint.seeded import add_import, case, edit, write

TALKER = "base_pkg/talker.py"
LISTENER = "base_pkg/listener.py"
SRV = "base_pkg/srv.py"


@case("SYN001", TALKER, "def publish(self)")
def missing_colon(root: Path) -> None:
    edit(root, TALKER, "def publish(self):", "def publish(self)")


@case("SYN001", TALKER, "msg.data = f'Hello {self.count}")
def unterminated_string(root: Path) -> None:
    edit(root, TALKER, "msg.data = f'Hello {self.count}'", "msg.data = f'Hello {self.count}")


@case("SYN001", TALKER, "self.publisher.publish(msg)")
def tab_indentation(root: Path) -> None:
    edit(root, TALKER, "        self.publisher.publish(msg)", "\tself.publisher.publish(msg)")


@case("PYC001", TALKER, "msg = Strng()")
def class_name_typo(root: Path) -> None:
    edit(root, TALKER, "msg = String()", "msg = Strng()")


@case("PYC001", TALKER, "cv2.imshow")
def cv2_used_without_import(root: Path) -> None:
    edit(root, TALKER, "        self.publisher.publish(msg)\n",
         "        self.publisher.publish(msg)\n        cv2.imshow('debug', None)\n")


@case("PYC001", TALKER, "rclpy.init(args=args)")
def rclpy_import_forgotten(root: Path) -> None:
    edit(root, TALKER, "import rclpy\n", "")


@case("PYC001", LISTENER, "count += 1")
def local_instead_of_attribute(root: Path) -> None:
    edit(root, LISTENER, "        self.count += 1\n        self.last_message",
         "        count += 1\n        self.last_message")


@case("PYC002", TALKER, "np.int0")
def numpy_int0(root: Path) -> None:
    edit(root, TALKER, "import rclpy\n", "import numpy as np\nimport rclpy\n")
    edit(root, TALKER, "        msg = String()\n",
         "        corners = np.int0([1.5, 2.5])\n        msg = String()\n        msg.data = "
         "str(corners)\n")
    edit(root, "package.xml", "  <exec_depend>launch</exec_depend>\n",
         "  <exec_depend>python3-numpy</exec_depend>\n  <exec_depend>launch</exec_depend>\n")


@case("PYC003", TALKER, "node.destroy_node()")
def node_in_finally_after_failed_construction(root: Path) -> None:
    edit(root, TALKER, "    node = None\n", "")
    edit(root, TALKER, "        if node is not None:\n            node.destroy_node()",
         "        node.destroy_node()")


@case("PYC004", SRV, "ActionClient.GoalStatus")
def goal_status_on_action_client(root: Path) -> None:
    edit(root, SRV, "from rclpy.node import Node\n",
         "from rclpy.action import ActionClient\nfrom rclpy.node import Node\n")
    edit(root, SRV, "        response.success = True\n",
         "        response.success = self.calls != ActionClient.GoalStatus.STATUS_ABORTED\n")


@case("PYC005", SRV, "spin_until_future_complete")
def wait_without_timeout(root: Path) -> None:
    edit(root, SRV, "        executor.spin()\n",
         "        client = node.create_client(Trigger, 'home')\n"
         "        future = client.call_async(Trigger.Request())\n"
         "        rclpy.spin_until_future_complete(node, future)\n        executor.spin()\n")


@case("SYN001", TALKER, "print 'publishing'")
def python2_print(root: Path) -> None:
    edit(root, TALKER, "        self.publisher.publish(msg)\n",
         "        print 'publishing'\n        self.publisher.publish(msg)\n")


@case("PYC001", TALKER, "self.create_timer(period, publish)")
def method_without_self(root: Path) -> None:
    edit(root, TALKER, "self.create_timer(period, self.publish)",
         "self.create_timer(period, publish)")


@case("PYC004", TALKER, "from rclpy.Node import Node")
def rclpy_node_module_capitalised(root: Path) -> None:
    edit(root, TALKER, "from rclpy.node import Node", "from rclpy.Node import Node")


@case("PYC004", TALKER, "from rclpy.nodes import Node")
def rclpy_node_module_plural(root: Path) -> None:
    edit(root, TALKER, "from rclpy.node import Node", "from rclpy.nodes import Node")


@case("PYC004", LISTENER, "SingleThreadExecutor")
def executor_class_misspelt(root: Path) -> None:
    edit(root, LISTENER, "ExternalShutdownException, SingleThreadedExecutor\n",
         "ExternalShutdownException, SingleThreadExecutor\n")
    edit(root, LISTENER, "executor = SingleThreadedExecutor()",
         "executor = SingleThreadExecutor()")


@case("PYC032", TALKER, "+ 'config/params.yaml'")
def node_reads_share_file_joined_without_slash(root: Path) -> None:
    edit(root, "package.xml", "  <exec_depend>launch</exec_depend>\n",
         "  <exec_depend>ament_index_python</exec_depend>\n  <exec_depend>launch</exec_depend>\n")
    add_import(root, TALKER,
               "from ament_index_python.packages import get_package_share_directory")
    edit(root, TALKER, "        self.count = 0\n",
         "        self.count = 0\n        self.config = "
         "get_package_share_directory('base_pkg') + 'config/params.yaml'\n")


@case("PYC016", LISTENER, "self.get_logger().exception(")
def python_logging_method_on_rclpy_logger(root: Path) -> None:
    edit(root, LISTENER, "self.get_logger().info(f'Received message {self.count}: {msg}')",
         "self.get_logger().exception(f'Received message {self.count}: {msg}')")


@case("PYC014", TALKER, "topic = self.get_parameter('topic').value")
def parameter_read_before_declared(root: Path) -> None:
    edit(root, TALKER, "        self.declare_parameter('topic', 'chatter')\n", "")
    edit(root, TALKER, "        topic = self.get_parameter('topic').value\n",
         "        topic = self.get_parameter('topic').value\n"
         "        self.declare_parameter('topic', 'chatter')\n")


@case("PYC006", SRV, "self.history")
def missing_comma_in_list(root: Path) -> None:
    edit(root, SRV, "        self.calls = 0\n",
         "        self.calls = 0\n        self.history = [('start', 0) ('ready', 1)]\n")


@case("PYC007", LISTENER, "String, topic, self.on_message)")
def subscription_without_qos(root: Path) -> None:
    edit(root, LISTENER, "String, topic, self.on_message, 10)", "String, topic, self.on_message)")


@case("PYC007", TALKER, "self.create_publisher(String, topic)")
def publisher_without_qos(root: Path) -> None:
    edit(root, TALKER, "self.create_publisher(String, topic, 10)",
         "self.create_publisher(String, topic)")


@case("PYC008", TALKER, "super().__init__('talker-node'")
def node_name_with_dash(root: Path) -> None:
    edit(root, TALKER, "super().__init__('talker'", "super().__init__('talker-node'")


@case("PYC008", TALKER, "'chatter topic'")
def topic_name_with_space(root: Path) -> None:
    edit(root, TALKER, "self.declare_parameter('topic', 'chatter')",
         "self.declare_parameter('topic', 'chatter')\n        self.status = self.create_publisher("
         "String, 'chatter topic', 10)")


@case("PYC009", TALKER, "super().__init__()")
def node_name_left_out(root: Path) -> None:
    edit(root, TALKER, "super().__init__('talker', **kwargs)", "super().__init__()")


@case("DEP007", TALKER, "from helpers import clamp")
def sibling_module_imported_top_level(root: Path) -> None:
    write(root, "base_pkg/helpers.py", """
        def clamp(value, low, high):
            return max(low, min(high, value))
        """)
    edit(root, TALKER, "import rclpy\n", "from helpers import clamp\nimport rclpy\n")
    edit(root, TALKER, "        self.count = 0\n", "        self.count = clamp(0, 0, 1)\n")


@case("DEP004", TALKER, "import rospy")
def ros1_import(root: Path) -> None:
    edit(root, TALKER, "import rclpy\n", "import rclpy\nimport rospy\n")
    edit(root, TALKER, "        self.count = 0\n",
         "        self.count = 0\n        self.rate = rospy.Rate(2)\n")


@case("PYC013", TALKER, "self.create_timer(period, self.publish())")
def timer_callback_called(root: Path) -> None:
    edit(root, TALKER, "self.create_timer(period, self.publish)",
         "self.create_timer(period, self.publish())")


@case("PYC013", LISTENER, "self.on_message(), 10)")
def subscription_callback_called(root: Path) -> None:
    edit(root, LISTENER, "self.on_message, 10)", "self.on_message(), 10)")


@case("PYC014", TALKER, "get_parameter('perod')")
def undeclared_parameter_read(root: Path) -> None:
    edit(root, TALKER, "self.get_parameter('period')", "self.get_parameter('perod')")


@case("PYC015", LISTENER)
def rclpy_init_forgotten(root: Path) -> None:
    edit(root, LISTENER, "    rclpy.init(args=args)\n", "")


@case("PYC016", LISTENER, "get_logger().info(")
def logger_called_like_print(root: Path) -> None:
    edit(root, LISTENER, "info(f'Received message {self.count}: {msg}')",
         "info('Received message', self.count, msg)")


@case("PYC017", TALKER, "rclpy.spin()")
def spin_without_node(root: Path) -> None:
    edit(root, TALKER, "        executor.add_node(node)\n        executor.spin()\n",
         "        rclpy.spin()\n")


@case("PYC017", LISTENER, "executor.add_node(node)")
def node_class_not_instantiated(root: Path) -> None:
    edit(root, LISTENER, "node = Listener()", "node = Listener")


@case("PYC018", TALKER, "self.create_publisher(String, topic, '10')")
def qos_depth_as_string(root: Path) -> None:
    edit(root, TALKER, "self.create_publisher(String, topic, 10)",
         "self.create_publisher(String, topic, '10')")


@case("PYC018", LISTENER, "String, topic, self.on_message, 10.0)")
def qos_depth_as_float(root: Path) -> None:
    edit(root, LISTENER, "String, topic, self.on_message, 10)",
         "String, topic, self.on_message, 10.0)")


@case("PYC018", SRV, "qos_profile=10)")
def service_qos_as_depth(root: Path) -> None:
    edit(root, SRV, "self.create_service(Trigger, name, self.on_request)",
         "self.create_service(Trigger, name, self.on_request, qos_profile=10)")


@case("PYC019", TALKER, "msg.dat = f'Hello")
def message_field_misspelled(root: Path) -> None:
    edit(root, TALKER, "msg.data = f'Hello {self.count}'", "msg.dat = f'Hello {self.count}'")


@case("PYC019", TALKER, "msg = String(text=")
def message_constructor_keyword_misspelled(root: Path) -> None:
    edit(root, TALKER, "msg = String()\n        msg.data = f'Hello {self.count}'",
         "msg = String(text=f'Hello {self.count}')")


@case("PYC019", TALKER, "cmd.linear.xx = 0.5")
def nested_message_field_misspelled(root: Path) -> None:
    edit(root, TALKER, "from std_msgs.msg import String\n",
         "from geometry_msgs.msg import Twist\nfrom std_msgs.msg import String\n")
    edit(root, TALKER, "        self.publisher.publish(msg)\n",
         "        self.publisher.publish(msg)\n        cmd = Twist()\n"
         "        cmd.linear.xx = 0.5\n        self.get_logger().info(str(cmd))\n")
    edit(root, "package.xml", "  <exec_depend>launch</exec_depend>\n",
         "  <exec_depend>geometry_msgs</exec_depend>\n  <exec_depend>launch</exec_depend>\n")


@case("PYC019", TALKER, "msg = String(f'Hello")
def message_constructor_positional(root: Path) -> None:
    edit(root, TALKER, "msg = String()\n        msg.data = f'Hello {self.count}'",
         "msg = String(f'Hello {self.count}')")


@case("PYC019", LISTENER, "msg.dat")
def received_message_field_misspelled(root: Path) -> None:
    edit(root, LISTENER, "self.last_message = msg\n", "self.last_message = msg.dat\n")


@case("PYC019", SRV, "response.sucess = True")
def service_response_field_misspelled(root: Path) -> None:
    edit(root, SRV, "response.success = True", "response.sucess = True")


@case("PYC020", TALKER, "self.publisher.publish(f'Hello")
def publish_a_string(root: Path) -> None:
    edit(root, TALKER, "self.publisher.publish(msg)",
         "self.publisher.publish(f'Hello {self.count}')")


@case("PYC020", TALKER, "self.publisher.publish(msg.data)")
def publish_the_data_field(root: Path) -> None:
    edit(root, TALKER, "self.publisher.publish(msg)", "self.publisher.publish(msg.data)")


@case("PYC021", LISTENER, "Int32, topic")
def subscription_type_changed_on_one_side(root: Path) -> None:
    edit(root, LISTENER, "from std_msgs.msg import String", "from std_msgs.msg import Int32")
    edit(root, LISTENER, "String, topic", "Int32, topic")


@case("PYC022", LISTENER, "String, topic, self.on_message, 10)")
def best_effort_publisher_reliable_subscription(root: Path) -> None:
    edit(root, TALKER, "from rclpy.node import Node\n",
         "from rclpy.node import Node\nfrom rclpy.qos import qos_profile_sensor_data\n")
    edit(root, TALKER, "(String, topic, 10)", "(String, topic, qos_profile_sensor_data)")


@case("PYC023", LISTENER, "self.on_mesage")
def subscription_callback_misspelled(root: Path) -> None:
    edit(root, LISTENER, "self.on_message, 10", "self.on_mesage, 10")


@case("PYC023", TALKER, "self.publisher_.publish(msg)")
def publisher_attribute_renamed_in_one_place(root: Path) -> None:
    edit(root, TALKER, "self.publisher.publish(msg)", "self.publisher_.publish(msg)")


@case("PYC024", LISTENER, "String, topic, self.on_message, 10)")
def subscription_callback_without_message_parameter(root: Path) -> None:
    edit(root, LISTENER, "def on_message(self, msg):", "def on_message(self):")
    edit(root, LISTENER, "self.last_message = msg\n", "self.last_message = None\n")
    edit(root, LISTENER, "Received message {self.count}: {msg}", "Received message {self.count}")


@case("PYC024", SRV, "self.create_service(Trigger, name, self.on_request)")
def service_callback_without_response_parameter(root: Path) -> None:
    edit(root, SRV, "def on_request(self, request, response):", "def on_request(self, request):")
    edit(root, SRV, "        self.calls += 1\n",
         "        response = Trigger.Response()\n        self.calls += 1\n")


@case("PYC025", TALKER, "msg.data = 42")
def number_for_a_string_field(root: Path) -> None:
    edit(root, TALKER, "msg.data = f'Hello {self.count}'", "msg.data = 42")


@case("PYC025", TALKER, "cmd.linear.x = 1")
def int_for_a_float_field(root: Path) -> None:
    edit(root, TALKER, "from std_msgs.msg import String\n",
         "from geometry_msgs.msg import Twist\nfrom std_msgs.msg import String\n")
    edit(root, TALKER, "        self.publisher.publish(msg)\n",
         "        self.publisher.publish(msg)\n        cmd = Twist()\n"
         "        cmd.linear.x = 1\n        self.get_logger().info(str(cmd))\n")
    edit(root, "package.xml", "  <depend>rclpy</depend>\n",
         "  <depend>geometry_msgs</depend>\n  <depend>rclpy</depend>\n")


@case("PYC019", SRV, "Trigger.response()")
def service_companion_class_lowercase(root: Path) -> None:
    edit(root, SRV, "    def on_request(self, request, response):",
         "    def make_response(self):\n        \"\"\"Return an empty response.\"\"\"\n"
         "        return Trigger.response()\n\n    def on_request(self, request, response):")


@case("PYC026", SRV, "def on_request(self, request, response):")
def service_response_not_returned(root: Path) -> None:
    edit(root, SRV, "        return response\n", "")


@case("PYC026", SRV, "return response.message")
def service_field_returned(root: Path) -> None:
    edit(root, SRV, "        return response\n", "        return response.message\n")


@case("PYC027", TALKER, "self.declare_parameter('topic', 'chat')")
def parameter_declaration_copied(root: Path) -> None:
    edit(root, TALKER, "        self.declare_parameter('period', 0.5)\n",
         "        self.declare_parameter('period', 0.5)\n"
         "        self.declare_parameter('topic', 'chat')\n")


@case("PYC028", TALKER, "get_parameter_value().integer_value")
def parameter_read_through_another_type(root: Path) -> None:
    edit(root, TALKER, "period = self.get_parameter('period').value",
         "period = self.get_parameter('period').get_parameter_value().integer_value")


@case("PYC029", TALKER, "default_value=0.5")
def parameter_default_by_wrong_keyword(root: Path) -> None:
    edit(root, TALKER, "self.declare_parameter('period', 0.5)",
         "self.declare_parameter('period', default_value=0.5)")


@case("PYC029", TALKER, "super().__init__(name='talker'")
def node_name_by_wrong_keyword(root: Path) -> None:
    edit(root, TALKER, "super().__init__('talker'", "super().__init__(name='talker'")


@case("PYC029", SRV, "wait_for_service(timeout=2.0)")
def wait_for_service_timeout_keyword(root: Path) -> None:
    edit(root, SRV, "        self.service = self.create_service(Trigger, name, self.on_request)\n",
         "        self.service = self.create_service(Trigger, name, self.on_request)\n"
         "        self.client = self.create_client(Trigger, name)\n"
         "        if not self.client.wait_for_service(timeout=2.0):\n"
         "            self.get_logger().warning('The service is not up yet')\n")


@case("PYC018", LISTENER, "QoSProfile(reliability=ReliabilityPolicy.BEST_EFFORT)")
def qos_profile_without_depth(root: Path) -> None:
    edit(root, LISTENER, "from rclpy.node import Node\n",
         "from rclpy.node import Node\nfrom rclpy.qos import QoSProfile, ReliabilityPolicy\n")
    edit(root, LISTENER, "String, topic, self.on_message, 10)",
         "String, topic, self.on_message,\n"
         "            QoSProfile(reliability=ReliabilityPolicy.BEST_EFFORT))")


@case("PYC025", TALKER, "header.stamp = self.get_clock().now()")
def stamp_without_to_msg(root: Path) -> None:
    edit(root, TALKER, "from std_msgs.msg import String",
         "from std_msgs.msg import Header, String")
    edit(root, TALKER, "        self.publisher.publish(msg)\n",
         "        self.publisher.publish(msg)\n        header = Header()\n"
         "        header.stamp = self.get_clock().now()\n"
         "        self.get_logger().debug(f'Stamped {header.stamp}')\n")


@case("PYC028", TALKER, "get_parameter('topic').value()")
def parameter_value_called(root: Path) -> None:
    edit(root, TALKER, "topic = self.get_parameter('topic').value",
         "topic = self.get_parameter('topic').value()")


@case("PYC028", TALKER, "get_parameter_value().str_value")
def parameter_value_field_misspelled(root: Path) -> None:
    edit(root, TALKER, "topic = self.get_parameter('topic').value",
         "topic = self.get_parameter('topic').get_parameter_value().str_value")


@case("PYC030", LISTENER, "'chatter', String, self.on_message, 10)")
def subscription_in_ros1_order(root: Path) -> None:
    edit(root, LISTENER, "String, topic, self.on_message, 10)",
         "'chatter', String, self.on_message, 10)")


@case("PYC030", TALKER, "self.create_timer(self.publish, period)")
def timer_arguments_swapped(root: Path) -> None:
    edit(root, TALKER, "self.create_timer(period, self.publish)",
         "self.create_timer(self.publish, period)")


@case("PYC031", TALKER, "self.create_timer(period, self.publish)")
def parameter_object_as_timer_period(root: Path) -> None:
    edit(root, TALKER, "period = self.get_parameter('period').value",
         "period = self.get_parameter('period')")


@case("PYC025", TALKER, "msg.data = self.count")
def counter_published_in_a_string_field(root: Path) -> None:
    edit(root, TALKER, "msg.data = f'Hello {self.count}'", "msg.data = self.count")


@case("DEP010", "test/test_talker.py", "from base_pkg.talker import TalkerNode")
def test_imports_a_renamed_class(root: Path) -> None:
    edit(root, "test/test_talker.py", "from base_pkg.talker import Talker",
         "from base_pkg.talker import TalkerNode")


@case("PYC033", LISTENER, "String, topic, self.on_message, 10, None)")
def subscription_callback_group_by_position(root: Path) -> None:
    edit(root, LISTENER, "String, topic, self.on_message, 10)",
         "String, topic, self.on_message, 10, None)")


@case("PYC034", SRV, "rclpy.spin_until_future_complete(self, upstream")
def node_spun_in_its_own_service_callback(root: Path) -> None:
    edit(root, SRV, "        self.service = self.create_service(Trigger, name, self.on_request)\n",
         "        self.service = self.create_service(Trigger, name, self.on_request)\n"
         "        self.client = self.create_client(Trigger, 'upstream')\n")
    edit(root, SRV, "        self.calls += 1\n",
         "        self.calls += 1\n"
         "        upstream = self.client.call_async(Trigger.Request())\n"
         "        rclpy.spin_until_future_complete(self, upstream, timeout_sec=1.0)\n")


@case("PYC036", SRV, "future.result()")
def response_read_before_it_arrives(root: Path) -> None:
    edit(root, SRV, "        self.service = self.create_service(Trigger, name, self.on_request)\n",
         "        self.service = self.create_service(Trigger, name, self.on_request)\n"
         "        self.client = self.create_client(Trigger, 'upstream')\n"
         "        future = self.client.call_async(Trigger.Request())\n"
         "        self.get_logger().info(future.result().message)\n")


@case("PYC031", TALKER, "self.create_publisher(String, topic, 10)")
def parameter_object_text_as_topic(root: Path) -> None:
    edit(root, TALKER, "topic = self.get_parameter('topic').value",
         "topic = str(self.get_parameter('topic'))")


@case("PYC025", TALKER, "msg.data = len(self.publisher.topic_name)")
def length_for_a_string_field(root: Path) -> None:
    edit(root, TALKER, "msg.data = f'Hello {self.count}'",
         "msg.data = len(self.publisher.topic_name)")


@case("PYC017", TALKER, "ActionClient(Talker, Fibonacci, 'fibonacci')")
def node_class_given_to_an_action_client(root: Path) -> None:
    add_import(root, TALKER, "from example_interfaces.action import Fibonacci")
    add_import(root, TALKER, "from rclpy.action import ActionClient")
    edit(root, TALKER, "        self.count = 0\n",
         "        self.count = 0\n"
         "        self.fibonacci = ActionClient(Talker, Fibonacci, 'fibonacci')\n")
    edit(root, "package.xml", "  <depend>rclpy</depend>\n",
         "  <depend>example_interfaces</depend>\n  <depend>rclpy</depend>\n")


@case("PYC009", TALKER, "node = Talker()")
def node_name_left_to_a_caller_that_gives_none(root: Path) -> None:
    edit(root, TALKER, "super().__init__('talker', **kwargs)", "super().__init__(**kwargs)")


@case("PYC034", TALKER, "rate.sleep()")
def rate_loop_in_the_constructor(root: Path) -> None:
    edit(root, TALKER, "        self.timer = self.create_timer(period, self.publish)\n",
         "        rate = self.create_rate(1.0 / period)\n        while rclpy.ok():\n"
         "            self.publish()\n            rate.sleep()\n")


@case("PYC033", TALKER, "self.get_parameter('period', 0.5)")
def parameter_default_given_to_get_parameter(root: Path) -> None:
    edit(root, TALKER, "period = self.get_parameter('period').value",
         "period = self.get_parameter('period', 0.5).value")


@case("PYC026", SRV, "self.get_logger().info(f'Answered request {self.calls}')")
def response_returned_only_on_an_early_path(root: Path) -> None:
    edit(root, SRV, "        return response\n", "")
    edit(root, SRV, "        response.success = True\n",
         "        if self.calls > 100:\n            response.success = False\n"
         "            return response\n        response.success = True\n")


@case("PYC034", TALKER, "self.client.call(Trigger.Request())")
def service_called_synchronously_in_a_timer_callback(root: Path) -> None:
    add_import(root, TALKER, "from std_srvs.srv import Trigger")
    edit(root, TALKER, "        self.count = 0\n",
         "        self.count = 0\n        self.client = self.create_client(Trigger, 'trigger')\n")
    edit(root, TALKER, "        msg = String()\n",
         "        self.client.call(Trigger.Request())\n        msg = String()\n")


@case("PYC035", SRV, "self.create_service(Trigger.Request")
def service_created_with_its_request_type(root: Path) -> None:
    edit(root, SRV, "self.create_service(Trigger,", "self.create_service(Trigger.Request,")


@case("PYC020", TALKER, "self.client.call_async(Trigger.Request)")
def request_class_sent_instead_of_a_request(root: Path) -> None:
    add_import(root, TALKER, "from std_srvs.srv import Trigger")
    edit(root, TALKER, "        self.count = 0\n",
         "        self.count = 0\n        self.client = self.create_client(Trigger, 'trigger')\n")
    edit(root, TALKER, "        msg = String()\n",
         "        self.client.call_async(Trigger.Request)\n        msg = String()\n")


@case("PYC018", TALKER, "reliability='reliable'")
def qos_reliability_as_a_string(root: Path) -> None:
    add_import(root, TALKER, "from rclpy.qos import QoSProfile")
    edit(root, TALKER, "create_publisher(String, topic, 10)",
         "create_publisher(String, topic, QoSProfile(depth=10, reliability='reliable'))")


@case("PYC033", TALKER, "rclpy.spin_once(node, 0.1)")
def spin_once_timeout_by_position(root: Path) -> None:
    edit(root, TALKER, "        executor.add_node(node)\n        executor.spin()\n",
         "        while rclpy.ok():\n            rclpy.spin_once(node, 0.1)\n")


@case("PYC004", SRV, "goal_handle.succeeded()")
def goal_handle_method_misspelt(root: Path) -> None:
    add_import(root, SRV, "from example_interfaces.action import Fibonacci")
    add_import(root, SRV, "from rclpy.action import ActionServer")
    edit(root, SRV, "        self.calls = 0\n",
         "        self.calls = 0\n"
         "        self.fibonacci = ActionServer(self, Fibonacci, 'fibonacci', self.execute)\n")
    edit(root, SRV, "    def on_request(self, request, response):\n",
         "    def execute(self, goal_handle):\n        \"\"\"Finish the goal at once.\"\"\"\n"
         "        goal_handle.succeeded()\n        return Fibonacci.Result()\n\n"
         "    def on_request(self, request, response):\n")
    edit(root, "package.xml", "  <depend>rclpy</depend>\n",
         "  <depend>example_interfaces</depend>\n  <depend>rclpy</depend>\n")


@case("PYC020", TALKER, "self.publisher.publish(String, msg)")
def message_class_published_beside_the_message(root: Path) -> None:
    edit(root, TALKER, "self.publisher.publish(msg)", "self.publisher.publish(String, msg)")


@case("PYC040", "my_robot_pkg/joint_state_logger.py", "return f'{value:.4f}'",
      base="my_robot_pkg")
def placeholder_text_formatted_as_a_number(root: Path) -> None:
    edit(root, "my_robot_pkg/joint_state_logger.py",
         "    return f'{values[index]:.4f}' if index < len(values) else MISSING\n",
         "    value = values[index] if index < len(values) else MISSING\n"
         "    return f'{value:.4f}'\n")


@case("PYC041", TALKER, "def __init__(self")
def node_constructor_never_called(root: Path) -> None:
    edit(root, TALKER, "        super().__init__('talker', **kwargs)\n", "")


@case("PYC042", TALKER, "msg.data = 'count: ' + self.count")
def number_added_to_text(root: Path) -> None:
    edit(root, TALKER, "        msg = String()\n",
         "        msg = String()\n        msg.data = 'count: ' + self.count\n")


@case("PYC043", "simple_avoidance_agent/scan_agent.py", "if msg.ranges < 0.1:",
      base="simple_avoidance_agent")
def scan_ranges_compared_with_a_distance(root: Path) -> None:
    edit(root, "simple_avoidance_agent/scan_agent.py",
         "        if not msg.ranges:\n            return\n",
         "        if not msg.ranges:\n            return\n        if msg.ranges < 0.1:\n"
         "            return\n")


@case("PYC034", TALKER, "rate.sleep()")
def rate_slept_in_a_timer_callback(root: Path) -> None:
    edit(root, TALKER, "        self.count += 1\n",
         "        self.count += 1\n        rate = self.create_rate(2)\n        rate.sleep()\n")


@case("PYC016", "base_pkg/listener.py", "self.get_logger().info(msg)")
def message_logged_as_it_is(root: Path) -> None:
    edit(root, "base_pkg/listener.py", "        self.last_message = msg\n",
         "        self.last_message = msg\n        self.get_logger().info(msg)\n")


@case("PYC030", SRV, "self.create_service(Trigger, self.on_request, name)")
def service_callback_where_the_name_goes(root: Path) -> None:
    edit(root, SRV, "self.create_service(Trigger, name, self.on_request)",
         "self.create_service(Trigger, self.on_request, name)")


@case("PYC026", SRV, "return Trigger.Response")
def service_returns_the_response_class(root: Path) -> None:
    edit(root, SRV, "        return response\n", "        return Trigger.Response\n")


@case("PYC044", "base_pkg/listener.py", "String, topic, self.on_message, 10)")
def subscription_topic_misspelt(root: Path) -> None:
    edit(root, "base_pkg/listener.py", "self.declare_parameter('topic', 'chatter')",
         "self.declare_parameter('topic', 'chater')")
    edit(root, "config/params.yaml", "listener:\n  ros__parameters:\n    topic: chatter",
         "listener:\n  ros__parameters:\n    topic: chater")


@case("PYC045", "simple_avoidance_agent/scan_agent.py", "if twist.angular > 1.0:",
      base="simple_avoidance_agent")
def nested_message_compared_with_a_number(root: Path) -> None:
    edit(root, "simple_avoidance_agent/scan_agent.py",
         "        self.publisher_.publish(twist)\n",
         "        if twist.angular > 1.0:\n            return\n"
         "        self.publisher_.publish(twist)\n")


@case("PYC046", "joint_controller_agent/humanoid_joint_controller.py",
      "response = future.result", base="joint_controller_agent")
def future_result_taken_without_a_call(root: Path) -> None:
    edit(root, "joint_controller_agent/humanoid_joint_controller.py",
         "        response = future.result()\n", "        response = future.result\n")


@case("PYC019", "joint_controller_agent/humanoid_joint_controller.py",
      "return response.sucess", base="joint_controller_agent")
def misspelt_field_of_a_service_response(root: Path) -> None:
    edit(root, "joint_controller_agent/humanoid_joint_controller.py",
         "        return response.success\n", "        return response.sucess\n")


@case("PYC047", TALKER, "self.count =+ 1")
def counter_assigned_instead_of_incremented(root: Path) -> None:
    edit(root, TALKER, "        self.count += 1\n", "        self.count =+ 1\n")


@case("PYC028", TALKER, "self.get_parameter('period').value.double_value")
def field_taken_of_a_parameter_value(root: Path) -> None:
    edit(root, TALKER, "self.get_parameter('period').value",
         "self.get_parameter('period').value.double_value")


@case("PYC048", TALKER, "self.publish(msg)")
def own_method_called_with_an_argument_it_does_not_take(root: Path) -> None:
    edit(root, TALKER, "        self.count += 1\n",
         "        self.count += 1\n        self.publish(msg)\n")


@case("PYC049", TALKER, "self.create_timer(period)")
def timer_created_without_its_callback(root: Path) -> None:
    edit(root, TALKER, "self.create_timer(period, self.publish)", "self.create_timer(period)")


@case("PYC050", TALKER, "msg.data == f'Hello {self.count}'")
def comparison_written_for_an_assignment(root: Path) -> None:
    edit(root, TALKER, "msg.data = f'Hello {self.count}'", "msg.data == f'Hello {self.count}'")


@case("PYC033", TALKER, "rclpy.init(args)")
def init_given_its_arguments_by_position(root: Path) -> None:
    edit(root, TALKER, "rclpy.init(args=args)", "rclpy.init(args)")


@case("PYC051", TALKER, "{self.count:s}")
def count_formatted_as_text(root: Path) -> None:
    edit(root, TALKER, "msg.data = f'Hello {self.count}'", "msg.data = f'Hello {self.count:s}'")


@case("PYC052", "test/test_talker.py", "assert (")
def assert_on_a_tuple(root: Path) -> None:
    edit(root, "test/test_talker.py", "from base_pkg.talker import Talker\n",
         "from base_pkg.talker import Talker\n\n\ndef test_truth():\n"
         "    assert (Talker is None, 'never')\n")


@case("SYN006", TALKER, "def publish(self, self)")
def parameter_named_twice(root: Path) -> None:
    edit(root, TALKER, "def publish(self):", "def publish(self, self):")


@case("PYC053", "simple_avoidance_agent/scan_agent.py", "msg.ranges.size",
      base="simple_avoidance_agent")
def scan_ranges_sized_like_an_array(root: Path) -> None:
    edit(root, "simple_avoidance_agent/scan_agent.py",
         "        if not msg.ranges:\n            return\n",
         "        if msg.ranges.size == 0:\n            return\n")
