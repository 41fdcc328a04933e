"""A Foxglove server's way in for one role (a participant page, the console, `haven bridge`'s
clients): what its clients may publish (the role's allow-list; anything else is refused, with a
warning here and a status message to the client), where accepted messages go, and the cue toggles
when the role may set them; and the publishers such messages go out on."""

from __future__ import annotations

import time
from collections.abc import Callable

from foxglove import Parameter as FoxgloveParameter
from rclpy.node import Node
from rclpy.publisher import Publisher

from haven_scenarios.nodes.cue_parameters import CueParameters
from haven_scenarios.web.access import Role
from haven_sim.nodes.wire import TopicSpec


class RoleSink:
    def __init__(
        self, node: Node, role: Role, forward: Callable[[str, bytes], None], cues: CueParameters, who: str
    ) -> None:
        """`forward(topic, cdr)`: an accepted message; `who`: how warnings name the client."""
        self.node, self.role, self.forward, self.cues, self.who = node, role, forward, cues, who

    def advertised(self, topic: str, schema_name: str) -> str | None:
        refused = self.role.may_publish(topic, schema_name)
        if refused:
            self.node.get_logger().warning(f"{self.who}: {refused}", throttle_duration_sec=5.0)
        return refused

    def refused_client(self, why: str) -> None:
        self.node.get_logger().warning(f"{self.who}: {why}", throttle_duration_sec=5.0)

    def message(self, topic: str, schema_name: str, data: bytes) -> None:
        self.forward(topic, data)

    def get_parameters(self, names: list[str]) -> list[FoxgloveParameter]:
        return self.cues.get(names) if self.role.parameters else []

    def set_parameters(self, parameters: list[FoxgloveParameter]) -> list[FoxgloveParameter]:
        return self.cues.set(parameters) if self.role.parameters else []


MATCH_WAIT_S = 1.0  # a new publisher waits this long at most for its readers


class TablePublishers:
    """Publishers made as clients first send on a topic, with the topic table's type and QoS. A new
    one waits (briefly) until it has matched the readers the graph already shows and at least one
    other node's, as `ros2 topic pub` waits for a matching subscription: a page's or Foxglove's first message (a goal, a
    Start) would otherwise go out before DDS has matched its readers, and a volatile reader never gets it. (Called from
    the Foxglove servers' threads, never the node's executor.)"""

    def __init__(self, node: Node, table: dict[str, TopicSpec]) -> None:
        self.node, self.table = node, table
        self.pubs: dict[str, Publisher] = {}

    def __call__(self, topic: str) -> Publisher:
        if topic not in self.pubs:
            spec = self.table[topic.lstrip("/")]
            pub = self.node.create_publisher(spec.msg_type, topic, spec.pub_qos)
            deadline = time.monotonic() + MATCH_WAIT_S
            while pub.get_subscription_count() < self._readers(topic) and time.monotonic() < deadline:
                time.sleep(0.01)
            self.pubs[topic] = pub
        return self.pubs[topic]

    def _readers(self, topic: str) -> int:
        """The readers to wait for: those the graph shows, and at least one that is not this node's
        own (a relay reads every topic; a reader seen by nobody yet is still being discovered)."""
        me = (self.node.get_name(), self.node.get_namespace())
        own = sum((i.node_name, i.node_namespace) == me for i in self.node.get_subscriptions_info_by_topic(topic))
        return max(self.node.count_subscribers(topic), own + 1)
