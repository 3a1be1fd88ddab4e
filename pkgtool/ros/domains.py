"""Machine-wide ROS_DOMAIN_ID leases: concurrent pkgtool processes never share a domain.

A lease is an exclusive ``flock`` on ``<lock dir>/<id>.lock``. The kernel drops it when the
holder closes it or dies, so a crashed test run never leaks a domain. Every test, colcon run
and graded job takes its domain from here instead of picking a number.
"""

from __future__ import annotations

import fcntl
import os
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

FIRST_ID, LAST_ID = 1, 101
"""Domain ids whose DDS ports stay below Linux's ephemeral port range."""

LOCK_DIR = Path(os.environ.get("PKGTOOL_DOMAIN_LOCK_DIR", "/tmp/pkgtool-ros-domains"))

_held: dict[int, int] = {}
"""Leased domain id -> the open lock file descriptor that holds it."""


def _lock_dir() -> Path:
    """The shared lock folder, world-writable and sticky like /tmp so every user can lease."""
    if not LOCK_DIR.is_dir():
        LOCK_DIR.mkdir(parents=True, exist_ok=True)
        LOCK_DIR.chmod(0o1777)
    return LOCK_DIR


def _try_lock(folder: Path, domain_id: int) -> int | None:
    # Read-only is enough for flock and lets other users open a lock file this user created.
    fd = os.open(folder / f"{domain_id}.lock", os.O_RDONLY | os.O_CREAT | os.O_CLOEXEC, 0o644)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        os.close(fd)
        return None
    return fd


def lease_domain() -> int:
    """Lease a domain id that no other lease on this machine holds, until :func:`release_domain`.

    The search starts at a place derived from the process id, so concurrent processes rarely
    contend; with every id taken it raises ``RuntimeError`` naming the lock folder.
    """
    folder = _lock_dir()
    count = LAST_ID - FIRST_ID + 1
    start = os.getpid() % count
    for step in range(count):
        domain_id = FIRST_ID + (start + step) % count
        if domain_id in _held:
            continue
        fd = _try_lock(folder, domain_id)
        if fd is not None:
            _held[domain_id] = fd
            return domain_id
    raise RuntimeError(f"Every ROS domain id {FIRST_ID}-{LAST_ID} is leased by another process "
                       f"(locks in {folder}). Wait for other ROS runs to finish and retry.")


def release_domain(domain_id: int) -> None:
    """Give back a domain leased by this process (a domain not held is ignored)."""
    fd = _held.pop(domain_id, None)
    if fd is not None:
        os.close(fd)


@contextmanager
def leased_domain() -> Iterator[int]:
    """A domain id held for the ``with`` block."""
    domain_id = lease_domain()
    try:
        yield domain_id
    finally:
        release_domain(domain_id)
