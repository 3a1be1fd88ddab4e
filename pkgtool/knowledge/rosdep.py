"""Which package.xml key provides an import, and which keys are not rosdep keys.

Third-party keys were checked against rosdep's ``python.yaml`` and ``base.yaml`` in
ros/rosdistro; they are data, not guesses: a module absent here is reported as unknown, never
mapped. ROS import names map to the ROS package of the same name unless listed in
:data:`ROS_MODULE_PACKAGES`.
"""

from __future__ import annotations

import sys

PYTHON_MODULE_KEYS: dict[str, str] = {
    "aiohttp": "python3-aiohttp", "argcomplete": "python3-argcomplete",
    "autobahn": "python3-autobahn", "boto3": "python3-boto3",
    "bs4": "python3-bs4", "bson": "python3-bson", "cairo": "python3-cairo",
    "can": "python3-can", "catkin_pkg": "python3-catkin-pkg", "click": "python3-click",
    "colorama": "python3-colorama", "coverage": "python3-coverage", "crcmod": "python3-crcmod",
    "cryptography": "python3-cryptography", "cv2": "python3-opencv",
    "dateutil": "python3-dateutil", "dbus": "python3-dbus", "deepdiff": "python3-deepdiff",
    "defusedxml": "python3-defusedxml", "docker": "python3-docker",
    "docopt": "python3-docopt", "docutils": "python3-docutils", "em": "python3-empy",
    "evdev": "python3-evdev", "fastapi": "python3-fastapi", "flask": "python3-flask",
    "geographiclib": "python3-geographiclib", "geopy": "python3-geopy",
    "gi": "python3-gi", "git": "python3-git", "gpiod": "python3-libgpiod",
    "gpiozero": "python3-gpiozero", "grpc": "python3-grpcio", "h5py": "python3-h5py",
    "httplib2": "python3-httplib2", "hypothesis": "python3-hypothesis",
    "imageio": "python3-imageio", "jinja2": "python3-jinja2", "joblib": "python3-joblib",
    "jsonschema": "python3-jsonschema", "lark": "python3-lark-parser", "lxml": "python3-lxml",
    "mako": "python3-mako", "markdown": "python3-markdown", "matplotlib": "python3-matplotlib",
    "mediapipe": "python3-mediapipe-pip", "mock": "python3-mock",
    "msgpack": "python3-msgpack", "netifaces": "python3-netifaces",
    "networkx": "python3-networkx", "nose": "python3-nose", "numpy": "python3-numpy",
    "onnxruntime": "python3-onnxruntime-pip", "open3d": "python3-open3d-pip",
    "openai": "python3-openai-pip", "OpenGL": "python3-opengl",
    "packaging": "python3-packaging", "paho": "python3-paho-mqtt", "pandas": "python3-pandas",
    "paramiko": "python3-paramiko", "pexpect": "python3-pexpect", "pika": "python3-pika",
    "PIL": "python3-pil", "pkg_resources": "python3-setuptools",
    "prettytable": "python3-prettytable", "psutil": "python3-psutil",
    "pyaudio": "python3-pyaudio", "pybullet": "python3-pybullet-pip",
    "pydantic": "python3-pydantic", "pydot": "python3-pydot",
    "pygame": "python3-pygame", "pygraphviz": "python3-pygraphviz", "PyKDL": "python3-pykdl",
    "pymodbus": "python3-pymodbus", "pymongo": "python3-pymongo",
    "pynmea2": "python3-pynmea2", "pynput": "pynput-pip", "pyparsing": "python3-pyparsing",
    "pyproj": "python3-pyproj", "PyQt5": "python3-pyqt5", "pyqtgraph": "python3-pyqtgraph",
    "pytest": "python3-pytest", "pytz": "python3-tz", "qtpy": "python3-qtpy",
    "requests": "python3-requests", "rospkg": "python3-rospkg", "ruamel": "python3-ruamel.yaml",
    "scipy": "python3-scipy", "serial": "python3-serial", "setuptools": "python3-setuptools",
    "shapely": "python3-shapely", "simplejson": "python3-simplejson",
    "six": "python3-six", "skimage": "python3-skimage", "sklearn": "python3-sklearn",
    "smbus": "python3-smbus", "smbus2": "python3-smbus2-pip",
    "sounddevice": "python3-sounddevice-pip", "sqlalchemy": "python3-sqlalchemy",
    "sympy": "python3-sympy", "tabulate": "python3-tabulate", "termcolor": "python3-termcolor",
    "tkinter": "python3-tk", "toml": "python3-toml", "tornado": "python3-tornado",
    "tqdm": "python3-tqdm", "transforms3d": "python3-transforms3d",
    "transitions": "python3-transitions", "trimesh": "python3-trimesh-pip",
    "twisted": "python3-twisted", "typing_extensions": "python3-typing-extensions",
    "ujson": "python3-ujson", "urllib3": "python3-urllib3", "usb": "python3-usb",
    "uvicorn": "python3-uvicorn", "watchdog": "python3-watchdog",
    "websocket": "python3-websocket", "websockets": "python3-websockets",
    "werkzeug": "python3-werkzeug", "xmltodict": "python3-xmltodict", "yaml": "python3-yaml",
    "zmq": "python3-zmq",
}
"""Third-party top-level import name -> the rosdep key that installs it (all in python.yaml).

``tkinter`` is here although it is in the standard library: Debian and Ubuntu ship it
separately (python3-tk), so it must be declared.
"""

ALTERNATIVE_KEYS: dict[str, tuple[str, ...]] = {
    "catkin_pkg": ("python3-catkin-pkg-modules",),
    "pkg_resources": ("python3-pkg-resources",),
    "rospkg": ("python3-rospkg-modules",),
    "tf2_ros": ("tf2_ros",),
}
"""Other keys that provide the same import (accepted, never suggested).

The ``-modules`` keys install only the Python modules, without the command line scripts; ROS
2's own tools (ros2pkg, ament_package users) declare them.
"""

ROS_MODULE_PACKAGES: dict[str, str] = {
    "tf2_ros": "tf2_ros_py",
    "urdf_parser_py": "urdfdom_py",
    "moveit": "moveit_py",
}
"""ROS import names whose package has another name (every other ROS import is its package)."""

NOT_ROSDEP_KEYS: dict[str, str] = {
    # pip distribution names and import names: rosdep has no such keys
    "numpy": "python3-numpy",
    "scipy": "python3-scipy",
    "opencv-python": "python3-opencv",
    "opencv-python-headless": "python3-opencv",
    "opencv-contrib-python": "python3-opencv",
    "opencv": "python3-opencv",
    "cv2": "python3-opencv",
    "pyyaml": "python3-yaml",
    "PyYAML": "python3-yaml",
    "pillow": "python3-pil",
    "Pillow": "python3-pil",
    "PIL": "python3-pil",
    "pyserial": "python3-serial",
    "matplotlib": "python3-matplotlib",
    "pandas": "python3-pandas",
    "scikit-learn": "python3-sklearn",
    "sklearn": "python3-sklearn",
    "requests": "python3-requests",
    "pytest": "python3-pytest",
    "transforms3d": "python3-transforms3d",
    "psutil": "python3-psutil",
    "setuptools": "python3-setuptools",
    # ROS 1 era Python 2 keys: no definition for the Ubuntu releases ROS 2 targets
    "python-opencv": "python3-opencv",
    "python-numpy": "python3-numpy",
    "python-yaml": "python3-yaml",
    "python-pytest": "python3-pytest",
    "python-setuptools": "python3-setuptools",
}
"""Names people write where a rosdep key belongs -> the key to use instead.

``yaml`` and ``serial`` are not listed: ``yaml`` is a real key (the libyaml C library) and
``serial`` is a ROS package in some distributions.
"""

ROS1_PACKAGES: dict[str, str] = {
    "rospy": "`rclpy`", "roscpp": "`rclcpp`", "roslib": "`ament_index_python`",
    "roslaunch": "`launch` and `launch_ros`", "rostest": "`launch_testing_ros`",
    "rosbag": "`rosbag2_py`", "tf": "`tf2_ros`", "actionlib": "`rclpy.action`",
    "dynamic_reconfigure": "node parameters", "message_generation": "`rosidl_default_generators`",
    "message_runtime": "`rosidl_default_runtime`",
    "catkin": "`<build_type>ament_python</build_type>` in `<export>`",
}
"""ROS 1 packages (and their Python modules) that no ROS 2 distribution has -> what replaces them.

``rospy``'s rosdep key resolves only on ROS 1 distributions; ROS 2 has none of these packages.
"""

NOT_PACKAGES: dict[str, str] = {
    "ament_python": "ament_python is a build type, not a package: declare "
                    "<build_type>ament_python</build_type> in <export> and drop the tag",
}
"""Build tools that are not packages at all, as buildtool_depend values."""


def stdlib_modules() -> frozenset[str]:
    """Top-level names of the standard library of the running interpreter."""
    return frozenset(sys.stdlib_module_names)


def key_for_python_module(top_level: str) -> str | None:
    """The rosdep key providing a third-party top-level import, or None if not curated."""
    return PYTHON_MODULE_KEYS.get(top_level)


def suggested_key(declared: str) -> str | None:
    """The rosdep key to use instead of ``declared`` when that is a pip/ROS 1 name."""
    return NOT_ROSDEP_KEYS.get(declared)


def package_for_ros_module(top_level: str) -> str:
    """The ROS package providing a ROS import (usually the same name)."""
    return ROS_MODULE_PACKAGES.get(top_level, top_level)


def accepted_keys(top_level: str, primary: str) -> tuple[str, ...]:
    """Every key that provides ``top_level``: ``primary`` first, then the alternatives."""
    return (primary, *ALTERNATIVE_KEYS.get(top_level, ()))
