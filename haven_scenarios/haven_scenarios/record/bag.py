"""Session bags: written as rosbag2 (MCAP storage, metadata version 9) with `rosbags`, read back
as the trial's messages (core payloads) so metrics can be recomputed from any recording.

Messages arrive as raw CDR bytes (the recorder node subscribes with raw=True), so recording costs
no Python message conversion; reading deserialises only the topics the metrics need.

A message's log time is the stamp it carries, where it carries one (a std_msgs/Header first, as
Odometry, LaserScan, PoseStamped; /clock's own time), so the bag's times are the suite's sim-time
stamps however late the recorder read them; other messages (Bool, String, TFMessage, ...) are
logged at the recorder's sim time when they arrived, as `ros2 bag record --use-sim-time` does.
"""

from __future__ import annotations

import contextlib
import json
import struct
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass
from io import BytesIO
from pathlib import Path
from types import TracebackType
from typing import Any, BinaryIO, TypeVar

import numpy as np
import yaml
from mcap.exceptions import McapError
from mcap.records import Channel as McapChannel, McapRecord, Message as McapMessage, Schema as McapSchema
from mcap.stream_reader import StreamReader
from rosbags.highlevel import AnyReader
from rosbags.interfaces import Connection, Qos
from rosbags.rosbag2 import StoragePlugin, Writer
from rosbags.rosbag2.storage_mcap import McapWriter
from rosbags.typesys import Stores, get_typestore

from haven_scenarios.record.message_types import why_not
from haven_scenarios.record.outsiders import PublisherLog
from haven_scenarios.record.timeline import RECORDED, Recording
from haven_sim.common import topics
from haven_sim.common.component import Message
from haven_sim.common.events import EventError
from haven_sim.runtime import decode
from haven_viz.cues import CueState

TYPESTORE = get_typestore(Stores.ROS2_JAZZY)
T = TypeVar("T")
HEADER, TIME = "std_msgs/msg/Header", "builtin_interfaces/msg/Time"
LOST_KEY = "haven.messages_lost"  # custom_data in metadata.yaml: {topic: messages DDS reported lost}
WALL_CLOCK_KEY = "haven.wall_clock"  # custom_data: [[sim ns, wall ns (Unix epoch)], ...] paired about once a second
CHUNK_OPCODE = 0x06  # an MCAP chunk record
PUBLISHERS_KEY = "haven.publishers"  # custom_data: every publisher the recorder saw (record/outsiders.py PublisherLog)
NOT_RECORDED_KEY = "haven.not_recorded"  # custom_data: {topic: "type: why it could not be recorded"}
REPAIRED_KEY = "haven.repaired"  # custom_data of a bag rebuilt by record/repair.py: JSON, how and how much


class BagWriter:
    """A context manager: the bag is closed (metadata written) however the block ends."""

    def __init__(self, path: Path) -> None:
        self.path = path
        self._writer = Writer(path, version=9, storage_plugin=StoragePlugin.MCAP)
        self._connections: dict[str, Connection] = {}
        self._stamped: dict[str, bool] = {}  # the type starts with a stamp (a Header, or /clock's time)
        self.not_recorded: dict[str, str] = {}  # topic -> "type: why not" (kept in the metadata)
        self.counts: dict[str, int] = {}

    def __enter__(self) -> BagWriter:
        self._writer.open()
        return self

    def __exit__(self, et: type[BaseException] | None, ev: BaseException | None, tb: TracebackType | None) -> None:
        self.close()

    def close(
        self,
        lost: Mapping[str, int] | None = None,
        wall_clock: Sequence[tuple[int, int]] = (),
        publishers: str | None = None,
    ) -> None:
        """Close the bag; `lost`: messages per topic that never reached the recorder, kept in the
        metadata's custom_data (LOST_KEY) so the session can say how complete it is; `wall_clock`:
        (sim ns, wall ns) pairs (WALL_CLOCK_KEY), to align the bag with other recordings;
        `publishers`: who published what (PUBLISHERS_KEY, a `PublisherLog` as JSON)."""
        if self._writer is not None:
            if lost is not None:
                self._writer.set_custom_data(LOST_KEY, json.dumps(dict(lost), sort_keys=True))
            if wall_clock:
                self._writer.set_custom_data(WALL_CLOCK_KEY, json.dumps([list(p) for p in wall_clock]))
            if publishers is not None:
                self._writer.set_custom_data(PUBLISHERS_KEY, publishers)
            if self.not_recorded:
                self._writer.set_custom_data(NOT_RECORDED_KEY, json.dumps(self.not_recorded, sort_keys=True))
            self._writer.close()
            self._writer = None  # type: ignore[assignment]

    def flush(self) -> None:
        """Write the messages held in memory to the file as a complete MCAP chunk, so that a
        recorder killed now loses nothing written before (rosbags keeps up to 1 MiB in memory)."""
        storage = self._writer.storage if self._writer is not None else None
        if isinstance(storage, McapWriter) and storage.chunk.msgs:
            storage.close_chunk()
            storage.bio.flush()

    def abort(self) -> None:
        """Give up the bag without its footer or metadata.yaml (the disk is full): the file is
        closed as far as it was written; `record.repair` rebuilds a bag from it."""
        if self._writer is not None:
            writer, self._writer = self._writer, None  # type: ignore[assignment]
            with contextlib.suppress(OSError):  # (the buffered rest could not be written either; the file is closed)
                writer.abort()

    def has_topic(self, topic: str) -> bool:
        return topic in self._connections

    def add_topic(self, topic: str, msgtype: str, offered_qos: Sequence[Qos] = ()) -> bool:
        """Register a topic with the QoS its publishers offer (what `ros2 bag play` republishes with);
        a type the typestore does not know is taken from its installed package
        (record/message_types.py); False (and why, in `not_recorded`) when it cannot be."""
        if topic in self._connections:
            return True
        if topic in self.not_recorded:
            return False
        why = why_not(TYPESTORE, msgtype)
        if why is not None:
            self.not_recorded[topic] = why  # (it names the type it could not find: this one or one it uses)
            return False
        self._connections[topic] = self._writer.add_connection(
            topic, msgtype, typestore=TYPESTORE, offered_qos_profiles=offered_qos
        )
        fields = TYPESTORE.fielddefs[msgtype][1]
        self._stamped[topic] = bool(fields) and fields[0][1][1] in (HEADER, TIME)
        self.counts[topic] = 0
        return True

    def write(self, topic: str, received_ns: int, data: bytes) -> None:
        """One message: logged at its own stamp where it has one (not zero), else at `received_ns`."""
        stamp = own_stamp(data) if self._stamped[topic] else 0
        self._writer.write(self._connections[topic], stamp or received_ns, data)
        self.counts[topic] += 1


def own_stamp(cdr: bytes) -> int:
    """The nanoseconds of the Time a CDR message starts with (after the 4-byte encapsulation: little
    endian when its second byte is 1); 0 when there is none to read."""
    if len(cdr) < 12:
        return 0
    sec, nsec = struct.unpack_from("<iI" if cdr[1] == 1 else ">iI", cdr, 4)
    return max(0, sec * 1_000_000_000 + nsec) if nsec < 1_000_000_000 else 0


def _message(topic: str, msg: Any, human_ids: Sequence[str]) -> Message:
    """A recorded message as the core payload the components and metrics use (the nodes' own
    decoder, haven_sim.runtime.decode), with its own stamp (the header's, or the event's or cue
    state's)."""
    if topic == topics.ODOM:
        return Message(topic, decode.odometry_from_msg(msg), decode.stamp_of(msg))
    if topic == topics.HUMANS:
        return Message(topic, decode.humans_from_msg(msg, human_ids), decode.stamp_of(msg))
    if topic == topics.BATTERY:
        return Message(topic, decode.battery_from_msg(msg), decode.stamp_of(msg))
    if topic == topics.PLAN:
        return Message(topic, decode.path_from_msg(msg), decode.stamp_of(msg))
    if topic == topics.GOAL:
        return Message(topic, decode.goal_from_msg(msg), decode.stamp_of(msg))
    if topic == topics.CUE_STATE:
        stamp, state = CueState.from_json(msg.data)
        return Message(topic, state, stamp)
    e = decode.event_from_msg(msg)
    return Message(topic, e, e.stamp)


READ = {"/" + t: t for t in RECORDED}


def read_messages(bag: Path, human_ids: Sequence[str] = ()) -> Iterator[Message]:
    """The trial's messages in bag order; recorded strings that are not valid events are skipped."""
    with AnyReader([bag], default_typestore=TYPESTORE) as reader:
        connections = [c for c in reader.connections if c.topic in READ]
        if not connections:  # (an empty list would mean every connection)
            return
        for conn, _, raw in reader.messages(connections=connections):
            try:
                yield _message(READ[conn.topic], reader.deserialize(raw, conn.msgtype), human_ids)
            except (EventError, ValueError):
                continue


@dataclass(frozen=True)
class RecoveredChannel:
    """A channel of an MCAP file as its records say: what a repaired bag needs to register it."""

    topic: str
    msgtype: str
    schema_encoding: str  # ros2msg or ros2idl
    msgdef: str  # the message definition (with its dependencies), as recorded
    message_encoding: str  # cdr
    offered_qos: str  # the channel's offered_qos_profiles (YAML), as recorded


STREAM_ERRORS = (McapError, EOFError, ValueError, struct.error)  # what reading a cut MCAP file raises


def _cut_chunk(rest: bytes) -> Iterator[McapRecord]:
    """The whole records at the start of a chunk cut short by the end of the file (rosbags writes
    chunks uncompressed, so they can be read up to the cut)."""
    if len(rest) < 9 or rest[0] != CHUNK_OPCODE:
        return
    try:
        off = 9 + 8 + 8 + 8 + 4  # opcode, length; message start and end time, uncompressed size, crc
        (n,) = struct.unpack_from("<I", rest, off)
        if n != 0:  # compressed ("zstd", "lz4"): nothing readable before the chunk's end
            return
        off += 4 + 8  # the compression string (empty) and the records' length
        yield from StreamReader(BytesIO(rest[off:]), skip_magic=True).records
    except STREAM_ERRORS:
        return


def _stream(f: BinaryIO) -> Iterator[McapRecord]:
    """Every record of an MCAP file as a stream (the records inside chunks unpacked), up to where
    the data ends, including the whole records of a chunk the end cuts short."""
    end = f.tell()
    try:
        for record in StreamReader(f, skip_magic=False).records:
            yield record
            end = f.tell()  # (records of a chunk come once the whole chunk has been read)
        return
    except STREAM_ERRORS:
        pass
    f.seek(end)
    yield from _cut_chunk(f.read())


def recovered_records(path: Path) -> Iterator[tuple[RecoveredChannel, int, bytes]]:
    """(channel, log time ns, CDR bytes) of every message one MCAP file still holds, read as a
    stream: what a recorder killed before it wrote its footer (or metadata.yaml) leaves readable.
    Stops quietly where the data ends (a cut file: every whole message before the cut is yielded)."""
    with path.open("rb") as f:
        schemas: dict[int, McapSchema] = {}
        channels: dict[int, RecoveredChannel] = {}
        for record in _stream(f):
            if isinstance(record, McapSchema):
                schemas[record.id] = record
            elif isinstance(record, McapChannel) and record.schema_id in schemas:
                schema = schemas[record.schema_id]
                text = schema.data.decode("utf-8", errors="replace")
                channels[record.id] = RecoveredChannel(
                    record.topic,
                    schema.name,
                    schema.encoding,
                    text,
                    record.message_encoding,
                    record.metadata.get("offered_qos_profiles", ""),
                )
            elif isinstance(record, McapMessage) and record.channel_id in channels:
                yield channels[record.channel_id], record.log_time, bytes(record.data)


def recovered_messages(bag: Path) -> Iterator[tuple[str, str, int, bytes]]:
    """(topic, type name, log time ns, CDR bytes) of every message the MCAP files of a bag still hold."""
    for path in sorted(bag.glob("*.mcap")):
        for channel, stamp, data in recovered_records(path):
            yield channel.topic, channel.msgtype, stamp, data


def readable(bag: Path) -> bool:
    """A complete bag: metadata.yaml and MCAP files that rosbags opens."""
    try:
        with AnyReader([bag], default_typestore=TYPESTORE):
            return True
    except Exception:
        return False


def custom_data(bag: Path) -> dict[str, str]:
    try:
        info = yaml.safe_load((bag / "metadata.yaml").read_text())["rosbag2_bagfile_information"]
        return {str(k): str(v) for k, v in (info.get("custom_data") or {}).items()}
    except (OSError, KeyError, TypeError, AttributeError, yaml.YAMLError):
        return {}


def wall_clock(bag: Path) -> list[tuple[int, int]]:
    """The recorder's (sim ns, wall ns) pairs, in order ([] for a bag without them)."""
    try:
        return [(int(a), int(b)) for a, b in json.loads(custom_data(bag).get(WALL_CLOCK_KEY, "[]"))]
    except (TypeError, ValueError):
        return []


def to_wall_time(pairs: Sequence[tuple[int, int]], sim_s: float) -> float | None:
    """The Unix time (s) at sim time `sim_s`, interpolated between the recorder's pairs (beyond
    them, extrapolated at the pace of the nearest two); None without pairs."""
    if not pairs:
        return None
    sim = np.array([p[0] for p in pairs], dtype=float) * 1e-9
    wall = np.array([p[1] for p in pairs], dtype=float) * 1e-9
    if len(pairs) == 1:
        return float(wall[0] + (sim_s - sim[0]))
    if sim_s <= sim[0] or sim_s >= sim[-1]:
        a, b = (0, 1) if sim_s <= sim[0] else (-2, -1)
        pace = (wall[b] - wall[a]) / (sim[b] - sim[a])
        return float(wall[a] + (sim_s - sim[a]) * pace)
    return float(np.interp(sim_s, sim, wall))


def _kept(bag: Path, key: str, kind: Callable[[Any], T]) -> dict[str, T]:
    """A {topic: value} mapping the recorder kept in metadata.yaml's custom_data ({} if none or unreadable)."""
    try:
        kept = json.loads(custom_data(bag).get(key, "{}"))
        return {str(k): kind(v) for k, v in kept.items()}
    except (TypeError, ValueError, AttributeError):
        return {}


def lost_messages(bag: Path) -> dict[str, int]:
    """What the recorder noted as lost per topic."""
    return _kept(bag, LOST_KEY, int)


def not_recorded(bag: Path) -> dict[str, str]:
    """The topics the recorder saw but could not record, and why."""
    return _kept(bag, NOT_RECORDED_KEY, str)


def repaired_note(bag: Path) -> str:
    """The validity reason of a bag rebuilt by `haven repair` (or at the end of `haven run`): ""
    for a bag its recorder closed."""
    text = custom_data(bag).get(REPAIRED_KEY)
    if text is None:
        return ""
    try:
        info = json.loads(text)
        n = int(info["messages"])
    except (TypeError, ValueError, KeyError):
        return "bag repaired (its recorder did not close it)"
    return f"bag repaired: its recorder did not close it; {n} messages recovered from the MCAP data, the rest is lost"


def read_recording(bag: Path, human_ids: Sequence[str] = ()) -> tuple[Recording, str]:
    """The recording, and a note when it had to be recovered from a damaged bag or was repaired
    ("" if neither: a bag its recorder closed)."""
    rec = Recording()
    try:  # (opened once: rosbags parses metadata.yaml and the MCAP index each time, a second on a busy machine)
        for m in read_messages(bag, human_ids):
            rec.add(m)
    except Exception:
        rec = Recording()
    else:
        rec.lost = lost_messages(bag)
        logged = custom_data(bag).get(PUBLISHERS_KEY)
        rec.publishers = PublisherLog.from_json(logged) if logged is not None else None
        return rec, repaired_note(bag)
    if not any(bag.glob("*.mcap")):
        return rec, f"no recording: {bag} holds no MCAP file"
    n = 0
    for topic, msgtype, _, data in recovered_messages(bag):
        name = READ.get(topic)
        if name is None or msgtype not in TYPESTORE.types:
            continue
        try:
            rec.add(_message(name, TYPESTORE.deserialize_cdr(data, msgtype), human_ids))
            n += 1
        except Exception:
            continue
    return (
        rec,
        f"bag recovered from its MCAP data ({n} messages read; metadata or footer missing: `haven repair` rebuilds it)",
    )
