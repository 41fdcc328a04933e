"""Session bags: written as rosbag2 (MCAP storage, metadata version 9) with `rosbags`, read back
into a `TrialLog` so metrics can be recomputed from any recording.

Messages arrive as raw CDR bytes (the recorder node subscribes with raw=True), so recording costs
no Python message conversion; reading deserialises only the topics the metrics need.
"""

from __future__ import annotations

import json
from collections.abc import Iterator, Sequence
from pathlib import Path
from types import TracebackType
from typing import Any

from rosbags.highlevel import AnyReader
from rosbags.rosbag2 import StoragePlugin, Writer
from rosbags.interfaces import Connection
from rosbags.typesys import Stores, get_typestore

from haven_scenarios.record.metrics import TrialLog
from haven_sim.common.geometry import quaternion_to_yaw

TYPESTORE = get_typestore(Stores.ROS2_JAZZY)


class BagWriter:
    """A context manager: the bag is closed (metadata written) however the block ends."""

    def __init__(self, path: Path) -> None:
        self.path = path
        self._writer = Writer(path, version=9, storage_plugin=StoragePlugin.MCAP)
        self._connections: dict[str, Connection] = {}
        self.counts: dict[str, int] = {}

    def __enter__(self) -> BagWriter:
        self._writer.open()
        return self

    def __exit__(self, et: type[BaseException] | None, ev: BaseException | None, tb: TracebackType | None) -> None:
        self.close()

    def close(self) -> None:
        if self._writer is not None:
            self._writer.close()
            self._writer = None  # type: ignore[assignment]

    def knows(self, topic: str) -> bool:
        return topic in self._connections

    def add_topic(self, topic: str, msgtype: str) -> bool:
        """Register a topic; False for types this ROS distribution's typestore does not know."""
        if topic in self._connections:
            return True
        if msgtype not in TYPESTORE.types:
            return False
        self._connections[topic] = self._writer.add_connection(topic, msgtype, typestore=TYPESTORE)
        self.counts[topic] = 0
        return True

    def write(self, topic: str, stamp_ns: int, data: bytes) -> None:
        self._writer.write(self._connections[topic], stamp_ns, data)
        self.counts[topic] += 1


def _messages(bag: Path, topics: Sequence[str]) -> Iterator[tuple[str, int, Any]]:
    with AnyReader([bag], default_typestore=TYPESTORE) as reader:
        connections = [c for c in reader.connections if c.topic in topics]
        for conn, stamp, raw in reader.messages(connections=connections):
            yield conn.topic, stamp, reader.deserialize(raw, conn.msgtype)


def read_log(bag: Path, human_ids: Sequence[str] = (), rate_hz: float = 10.0) -> TrialLog:
    """The trial as `TrialLog` samples (at `rate_hz` of bag time) plus every event."""
    log = TrialLog()
    robot: tuple[float, float, float, float] | None = None
    humans: dict[str, tuple[float, float]] = {}
    battery = 1.0
    live: dict[tuple[str, int], Any] = {}
    step_ns = int(1e9 / rate_hz)
    next_ns: int | None = None
    topics = ["/odom", "/humans", "/battery_state", "/haven/events", "/haven/ar_markers"]
    for topic, stamp, msg in _messages(bag, topics):
        if topic == "/haven/events":
            log.events.append(json.loads(msg.data))
            continue
        if next_ns is not None and robot is not None:
            while stamp >= next_ns:
                bubble = any(ns == "thought_bubble" for ns, _ in live)
                signal = 1 if ("turn_signals", 0) in live else (-1 if ("turn_signals", 1) in live else 0)
                log.sample(next_ns * 1e-9, robot, dict(humans), battery, bubble, signal)
                next_ns += step_ns
        if topic == "/odom":
            p, q = msg.pose.pose.position, msg.pose.pose.orientation
            robot = (p.x, p.y, quaternion_to_yaw(q.x, q.y, q.z, q.w), msg.twist.twist.angular.z)
            if next_ns is None:
                next_ns = stamp - stamp % step_ns + step_ns
        elif topic == "/humans":
            for i, pose in enumerate(msg.poses):
                hid = human_ids[i] if i < len(human_ids) else f"h{i}"
                humans[hid] = (pose.position.x, pose.position.y)
        elif topic == "/battery_state":
            battery = float(msg.percentage)
        elif topic == "/haven/ar_markers":
            for m in msg.markers:
                if m.action == 2:  # DELETE
                    live.pop((m.ns, m.id), None)
                elif m.action == 0:
                    live[(m.ns, m.id)] = True
    return log
