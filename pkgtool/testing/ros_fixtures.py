"""pytest fixtures giving each test an isolated, in-process ROS 2 context.

Load with ``pytest_plugins = ["pkgtool.testing.ros_fixtures"]``. Each test gets its own
``rclpy`` context with discovery OFF, its own leased domain id and a temporary log folder, shut
down even when the test fails. Nothing here talks to the real network.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest


@pytest.fixture
def ros_domain() -> Iterator[int]:
    """A ROS domain id leased for this test alone: no other process on the machine uses it."""
    from pkgtool.ros.domains import leased_domain

    with leased_domain() as domain_id:
        yield domain_id


@pytest.fixture
def ros_env(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, ros_domain: int) -> dict[str, str]:
    """Set the isolation variables in this process for the test's duration and return them."""
    from pkgtool.ros.isolation import isolated_ros_env

    log_dir = tmp_path / "ros_log"
    log_dir.mkdir()
    env = isolated_ros_env(domain_id=ros_domain, log_dir=str(log_dir), discovery_range="OFF",
                           base={})
    for key, value in env.items():
        monkeypatch.setenv(key, value)
    return env


@pytest.fixture
def ros_context(ros_env: dict[str, str]) -> Iterator[object]:
    """An initialised rclpy Context for this test only; shut down afterwards whatever happens."""
    import rclpy
    from rclpy.context import Context

    context = Context()
    rclpy.init(context=context, domain_id=int(ros_env["ROS_DOMAIN_ID"]))
    try:
        yield context
    finally:
        if context.ok():
            rclpy.shutdown(context=context)
