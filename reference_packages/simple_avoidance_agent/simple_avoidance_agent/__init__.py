"""Obstacle avoidance agents: LaserScan in, geometry_msgs/Twist out."""
