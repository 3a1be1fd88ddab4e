# Copyright 2026 Physical AI Robotics Team
#
# Licensed under the Apache License, Version 2.0 (the "License");
# you may not use this file except in compliance with the License.
# You may obtain a copy of the License at
#
#     http://www.apache.org/licenses/LICENSE-2.0
#
# Unless required by applicable law or agreed to in writing, software
# distributed under the License is distributed on an "AS IS" BASIS,
# WITHOUT WARRANTIES OR CONDITIONS OF ANY KIND, either express or implied.
# See the License for the specific language governing permissions and
# limitations under the License.

"""Timestamp helpers and an approximate-time synchroniser for several message streams."""

from collections import deque

_NANOSECONDS_PER_SECOND = 1_000_000_000


def stamp_to_nanoseconds(stamp) -> int:
    """Return a builtin_interfaces/Time as integer nanoseconds."""
    return stamp.sec * _NANOSECONDS_PER_SECOND + stamp.nanosec


def stamp_to_seconds(stamp) -> float:
    """Return a builtin_interfaces/Time as float seconds."""
    return stamp_to_nanoseconds(stamp) / _NANOSECONDS_PER_SECOND


class TimestampSynchronizer:
    """
    Group messages of ``stream_count`` streams whose header stamps lie within ``slop`` seconds.

    Each stream keeps its ``queue_size`` newest messages. When a message arrives, the closest
    message of every other stream is looked up; if all are within ``slop`` of it, the group is
    returned (in stream order) and it and everything older are dropped from the queues.
    """

    def __init__(self, stream_count: int, slop: float, queue_size: int = 10) -> None:
        """Create empty queues; ``slop`` is in seconds."""
        if stream_count < 2 or slop < 0 or queue_size < 1:
            raise ValueError('need two or more streams, slop >= 0 and queue_size >= 1')
        self._slop = round(slop * _NANOSECONDS_PER_SECOND)
        self._queues = [deque(maxlen=queue_size) for _ in range(stream_count)]

    def add(self, stream: int, msg) -> tuple | None:
        """Add ``msg`` (with a header) from ``stream``; return a synchronised group or None."""
        stamp = stamp_to_nanoseconds(msg.header.stamp)
        self._queues[stream].append((stamp, msg))
        group = []
        for index, queue in enumerate(self._queues):
            if index == stream:
                group.append((stamp, msg))
                continue
            if not queue:
                return None
            best = min(queue, key=lambda item: abs(item[0] - stamp))
            if abs(best[0] - stamp) > self._slop:
                return None
            group.append(best)
        for queue, (matched, _) in zip(self._queues, group):
            while queue and queue[0][0] <= matched:
                queue.popleft()
        return tuple(message for _, message in group)
