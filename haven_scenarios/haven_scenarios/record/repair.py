"""Repairing a bag its recorder never closed (killed, or stopped by a full disk).

Such a bag has MCAP chunks but no footer, no summary and no metadata.yaml, so rosbag2 tools and
rosbags refuse it. Every chunk written before the recorder died still holds its messages, with the
schemas and channels (and their offered QoS) that came first. `repair` reads them as a stream and
writes a proper rosbag2 bag (metadata version 9, an MCAP file with its summary and footer) with the
same topics, message types, QoS and messages, in the order they were recorded; metadata.yaml's
custom_data (REPAIRED_KEY) says it was repaired and how many messages were recovered.

Nothing is lost on the way: the new bag is written beside the old files first; only when it is
complete are the damaged files renamed (`bag.mcap` -> `bag.mcap.damaged`, a stale metadata.yaml ->
`metadata.yaml.damaged`) and the new ones moved in. A full disk during the repair leaves the
damaged recording exactly as it was.
"""

from __future__ import annotations

import json
import shutil
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

from mcap.reader import make_reader
from rosbags.interfaces import Connection
from rosbags.rosbag2 import StoragePlugin, Writer
from rosbags.rosbag2.metadata import parse_qos
from rosbags.typesys import Stores, get_typestore
from rosbags.typesys.msg import get_types_from_msg

from haven_scenarios.record.bag import (
    REPAIRED_KEY,
    TYPESTORE,
    RecoveredChannel,
    custom_data,
    readable,
    recovered_records,
)

DAMAGED = ".damaged"  # suffix of the damaged originals kept beside the repaired bag
WORK = ".repairing"  # the new bag is written here first (inside the bag folder)
METADATA = "metadata.yaml"


class RepairError(Exception):
    """A bag that could not be repaired; the message is one line and names the bag."""


@dataclass(frozen=True)
class Repaired:
    bag: Path
    messages: int
    topics: int
    kept: tuple[Path, ...]  # the damaged originals, renamed
    skipped: dict[str, int] = field(default_factory=dict)  # topic -> messages of a type that could not be registered

    def line(self) -> str:
        kept = ", ".join(p.name for p in self.kept)
        skipped = (
            f"; left out {sum(self.skipped.values())} of unknown type ({', '.join(sorted(self.skipped))})"
            if self.skipped
            else ""
        )
        return (
            f"repaired {self.bag}: {self.messages} messages on {self.topics} "
            f"topics recovered{skipped}; the damaged original kept as {kept}"
        )


def _has_summary(path: Path) -> bool:
    try:
        with path.open("rb") as f:
            return make_reader(f).get_summary() is not None
    except Exception:
        return False


def _sources(bag: Path) -> list[Path]:
    """The MCAP files to recover from: the bag's own, or the damaged originals of a repair that
    was itself cut short before it moved the new bag in."""
    files = sorted(bag.glob("*.mcap"))
    if files:
        return files
    return sorted(bag.glob(f"*.mcap{DAMAGED}")) if not (bag / METADATA).exists() else []


def needs_repair(bag: Path) -> bool:
    """A bag folder with MCAP data that is not a complete bag: no metadata.yaml, or an MCAP file
    without its summary and footer."""
    files = _sources(bag)
    if not files:
        return False
    if not (bag / METADATA).is_file() or any(p.suffix != ".mcap" for p in files):
        return True
    return not all(_has_summary(p) for p in files) or not readable(bag)


def _connection(writer: Writer, channel: RecoveredChannel) -> Connection:
    """Register a recovered channel: its type from this ROS distribution's typestore, or else from
    the definition recorded in the MCAP schema; its offered QoS as recorded."""
    qos = parse_qos(channel.offered_qos)
    if channel.msgtype in TYPESTORE.types:
        return writer.add_connection(
            channel.topic,
            channel.msgtype,
            typestore=TYPESTORE,
            serialization_format=channel.message_encoding,
            offered_qos_profiles=qos,
        )
    if channel.schema_encoding != "ros2msg":
        raise ValueError(f"schema encoding {channel.schema_encoding}")
    store = get_typestore(Stores.EMPTY)
    store.register(get_types_from_msg(channel.msgdef, channel.msgtype))
    return writer.add_connection(
        channel.topic,
        channel.msgtype,
        msgdef=channel.msgdef,
        rihs01=store.hash_rihs01(channel.msgtype),
        serialization_format=channel.message_encoding,
        offered_qos_profiles=qos,
    )


def _rewrite(
    sources: Sequence[Path], out: Path, kept_custom: dict[str, str], how: str
) -> tuple[int, int, dict[str, int]]:
    """A new bag at `out` with every message the sources still hold: (messages, topics, skipped)."""
    writer = Writer(out, version=9, storage_plugin=StoragePlugin.MCAP)
    writer.open()
    connections: dict[RecoveredChannel, Connection | None] = {}
    n, skipped = 0, dict[str, int]()
    try:
        for path in sources:
            for channel, stamp, data in recovered_records(path):
                if channel not in connections:
                    try:
                        connections[channel] = _connection(writer, channel)
                    except Exception:
                        connections[channel] = None
                conn = connections[channel]
                if conn is None:
                    skipped[channel.topic] = skipped.get(channel.topic, 0) + 1
                    continue
                writer.write(conn, stamp, data)
                n += 1
        for key, value in kept_custom.items():
            writer.set_custom_data(key, value)
        info = {"messages": n, "from": [p.name for p in sources], "how": how, "skipped": skipped}
        writer.set_custom_data(REPAIRED_KEY, json.dumps(info, sort_keys=True))
        writer.close()
    except BaseException:
        writer.abort()
        raise
    return n, len({c.topic for c, conn in connections.items() if conn is not None}), skipped


def _keep(path: Path) -> Path:
    """Rename a damaged original out of the way (`X` -> `X.damaged`, never over another)."""
    if path.name.endswith(DAMAGED):
        return path
    target, i = path.with_name(path.name + DAMAGED), 1
    while target.exists():
        i += 1
        target = path.with_name(f"{path.name}{DAMAGED}{i}")
    path.rename(target)
    return target


def repair(bag: Path, how: str = "haven repair") -> Repaired:
    """Rebuild `bag` (a rosbag2 folder) from the MCAP data it still holds; RepairError if it
    cannot (the damaged files are then left as they were)."""
    sources = _sources(bag)
    if not sources:
        raise RepairError(f"{bag}: no MCAP file to repair")
    stale = bag / METADATA
    kept_custom = {k: v for k, v in custom_data(bag).items() if k != REPAIRED_KEY} if stale.exists() else {}
    work = bag / WORK
    shutil.rmtree(work, ignore_errors=True)
    try:
        work.mkdir()
        n, topics, skipped = _rewrite(sources, work / bag.name, kept_custom, how)
    except OSError as e:
        shutil.rmtree(work, ignore_errors=True)
        raise RepairError(
            f"{bag}: could not write the repaired bag: {e.strerror or e}; the damaged recording is left as it was"
        ) from None
    kept = [_keep(p) for p in sources]
    if stale.exists():
        kept.append(_keep(stale))
    for made in sorted((work / bag.name).iterdir()):
        made.rename(bag / made.name)
    shutil.rmtree(work, ignore_errors=True)
    return Repaired(bag, n, topics, tuple(kept), skipped)
