"""Which package.xml key provides an import, and which keys are not rosdep keys.

Tables are curated from rosdep's base yaml (python.yaml) and the ROS 2 Jazzy package set;
they are data, not guesses: a module absent here is reported as unknown, never mapped.
"""

from __future__ import annotations

import sys

# Third-party import name -> rosdep key (rosdep/python.yaml, Ubuntu 24.04 / Debian names).
PYTHON_MODULE_KEYS: dict[str, str] = {
    "numpy": "python3-numpy",
    "scipy": "python3-scipy",
    "cv2": "python3-opencv",
    "yaml": "python3-yaml",
    "PIL": "python3-pil",
    "serial": "python3-serial",
    "matplotlib": "python3-matplotlib",
    "pandas": "python3-pandas",
    "sklearn": "python3-sklearn",
    "requests": "python3-requests",
    "transforms3d": "python3-transforms3d",
    "psutil": "python3-psutil",
    "pytest": "python3-pytest",
    "mock": "python3-mock",
    "setuptools": "python3-setuptools",
    "pkg_resources": "python3-setuptools",
    "lxml": "python3-lxml",
    "jinja2": "python3-jinja2",
    "empy": "python3-empy",
    "em": "python3-empy",
    "netifaces": "python3-netifaces",
    "shapely": "python3-shapely",
    "sympy": "python3-sympy",
    "networkx": "python3-networkx",
    "pyproj": "python3-pyproj",
    "usb": "python3-usb",
    "smbus": "python3-smbus",
    "smbus2": "python3-smbus2",
    "zmq": "python3-zmq",
    "paho": "python3-paho-mqtt",
    "bson": "python3-bson",
    "pymongo": "python3-pymongo",
    "flask": "python3-flask",
    "websocket": "python3-websocket",
    "twisted": "python3-twisted",
    "tornado": "python3-tornado",
    "toml": "python3-toml",
    "tomli": "python3-tomli",
    "pygame": "python3-pygame",
    "pexpect": "python3-pexpect",
    "termcolor": "python3-termcolor",
    "tqdm": "python3-tqdm",
    "skimage": "python3-skimage",
    "open3d": "python3-open3d-pip",
    "torch": "python3-torch",
    "tensorflow": "python3-tensorflow-pip",
    "ultralytics": "python3-ultralytics-pip",
    "qtpy": "python3-qtpy",
    "PyQt5": "python3-pyqt5",
    "pydantic": "python3-pydantic",
    "rosbags": "python3-rosbags-pip",
    "packaging": "python3-packaging",
    "docutils": "python3-docutils",
    "dateutil": "python3-dateutil",
    "defusedxml": "python3-defusedxml",
    "cryptography": "python3-cryptography",
    "nose": "python3-nose",
    "coverage": "python3-coverage",
    "hypothesis": "python3-hypothesis",
}

# Import names whose ROS package has another name.
ROS_MODULE_PACKAGES: dict[str, str] = {
    "tf2_ros": "tf2_ros_py",
    "tf_transformations": "tf_transformations",
    "launch_ros": "launch_ros",
    "ament_index_python": "ament_index_python",
    "rosidl_runtime_py": "rosidl_runtime_py",
    "cv_bridge": "cv_bridge",
}

# pip distribution names (and old ROS 1 keys) that people write where a rosdep key belongs.
NOT_ROSDEP_KEYS: dict[str, str] = {
    "numpy": "python3-numpy",
    "scipy": "python3-scipy",
    "opencv-python": "python3-opencv",
    "opencv-python-headless": "python3-opencv",
    "opencv-contrib-python": "python3-opencv",
    "opencv": "python3-opencv",
    "cv2": "python3-opencv",
    "python-opencv": "python3-opencv",
    "python-numpy": "python3-numpy",
    "python-yaml": "python3-yaml",
    "pyyaml": "python3-yaml",
    "PyYAML": "python3-yaml",
    "yaml": "python3-yaml",
    "pillow": "python3-pil",
    "Pillow": "python3-pil",
    "PIL": "python3-pil",
    "pyserial": "python3-serial",
    "serial": "python3-serial",
    "matplotlib": "python3-matplotlib",
    "pandas": "python3-pandas",
    "scikit-learn": "python3-sklearn",
    "sklearn": "python3-sklearn",
    "requests": "python3-requests",
    "pytest": "python3-pytest",
    "python-pytest": "python3-pytest",
    "transforms3d": "python3-transforms3d",
    "psutil": "python3-psutil",
    "setuptools": "python3-setuptools",
    "python-setuptools": "python3-setuptools",
    "torch": "python3-torch",
}

# Build tools that are not packages at all, as buildtool_depend values.
NOT_PACKAGES: dict[str, str] = {
    "ament_python": "ament_python is a build type, not a package: declare "
                    "<build_type>ament_python</build_type> in <export> and drop the tag",
}


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
