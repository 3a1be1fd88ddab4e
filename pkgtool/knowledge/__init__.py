"""Curated facts about the ROS and Python ecosystems (offline tables, no network)."""
