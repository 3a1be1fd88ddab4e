"""Helpers for running real ROS 2 Jazzy (from PyPI wheels) safely: isolation and wheel fix-ups."""
