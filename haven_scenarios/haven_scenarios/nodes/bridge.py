"""`haven bridge`: relays the suite's ROS topics (default: every topic of the graph) to a Foxglove
WebSocket server, bound to 127.0.0.1 unless told otherwise, so a browser viewer can watch a trial
live (Foxglove: Open connection -> Foxglove WebSocket -> ws://localhost:8765)."""

from __future__ import annotations

import sys
import time

from rclpy.node import Node

from haven_scenarios.nodes.raw_topics import RawTopics
from haven_scenarios.tools.foxglove_relay import FoxgloveRelay
from haven_sim.nodes.runner import run_node


class Bridge(Node):
    def __init__(self) -> None:
        super().__init__("foxglove_bridge")
        host = self.declare_parameter("host", "127.0.0.1").value
        port = self.declare_parameter("port", 8765).value
        topics = list(self.declare_parameter("topics", [""]).value)
        self.relay = FoxgloveRelay()
        self.relay.serve(host, port)
        self.topics = RawTopics(self, self.relay.add_topic, self._on_message, [t for t in topics if t] or None)
        print(f"bridge: Foxglove WebSocket on ws://{host}:{self.relay.port}", flush=True)

    def _on_message(self, topic: str, msgtype: str, data: bytes) -> None:
        self.relay.publish(topic, data, time.time_ns())

    def destroy_node(self) -> None:
        self.relay.stop()
        super().destroy_node()


def main(args: list[str] | None = None) -> None:
    sys.exit(run_node(Bridge, args))


if __name__ == "__main__":
    main()
