"""The job's own filesystem: a size-capped tmpfs that exists only in the grading process's
private mount namespace, so it is invisible to the machine and vanishes with the process."""

from __future__ import annotations

import ctypes
import functools
import os
import subprocess
from pathlib import Path

from pkgtool.grade.jail import SYSTEM_PATH

_CLONE_NEWNS = 0x00020000
_MNT_DETACH = 2


@functools.cache
def private_mounts() -> bool:
    """Move this process (its calling thread) into a private copy of the mount namespace.

    Mounts made afterwards are seen by this process and its children only, and are gone
    when they all have exited. False when that is not allowed (not root).
    """
    if os.geteuid() != 0:
        return False
    libc = ctypes.CDLL(None, use_errno=True)
    if libc.unshare(_CLONE_NEWNS) != 0:
        return False
    done = subprocess.run(["mount", "--make-rprivate", "/"], capture_output=True, check=False,
                          env={"PATH": SYSTEM_PATH})
    return done.returncode == 0


def mount_tmpfs(folder: Path, size_mb: int) -> bool:
    """Mount a tmpfs of ``size_mb`` MB on ``folder`` in the private namespace; False if not.

    The tmpfs keeps the folder's mode bits (``mode=`` of the folder as it is now).
    """
    if not private_mounts():
        return False
    mode = folder.stat().st_mode & 0o7777
    done = subprocess.run(["mount", "-t", "tmpfs", "-o",
                           f"size={size_mb}m,mode={mode:o},nosuid,nodev", "pkgtool-job",
                           str(folder)], capture_output=True, check=False,
                          env={"PATH": SYSTEM_PATH})
    return done.returncode == 0


def unmount(folder: Path) -> None:
    """Detach the mount on ``folder``: its files are freed without walking them."""
    libc = ctypes.CDLL(None, use_errno=True)
    libc.umount2(os.fsencode(folder), _MNT_DETACH)
