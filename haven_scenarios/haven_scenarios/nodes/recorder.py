"""Session recorder: every topic of the graph into a rosbag2 bag (MCAP, metadata version 9), and
/haven/events also line by line into events.jsonl, so nothing is lost if the run is cut short.

Messages are subscribed raw (CDR bytes, no Python conversion) and stamped with the receive time in
sim time. The bag is closed properly on Ctrl-C or SIGTERM.
"""

from __future__ import annotations

import sys
from pathlib import Path

from rclpy.node import Node
from rclpy.serialization import deserialize_message
from std_msgs.msg import String

from haven_scenarios.nodes.raw_topics import RawTopics
from haven_scenarios.record.bag import BagWriter
from haven_sim.nodes import conversions as conv
from haven_sim.nodes.runner import run_node


class Recorder(Node):
    def __init__(self) -> None:
        super().__init__("recorder")
        folder = Path(self.declare_parameter("session_dir", "session").value)
        folder.mkdir(parents=True, exist_ok=True)
        self.bag = BagWriter(folder / "bag")
        self.bag.__enter__()
        self.events = (folder / "events.jsonl").open("a", encoding="utf-8")
        self.topics = RawTopics(self, self._add, self._on_message)

    def _add(self, topic: str, msgtype: str, latched: bool) -> bool:
        if self.bag.add_topic(topic, msgtype):
            return True
        self.get_logger().warning(f"not recording {topic}: type {msgtype} unknown to rosbags")
        return False

    def _on_message(self, topic: str, data: bytes) -> None:
        self.bag.write(topic, self.get_clock().now().nanoseconds, data)
        if topic == "/haven/events":
            try:
                event = conv.event_from_msg(deserialize_message(data, String))
            except ValueError as e:  # kept in the bag as received; left out of events.jsonl
                self.get_logger().warning(f"not an event on /haven/events: {e}", throttle_duration_sec=5.0)
                return
            self.events.write(event.to_json() + "\n")
            self.events.flush()

    def destroy_node(self) -> None:
        self.bag.close()
        self.events.close()
        super().destroy_node()


def main(args: list[str] | None = None) -> None:
    sys.exit(run_node(Recorder, args))


if __name__ == "__main__":
    main()
