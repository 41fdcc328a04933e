"""Session player: a recorded bag back on the graph, as it was live (for installs without `ros2 bag
play`, which plays these bags too).

Each topic is published with the QoS its publishers offered (recorded on every MCAP channel, as
rosbag2 does): /tf_static, /map, /plan and the world markers are latched again, so RViz with the
shipped config or a Foxglove client that joins late gets them. The recorded /clock is played too, so
nodes on `use_sim_time` follow the session's time. Messages go out at their recorded (log) times,
`rate` times as fast; with `hold`, the player stays up after the end so the latched state remains.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

from rclpy.node import Node
from rclpy.publisher import Publisher
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy
from rosbags.highlevel import AnyReader
from rosbags.interfaces import Qos, QosDurability, QosReliability

from haven_scenarios.nodes.raw_topics import message_class
from haven_scenarios.record.bag import TYPESTORE
from haven_sim.nodes.runner import declare, run_node, stop_requested

LATCHED_DEPTH = 10  # rosbag2's depth for a replayed topic whose recorded history is unknown


def replay_qos(offered: list[Qos]) -> QoSProfile:
    """rosbag2's rule: the offered profile when every publisher offered the same reliability and
    durability, else a reliable volatile default."""
    same = offered and all(
        o.reliability == offered[0].reliability and o.durability == offered[0].durability for o in offered
    )
    latched = bool(same) and offered[0].durability == QosDurability.TRANSIENT_LOCAL
    best_effort = bool(same) and offered[0].reliability == QosReliability.BEST_EFFORT
    return QoSProfile(
        depth=LATCHED_DEPTH,
        history=HistoryPolicy.KEEP_LAST,
        reliability=ReliabilityPolicy.BEST_EFFORT if best_effort else ReliabilityPolicy.RELIABLE,
        durability=DurabilityPolicy.TRANSIENT_LOCAL if latched else DurabilityPolicy.VOLATILE,
    )


class Player(Node):
    def __init__(self) -> None:
        super().__init__("haven_player")
        self.bag = Path(declare(self, "bag", ""))
        self.rate = float(declare(self, "rate", 1.0))
        self.hold = bool(declare(self, "hold", False))
        if not self.rate > 0:
            raise ValueError(f"rate must be positive, got {self.rate}")
        if not (self.bag / "metadata.yaml").exists():
            raise ValueError(f"{self.bag}: no bag here (no metadata.yaml)")
        self.pubs: dict[str, Publisher] = {}
        self._start = self.create_timer(0.0, self.play)

    def play(self) -> None:
        """The whole bag, in this one callback (DDS serves late joiners their latched messages on
        its own threads meanwhile); then exit, or stay up with `hold`."""
        self._start.cancel()
        with AnyReader([self.bag], default_typestore=TYPESTORE) as reader:
            for c in reader.connections:
                try:
                    cls = message_class(c.msgtype)
                except (ImportError, AttributeError):
                    self.get_logger().warning(f"{c.topic}: type {c.msgtype} not installed; not played")
                    continue
                offered = list(getattr(c.ext, "offered_qos_profiles", []))  # (a rosbag1 connection has none)
                self.pubs[c.topic] = self.create_publisher(cls, c.topic, replay_qos(offered))
            self.get_logger().info(f"playing {self.bag} ({len(self.pubs)} topics) at {self.rate:g}x")
            first: int | None = None
            start = time.monotonic()
            for connection, log_ns, data in reader.messages(
                connections=[c for c in reader.connections if c.topic in self.pubs]
            ):
                first = log_ns if first is None else first
                due = start + (log_ns - first) * 1e-9 / self.rate
                while (wait := due - time.monotonic()) > 0 and not stop_requested():
                    time.sleep(min(wait, 0.1))
                if stop_requested():
                    return
                self.pubs[connection.topic].publish(data)  # the recorded CDR bytes as they were
        self.get_logger().info("end of the bag" + ("; holding the latched topics until Ctrl-C" if self.hold else ""))
        if not self.hold:
            raise SystemExit(0)


def main(args: list[str] | None = None) -> None:
    sys.exit(run_node(Player, args))


if __name__ == "__main__":
    main()
