"""Raw (CDR bytes) subscriptions to every topic of the graph, for the recorder and the bridge.

The suite's own topics are subscribed at once with the topic table's QoS, so that nothing published
right after start-up is missed; other topics are found through the graph API once a second and
subscribed with the durability and reliability their publishers offer.
"""

from __future__ import annotations

import functools
import importlib
from collections.abc import Callable
from typing import Any

from rclpy.clock import Clock, ClockType
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy

from haven_sim.nodes import qos

KNOWN = [
    ("/clock", "rosgraph_msgs/msg/Clock", qos.CLOCK),
    ("/map", "nav_msgs/msg/OccupancyGrid", qos.LATCHED),
    ("/odom", "nav_msgs/msg/Odometry", qos.RELIABLE),
    ("/tf", "tf2_msgs/msg/TFMessage", qos.TF),
    ("/tf_static", "tf2_msgs/msg/TFMessage", qos.LATCHED),
    ("/scan", "sensor_msgs/msg/LaserScan", qos.SENSOR),
    ("/battery_state", "sensor_msgs/msg/BatteryState", qos.RELIABLE),
    ("/humans", "geometry_msgs/msg/PoseArray", qos.RELIABLE),
    ("/cmd_vel", "geometry_msgs/msg/Twist", qos.RELIABLE),
    ("/goal_pose", "geometry_msgs/msg/PoseStamped", qos.RELIABLE),
    ("/plan", "nav_msgs/msg/Path", qos.LATCHED),
    ("/haven/wait", "std_msgs/msg/Bool", qos.LATCHED),
    ("/haven/thought", "std_msgs/msg/String", qos.LATCHED),
    ("/haven/events", "std_msgs/msg/String", qos.EVENTS_HISTORY),
    ("/haven/ar_markers", "visualization_msgs/msg/MarkerArray", qos.RELIABLE),
    ("/haven/world_markers", "visualization_msgs/msg/MarkerArray", qos.LATCHED),
]
IGNORED = ("/rosout", "/parameter_events")

# add(topic, type name, latched) -> whether to subscribe; on_message(topic, cdr bytes)
AddTopic = Callable[[str, str, bool], bool]
OnMessage = Callable[[str, bytes], None]


def message_class(type_name: str) -> Any:
    """The rclpy message class of a type name like 'nav_msgs/msg/Odometry'."""
    package, kind, cls = type_name.split("/")
    return getattr(importlib.import_module(f"{package}.{kind}"), cls)


def matching_qos(node: Node, topic: str, depth: int = 100) -> QoSProfile:
    """The QoS that matches what a topic's publishers offer (latched topics need transient local to
    be seen late; a best-effort publisher needs a best-effort subscriber)."""
    infos = node.get_publishers_info_by_topic(topic)
    latched = bool(infos) and all(i.qos_profile.durability == DurabilityPolicy.TRANSIENT_LOCAL for i in infos)
    best_effort = any(i.qos_profile.reliability == ReliabilityPolicy.BEST_EFFORT for i in infos)
    return QoSProfile(
        depth=depth,
        history=HistoryPolicy.KEEP_LAST,
        reliability=ReliabilityPolicy.BEST_EFFORT if best_effort else ReliabilityPolicy.RELIABLE,
        durability=DurabilityPolicy.TRANSIENT_LOCAL if latched else DurabilityPolicy.VOLATILE,
    )


class RawTopics:
    def __init__(self, node: Node, add: AddTopic, on_message: OnMessage, topics: list[str] | None = None) -> None:
        """`topics`: only these (all of the graph when None)."""
        self.node, self.add, self.on_message, self.only = node, add, on_message, topics
        self.handled: set[str] = set()
        for topic, msgtype, profile in KNOWN:
            if self._wanted(topic):
                self._subscribe(topic, msgtype, profile)
        # Wall clock: topics must be found even before /clock runs.
        node.create_timer(1.0, self.discover, clock=Clock(clock_type=ClockType.STEADY_TIME))
        self.discover()

    def _wanted(self, topic: str) -> bool:
        return topic not in IGNORED and not topic.startswith(IGNORED) and (self.only is None or topic in self.only)

    def discover(self) -> None:
        for topic, types in self.node.get_topic_names_and_types():
            if topic in self.handled or not self._wanted(topic) or self.node.count_publishers(topic) == 0:
                continue
            self._subscribe(topic, types[0], matching_qos(self.node, topic))

    def _subscribe(self, topic: str, msgtype: str, profile: QoSProfile) -> None:
        self.handled.add(topic)
        try:
            cls = message_class(msgtype)
        except (ImportError, AttributeError):  # e.g. tf2_msgs where the pip setup could not build it
            return
        if not self.add(topic, msgtype, profile.durability == DurabilityPolicy.TRANSIENT_LOCAL):
            return
        self.node.create_subscription(cls, topic, functools.partial(self.on_message, topic), profile, raw=True)
