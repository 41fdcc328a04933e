"""`haven bridge`: relays the suite's ROS topics (default: every topic of the graph) to a Foxglove
WebSocket server, bound to 127.0.0.1 unless told otherwise, so a browser viewer can watch a trial
live (Foxglove: Open connection -> Foxglove WebSocket -> ws://localhost:8765).

It advertises what the shipped layout uses: Parameters (the viz node's four cue toggles, named
'/viz.<cue>' as Foxglove's ROS bridge names node parameters, for the Parameters panel), client
publishing on an allow-list only (ALLOWED: a goal from the 3D panel, teleop, the e-stop; anything
else is refused with a status message), and Time (the suite's /clock, so panels follow sim time).
It is our relay, not the foxglove_bridge package: it runs where that C++ package is not installed.
"""

from __future__ import annotations

import sys
import time

from rclpy.node import Node
from rosgraph_msgs.msg import Clock

from haven_scenarios.nodes.cue_parameters import CueParameters
from haven_scenarios.nodes.raw_topics import RawTopics
from haven_scenarios.nodes.role_sink import RoleSink, TablePublishers
from haven_scenarios.web.access import Role, absolute
from haven_scenarios.web.foxglove_relay import FoxgloveRelay
from haven_sim.common import nodes, topics
from haven_sim.common.params import build, defaults
from haven_sim.common.topics import WireParams
from haven_sim.nodes import qos, wire
from haven_sim.nodes.runner import declare, run_node

ALLOWED = (topics.GOAL, topics.CMD_VEL_TELEOP, topics.ESTOP)  # what Foxglove clients may publish
TIME_PERIOD_S = 0.05  # the server's time is broadcast at most this often (wall time)


class Bridge(Node):
    def __init__(self) -> None:
        super().__init__(nodes.BRIDGE.name)
        host = declare(self, "host", "127.0.0.1")
        port = declare(self, "port", 8765)
        only = list(declare(self, "topics", []))
        params = build(
            WireParams, {n: declare(self, n, d) for n, d in defaults(WireParams).items()}, where="bridge: parameter "
        )
        self.table = wire.with_wire_params(wire.specs(), params)
        self.publisher = TablePublishers(self, self.table)
        role = Role("foxglove", {absolute(t): wire.type_name(self.table[t].msg_type) for t in ALLOWED}, parameters=True)
        self.relay = FoxgloveRelay()
        sink = RoleSink(self, role, self.forward, CueParameters(self), "a Foxglove client")
        self.relay.serve(host, port, "haven bridge", sink, parameters=True, time=True)
        self.topics = RawTopics(
            self, self.relay.add_topic, self._on_message, [t for t in only if t] or None, params=params
        )
        self._time_sent = 0.0
        self.create_subscription(Clock, topics.CLOCK, self._on_clock, qos.CLOCK)
        print(f"bridge: Foxglove WebSocket on ws://{host}:{self.relay.port}", flush=True)

    def forward(self, topic: str, data: bytes) -> None:
        """A client's message on the allow-list: its CDR bytes as they came, with the topic table's QoS."""
        self.publisher(topic).publish(data)

    def _on_message(self, topic: str, msgtype: str, data: bytes) -> None:
        self.relay.publish(topic, data, time.time_ns())

    def _on_clock(self, msg: Clock) -> None:
        now = time.monotonic()
        if now - self._time_sent >= TIME_PERIOD_S:
            self._time_sent = now
            self.relay.broadcast_time(msg.clock.sec * 1_000_000_000 + msg.clock.nanosec)

    def destroy_node(self) -> None:
        self.relay.stop()
        super().destroy_node()


def main(args: list[str] | None = None) -> None:
    sys.exit(run_node(Bridge, args))


if __name__ == "__main__":
    main()
