"""Session recorder: every topic of the graph into a rosbag2 bag (MCAP, metadata version 9), and
/haven/events also line by line into events.jsonl, so nothing is lost if the run is cut short.

Topics are discovered through the rclpy graph API once a second and subscribed raw (CDR bytes, no
Python conversion), with the durability and reliability their publishers offer. Messages are
stamped with the receive time in sim time. The bag is closed properly on Ctrl-C or SIGTERM.
"""

from __future__ import annotations

import importlib
import json
import sys
from pathlib import Path
from typing import Any

from rclpy.clock import Clock, ClockType
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy
from rclpy.serialization import deserialize_message
from std_msgs.msg import String

from haven_scenarios.bag import BagWriter
from haven_sim.nodes import conversions as conv
from haven_sim.nodes import qos
from haven_sim.nodes.runner import run_node


KNOWN = [
    ("/clock", "rosgraph_msgs/msg/Clock", qos.CLOCK),
    ("/map", "nav_msgs/msg/OccupancyGrid", qos.LATCHED),
    ("/odom", "nav_msgs/msg/Odometry", qos.RELIABLE),
    ("/scan", "sensor_msgs/msg/LaserScan", qos.SENSOR),
    ("/battery_state", "sensor_msgs/msg/BatteryState", qos.RELIABLE),
    ("/humans", "geometry_msgs/msg/PoseArray", qos.RELIABLE),
    ("/cmd_vel", "geometry_msgs/msg/Twist", qos.RELIABLE),
    ("/goal_pose", "geometry_msgs/msg/PoseStamped", qos.RELIABLE),
    ("/plan", "nav_msgs/msg/Path", qos.LATCHED),
    ("/haven/wait", "std_msgs/msg/Bool", qos.LATCHED),
    ("/haven/thought", "std_msgs/msg/String", qos.LATCHED),
    ("/haven/events", "std_msgs/msg/String", qos.EVENTS),
    ("/haven/ar_markers", "visualization_msgs/msg/MarkerArray", qos.RELIABLE),
    ("/haven/world_markers", "visualization_msgs/msg/MarkerArray", qos.LATCHED),
]


class Recorder(Node):
    def __init__(self) -> None:
        super().__init__("recorder")
        folder = Path(self.declare_parameter("session_dir", "session").value)
        folder.mkdir(parents=True, exist_ok=True)
        self.bag = BagWriter(folder / "bag")
        self.bag.__enter__()
        self.events = (folder / "events.jsonl").open("a", encoding="utf-8")
        self.skipped: set[str] = set()
        # The suite's own topics are subscribed at once (with the topic table's QoS), so that nothing
        # published right after start-up is missed; anything else is found by discovery.
        for topic, msgtype, profile in KNOWN:
            self._subscribe(topic, msgtype, profile)
        # Wall clock: topics must be found even before /clock runs.
        self.create_timer(1.0, self._discover, clock=Clock(clock_type=ClockType.STEADY_TIME))
        self._discover()

    def _qos(self, topic: str) -> QoSProfile:
        infos = self.get_publishers_info_by_topic(topic)
        latched = bool(infos) and all(i.qos_profile.durability == DurabilityPolicy.TRANSIENT_LOCAL for i in infos)
        best_effort = any(i.qos_profile.reliability == ReliabilityPolicy.BEST_EFFORT for i in infos)
        return QoSProfile(
            depth=100,
            history=HistoryPolicy.KEEP_LAST,
            reliability=ReliabilityPolicy.BEST_EFFORT if best_effort else ReliabilityPolicy.RELIABLE,
            durability=DurabilityPolicy.TRANSIENT_LOCAL if latched else DurabilityPolicy.VOLATILE,
        )

    def _discover(self) -> None:
        for topic, types in self.get_topic_names_and_types():
            if self.bag.knows(topic) or topic in self.skipped or self.count_publishers(topic) == 0:
                continue
            if topic.startswith("/parameter_events") or topic == "/rosout":
                self.skipped.add(topic)
                continue
            self._subscribe(topic, types[0], self._qos(topic))

    def _subscribe(self, topic: str, msgtype: str, profile: QoSProfile) -> None:
        if not self.bag.add_topic(topic, msgtype):
            self.skipped.add(topic)
            self.get_logger().warning(f"not recording {topic}: type {msgtype} unknown to rosbags")
            return
        self.create_subscription(_any_type(msgtype), topic, lambda data, t=topic: self._on_message(t, data), profile, raw=True)

    def _on_message(self, topic: str, data: bytes) -> None:
        stamp = self.get_clock().now().nanoseconds
        self.bag.write(topic, stamp, data)
        if topic == "/haven/events":
            text = conv.event_from_msg(deserialize_message(data, String))
            self.events.write(json.dumps(text, sort_keys=True) + "\n")
            self.events.flush()

    def destroy_node(self) -> None:
        self.bag.close()
        self.events.close()
        super().destroy_node()


def _any_type(name: str) -> Any:
    """The rclpy message class of a type name like 'nav_msgs/msg/Odometry'."""
    package, kind, cls = name.split("/")
    return getattr(importlib.import_module(f"{package}.{kind}"), cls)


def main(args: list[str] | None = None) -> None:
    sys.exit(run_node(Recorder, args))


if __name__ == "__main__":
    main()
