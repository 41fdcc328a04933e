"""Session bags: written as rosbag2 (MCAP storage, metadata version 9) with `rosbags`, read back
as the trial's messages (core payloads) so metrics can be recomputed from any recording.

Messages arrive as raw CDR bytes (the recorder node subscribes with raw=True), so recording costs
no Python message conversion; reading deserialises only the topics the metrics need.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from pathlib import Path
from types import TracebackType
from typing import Any

from rosbags.highlevel import AnyReader
from rosbags.interfaces import Connection
from rosbags.rosbag2 import StoragePlugin, Writer
from rosbags.typesys import Stores, get_typestore

from haven_scenarios.record.log import LogBuilder, TrialLog
from haven_sim.common import topics
from haven_sim.common.events import Event, EventError
from haven_sim.common.geometry import Pose2D, Twist2D, quaternion_to_yaw
from haven_sim.common.state import RobotState, name_humans
from haven_sim.runtime.component import Message
from haven_sim.sim.battery import BatteryReading, PowerStatus
from haven_viz.cues import CueState

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


def _pose(p: Any) -> Pose2D:
    q = p.orientation
    return Pose2D(p.position.x, p.position.y, quaternion_to_yaw(q.x, q.y, q.z, q.w))


def _payload(topic: str, msg: Any, human_ids: Sequence[str]) -> Any:
    """A recorded message as the core payload the components and metrics use."""
    if topic == topics.ODOM:
        t = msg.twist.twist
        return RobotState(_pose(msg.pose.pose), Twist2D(t.linear.x, t.linear.y, t.angular.z))
    if topic == topics.HUMANS:
        return name_humans([_pose(p) for p in msg.poses], human_ids)
    if topic == topics.BATTERY:
        level = float(msg.percentage)
        return BatteryReading(level, PowerStatus.DISCHARGING, float(msg.voltage), float(msg.charge), float(msg.capacity), float("nan"))
    if topic == topics.CUE_STATE:
        return CueState.from_json(msg.data)[1]
    return Event.from_json(msg.data)


READ = {"/" + t: t for t in (topics.ODOM, topics.HUMANS, topics.BATTERY, topics.EVENTS, topics.CUE_STATE)}


def read_messages(bag: Path, human_ids: Sequence[str] = ()) -> Iterator[Message]:
    """The trial's messages in bag order; recorded strings that are not valid events are skipped."""
    with AnyReader([bag], default_typestore=TYPESTORE) as reader:
        connections = [c for c in reader.connections if c.topic in READ]
        for conn, stamp, raw in reader.messages(connections=connections):
            topic = READ[conn.topic]
            try:
                data = _payload(topic, reader.deserialize(raw, conn.msgtype), human_ids)
            except (EventError, ValueError):
                continue
            yield Message(topic, data, stamp * 1e-9)


def read_log(bag: Path, human_ids: Sequence[str] = (), rate_hz: float = 10.0) -> TrialLog:
    """The trial as `TrialLog` samples (at `rate_hz` of bag time) plus every event."""
    builder = LogBuilder(rate_hz)
    for m in read_messages(bag, human_ids):
        builder.add(m)
    return builder.log
