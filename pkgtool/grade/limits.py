"""What one sandboxed command may use, and the words for the limit that stopped it."""

from __future__ import annotations

import signal
from collections.abc import Mapping

from pkgtool.records import record


@record
class Limits:
    """What one sandboxed command may use; ``timeout`` is wall-clock seconds.

    ``disk_mb`` is the size of the job's own filesystem (workspace, /tmp and /dev/shm of
    each step), where the machine allows one.
    """

    timeout: float = 300.0
    memory_mb: int = 2048
    processes: int = 256
    cpu_seconds: int = 600
    file_size_mb: int = 256
    output_kb: int = 256
    disk_mb: int = 1024


def limits_hit(limits: Limits, timeout: float, stopped: str, events: Mapping[str, int],
               returncode: int, output: str, in_cgroup: bool) -> list[str]:
    """Plain words for every limit the run hit (from the cgroup's counters, else its output)."""
    hits = []
    if stopped == "timeout":
        hits.append(f"timed out after {timeout:g} s")
    if stopped == "output":
        hits.append(f"killed: output over {64 * limits.output_kb} KB")
    if events.get("memory") or (not in_cgroup and "MemoryError" in output):
        hits.append(f"killed: memory (limit {limits.memory_mb} MB)")
    if events.get("pids") or (not in_cgroup and "Resource temporarily unavailable" in output):
        hits.append(f"killed: too many processes (limit {limits.processes})")
    if returncode in (-signal.SIGXCPU, 128 + signal.SIGXCPU):
        hits.append(f"killed: CPU time (limit {limits.cpu_seconds} s)")
    if "File too large" in output:
        hits.append(f"file size limit reached ({limits.file_size_mb} MB)")
    if "No space left on device" in output:
        hits.append(f"disk full (limit {limits.disk_mb} MB)")
    return hits
