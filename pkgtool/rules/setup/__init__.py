"""SET: setup.py and setup.cfg against package.xml and what colcon needs."""
