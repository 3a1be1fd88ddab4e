"""pkgtool: create, lint, check, test and grade ROS 2 Python (ament_python) packages."""

__version__ = "0.1.0"
