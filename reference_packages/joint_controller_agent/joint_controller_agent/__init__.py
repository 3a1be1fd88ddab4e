"""A Python agent commanding humanoid joints through ROS 2 controllers."""
