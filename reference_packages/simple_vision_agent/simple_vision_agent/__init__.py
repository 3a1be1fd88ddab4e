"""A perception agent: find coloured objects in sensor_msgs/Image streams."""
