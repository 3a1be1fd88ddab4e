"""Seeded import-versus-package.xml mistakes (DEP)."""

from __future__ import annotations

from pathlib import Path

from tests.lint.seeded import add_import, case, edit, write

XML = "package.xml"
TALKER = "base_pkg/talker.py"
CAMERA = "physical_ai_camera"


def _import(root: Path, module: str, line: str, use: str) -> None:
    """Add ``line`` to the imports of ``module`` and ``use`` to its first method."""
    add_import(root, module, line)
    edit(root, module, "        self.count = 0\n", f"        self.count = 0\n        {use}\n")


@case("DEP001", TALKER, "import numpy as np")
def numpy_undeclared(root: Path) -> None:
    _import(root, TALKER, "import numpy as np", "self.history = np.zeros(10)")


@case("DEP001", TALKER, "import cv2")
def cv2_undeclared(root: Path) -> None:
    _import(root, TALKER, "import cv2", "self.window = cv2.namedWindow")


@case("DEP001", TALKER, "import yaml")
def yaml_undeclared(root: Path) -> None:
    _import(root, TALKER, "import yaml", "self.settings = yaml.safe_load('{}')")


@case("DEP001", TALKER, "from sensor_msgs.msg import Imu")
def sensor_msgs_undeclared(root: Path) -> None:
    _import(root, TALKER, "from sensor_msgs.msg import Imu",
            "self.imu = self.create_publisher(Imu, 'imu', 10)")


@case("DEP001", TALKER, "from geometry_msgs.msg import Twist")
def geometry_msgs_undeclared(root: Path) -> None:
    _import(root, TALKER, "from geometry_msgs.msg import Twist",
            "self.cmd = self.create_publisher(Twist, 'cmd_vel', 10)")


@case("DEP001", TALKER, "import tf2_ros")
def tf2_ros_undeclared(root: Path) -> None:
    _import(root, TALKER, "import tf2_ros",
            "self.broadcaster = tf2_ros.TransformBroadcaster(self)")


@case("DEP001", TALKER, "from tf_transformations import")
def tf_transformations_undeclared(root: Path) -> None:
    _import(root, TALKER, "from tf_transformations import euler_from_quaternion",
            "self.convert = euler_from_quaternion")


@case("DEP001", TALKER, "from ament_index_python")
def ament_index_python_undeclared(root: Path) -> None:
    _import(root, TALKER, "from ament_index_python.packages import get_package_share_directory",
            "self.share = get_package_share_directory('base_pkg')")


@case("DEP001", TALKER, "from cv_bridge import CvBridge")
def cv_bridge_undeclared(root: Path) -> None:
    _import(root, TALKER, "from cv_bridge import CvBridge", "self.bridge = CvBridge()")


@case("DEP001", "base_pkg/srv.py", "from std_srvs.srv import Trigger")
def service_package_undeclared(root: Path) -> None:
    edit(root, XML, "  <depend>std_srvs</depend>\n", "")


@case("DEP001", TALKER, "import rclpy")
def rclpy_undeclared(root: Path) -> None:
    edit(root, XML, "  <depend>rclpy</depend>\n", "")


@case("DEP002", TALKER, "from std_msgs.msg import String")
def message_package_only_build_depend(root: Path) -> None:
    edit(root, XML, "<depend>std_msgs</depend>", "<build_depend>std_msgs</build_depend>")


@case("DEP001", TALKER, "import numpy as np")
def numpy_only_test_depend(root: Path) -> None:
    _import(root, TALKER, "import numpy as np", "self.history = np.zeros(10)")
    edit(root, XML, "  <test_depend>python3-pytest</test_depend>\n",
         "  <test_depend>python3-numpy</test_depend>\n"
         "  <test_depend>python3-pytest</test_depend>\n")


@case("MAN018", TALKER, "import numpy as np")  # the pip name holds the import's DEP001
def numpy_declared_under_pip_name(root: Path) -> None:
    _import(root, TALKER, "import numpy as np", "self.history = np.zeros(10)")
    edit(root, XML, "  <exec_depend>launch</exec_depend>\n",
         "  <exec_depend>numpy</exec_depend>\n  <exec_depend>launch</exec_depend>\n")


@case("DEP003", "test/test_numbers.py", "import numpy")
def test_imports_undeclared(root: Path) -> None:
    write(root, "test/test_numbers.py", """
        import numpy


        def test_zeros():
            assert numpy.zeros(2).sum() == 0
        """, licensed=True)


@case("DEP001", "base_pkg/nodes/camera.py", "import cv2")
def undeclared_in_subpackage(root: Path) -> None:
    write(root, "base_pkg/nodes/__init__.py", "")
    write(root, "base_pkg/nodes/camera.py", """
        import cv2


        def show(frame):
            cv2.imshow('camera', frame)
        """, licensed=True)


@case("DEP001", f"{CAMERA}/nodes/image_subscriber.py", "cv2", base=CAMERA)
def opencv_dependency_dropped(root: Path) -> None:
    edit(root, XML, "  <exec_depend>python3-opencv</exec_depend>\n", "")


@case("DEP001", f"{CAMERA}/camera/image_processor.py", "numpy", base=CAMERA)
def numpy_dependency_dropped(root: Path) -> None:
    edit(root, XML, "  <exec_depend>python3-numpy</exec_depend>\n", "")


@case("DEP001", f"{CAMERA}/nodes/image_subscriber.py", "sensor_msgs", base=CAMERA)
def sensor_msgs_dependency_dropped(root: Path) -> None:
    edit(root, XML, "  <depend>sensor_msgs</depend>\n", "")


@case("DEP002", "base_pkg/srv.py", "from std_srvs.srv import")
def service_package_only_buildtool_depend(root: Path) -> None:
    edit(root, XML, "<depend>std_srvs</depend>", "<buildtool_depend>std_srvs</buildtool_depend>")


@case("DEP008", TALKER, "from std_msgs.msgs import String")
def message_module_plural(root: Path) -> None:
    edit(root, TALKER, "from std_msgs.msg import String", "from std_msgs.msgs import String")


@case("DEP008", TALKER, "from std_msgs import String")
def message_imported_from_the_package(root: Path) -> None:
    edit(root, TALKER, "from std_msgs.msg import String", "from std_msgs import String")


@case("DEP008", "base_pkg/srv.py", "from std_srvs.srvs import Trigger")
def service_module_plural(root: Path) -> None:
    edit(root, "base_pkg/srv.py", "from std_srvs.srv import", "from std_srvs.srvs import")


def _helpers(root: Path, line: str, use: str) -> None:
    """Add a helpers module to the package and ``line`` importing from it to the talker."""
    write(root, "base_pkg/helpers.py", """
        def clamp(value, low, high):
            return max(low, min(high, value))
        """, licensed=True)
    edit(root, TALKER, "import rclpy\n", f"import rclpy\n\n{line}\n")
    edit(root, TALKER, "        self.count = 0\n", f"        self.count = {use}\n")


@case("DEP010", TALKER, "from base_pkg.helper import clamp")
def own_module_name_misspelled(root: Path) -> None:
    _helpers(root, "from base_pkg.helper import clamp", "clamp(0, 0, 1)")


@case("DEP010", TALKER, "from base_pkg.helpers import clip")
def own_function_name_misspelled(root: Path) -> None:
    _helpers(root, "from base_pkg.helpers import clip", "clip(0, 0, 1)")
