"""Watch one sandboxed command: collect its output and private answers, stop it, name the limit."""

from __future__ import annotations

import os
import selectors
import signal
import subprocess
import time
from dataclasses import dataclass

CHANNEL_CAP = 8 * 1024 * 1024
"""Most bytes kept from a command's results descriptor (the rest is drained and dropped)."""


@dataclass
class Collected:
    """What a run produced: output text, results-channel bytes, and why it was stopped."""

    output: str
    channel: bytes
    stopped: str


def collect(process: subprocess.Popen[bytes], timeout: float, keep: int,
            channel: int | None) -> Collected:
    """Read output (and ``channel``) until exit or ``timeout``, keeping head and tail.

    ``stopped`` is ``timeout``, ``output`` (a flood of 64 times ``keep``) or ``""``. The
    process group is killed before returning, so nothing of the command is left running
    when the caller reads the channel.
    """
    assert process.stdout is not None
    head, tail, answer = bytearray(), bytearray(), bytearray()
    total, stopped = 0, ""
    deadline = time.monotonic() + timeout
    grace: float | None = None
    with selectors.DefaultSelector() as selector:
        selector.register(process.stdout.fileno(), selectors.EVENT_READ, "out")
        if channel is not None:
            selector.register(channel, selectors.EVENT_READ, "channel")
        while selector.get_map():
            now = time.monotonic()
            if now >= deadline:
                stopped = "timeout"
                break
            if grace is None and process.poll() is not None:
                grace = now + 1.0  # background children may hold the pipes: not for long
            if grace is not None and now >= grace:
                break
            for key, _ in selector.select(timeout=min(0.2, deadline - now)):
                chunk = os.read(key.fd, 65536)
                if not chunk:
                    selector.unregister(key.fd)
                elif key.data == "channel":
                    answer += chunk[:max(0, CHANNEL_CAP - len(answer))]
                else:
                    total += len(chunk)
                    room = keep - len(head)
                    if room > 0:
                        head += chunk[:room]
                        chunk = chunk[room:]
                    tail = (tail + chunk)[-keep:]
            if total > 64 * keep:
                stopped = "output"
                break
    kill_group(process)
    omitted = total - len(head) - len(tail)
    middle = f"\n[... {omitted} bytes of output omitted ...]\n".encode() if omitted > 0 else b""
    text = (bytes(head) + middle + bytes(tail)).decode(errors="replace")
    return Collected(text, bytes(answer), stopped)


def kill_group(process: subprocess.Popen[bytes]) -> None:
    """SIGKILL the command's process group (in a jail: its pid namespace dies with it)."""
    try:
        os.killpg(process.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass
    process.wait()
    if process.stdout is not None:
        process.stdout.close()
