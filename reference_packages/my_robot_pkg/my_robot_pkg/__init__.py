"""Agents that observe and report the robot's state."""
