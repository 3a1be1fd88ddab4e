"""Environment for any process that initialises rclpy: never multicast on the real network."""

from __future__ import annotations

import os
from collections.abc import Mapping

# Variables of the parent's ROS setup that must not leak into an isolated run.
_DROPPED = ("_ROS_WHEELS_BOOTSTRAP_COMPLETE", "RMW_IMPLEMENTATION", "ROS_LOCALHOST_ONLY",
            "ROS_STATIC_PEERS", "FASTRTPS_DEFAULT_PROFILES_FILE", "FASTDDS_DEFAULT_PROFILES_FILE")


def isolated_ros_env(
    *,
    domain_id: int,
    log_dir: str,
    discovery_range: str = "LOCALHOST",
    base: Mapping[str, str] | None = None,
) -> dict[str, str]:
    """Return a copy of ``base`` (default: os.environ) set up for one isolated ROS run.

    ``discovery_range`` is LOCALHOST for runs that talk between processes and OFF for purely
    in-process runs; the default, SUBNET, is never allowed.
    """
    if discovery_range not in ("LOCALHOST", "OFF"):
        raise ValueError(f"discovery range must be LOCALHOST or OFF, not {discovery_range!r}")
    if not 0 <= domain_id <= 232:
        raise ValueError(f"ROS_DOMAIN_ID must be within 0..232, not {domain_id}")
    env = {k: v for k, v in (os.environ if base is None else base).items() if k not in _DROPPED}
    env.update(
        ROS_AUTOMATIC_DISCOVERY_RANGE=discovery_range,
        ROS_DOMAIN_ID=str(domain_id),
        ROS_LOG_DIR=log_dir,
        RCUTILS_COLORIZED_OUTPUT="0",
        PYTHONUNBUFFERED="1",
    )
    return env
