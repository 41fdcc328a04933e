"""Raw (CDR bytes) subscriptions to every topic of the graph, for the recorder and the bridge.

The suite's own topics are subscribed at once with the topic table's QoS, so that nothing published
right after start-up is missed; other topics are found through the graph API once a second and
subscribed with the durability and reliability their publishers offer.

A topic that others may publish either way (/plan: our planner latches it, Nav2's publishes it
volatile) is read volatile, which matches both. For a recorder (`catch_up`), a latched reader runs
beside it while every publisher there latches: a publisher's history (our planner keeps its last
100 plans) then reaches the recording even when its first messages went out before the readers
matched, whatever the start-up order. A message that both readers get is recorded once: its
publisher's timestamp and sequence number say it is the same.
"""

from __future__ import annotations

import functools
import importlib
import importlib.util
from collections import deque
from collections.abc import Callable
from typing import Any

from rclpy.callback_groups import CallbackGroup
from rclpy.clock import Clock, ClockType
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy
from rclpy.subscription import Subscription

from haven_sim.common.topics import WireParams
from haven_sim.nodes import qos, wire
from haven_sim.nodes.lockstep_inbox import take_all, take_all_with_info
from haven_sim.nodes.wire import type_name
from haven_viz.nodes.conversions import viz_specs

DEFAULT_WIRE_PARAMS = WireParams()  # the topic table's defaults (frozen, so one instance serves every call)


def known_topics(params: WireParams = DEFAULT_WIRE_PARAMS) -> list[tuple[str, str, QoSProfile, bool]]:
    """The suite's own topics from the topic table (type name, the QoS to read them with: what our
    publishers offer, or, where other nodes may publish with either durability (/plan from Nav2),
    volatile like our own readers, which matches both), and whether our publishers latch it."""
    table = wire.with_wire_params({**wire.specs(), **viz_specs()}, params)
    out = []
    for topic, spec in table.items():
        profile = spec.pub_qos
        if spec.sub_qos == qos.ANY_DURABILITY:  # /plan, /haven/estop: outsiders publish them volatile
            profile = QoSProfile(
                depth=profile.depth,
                history=profile.history,
                reliability=profile.reliability,
                durability=DurabilityPolicy.VOLATILE,
            )
        latched = spec.pub_qos.durability == DurabilityPolicy.TRANSIENT_LOCAL
        out.append(("/" + topic.lstrip("/"), type_name(spec.msg_type), profile, latched))
    return out


def _late_readable(params: WireParams) -> dict[str, QoSProfile]:
    """The suite's topics with a latched catch-up reader in the topic table (`late_qos`): its QoS."""
    table = wire.with_wire_params({**wire.specs(), **viz_specs()}, params)
    return {"/" + t.lstrip("/"): s.late_qos for t, s in table.items() if s.late_qos is not None}


DRAIN_PERIOD_S = 0.01  # batched readers are emptied this often (wall time)


class DrainedReaders(CallbackGroup):
    """Readers the executor never calls back: their owner empties them in batches (`drain`), which
    costs a fraction of a callback per message. Their event handlers (message lost) still run."""

    def can_execute(self, entity: Any) -> bool:
        return not isinstance(entity, Subscription)

    def beginning_execution(self, entity: Any) -> bool:
        return not isinstance(entity, Subscription)

    def ending_execution(self, entity: Any) -> None:
        pass


# logs, parameter changes, the lockstep clock's own traffic
IGNORED = ("/rosout", "/parameter_events", "/haven/lockstep/")


def hidden(topic: str) -> bool:
    """A hidden topic (a name part starting with "_": an action's feedback and status, a service's
    events; ROS 2 design, "Topic and Service name mapping to DDS": tools may leave them out), which
    `ros2 bag record` records only with --include-hidden-topics."""
    return any(part.startswith("_") for part in topic.split("/"))


# add(topic, type name, latched) -> whether to subscribe; on_message(topic, type name, cdr bytes)
AddTopic = Callable[[str, str, bool], bool]
OnMessage = Callable[[str, str, bytes], None]


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
    def __init__(
        self,
        node: Node,
        add: AddTopic,
        on_message: OnMessage,
        topics: list[str] | None = None,
        keep_all: bool = False,
        on_lost: Callable[[str, int, bool], None] | None = None,
        batched: bool = False,
        held: tuple[str, ...] = (),
        params: WireParams = DEFAULT_WIRE_PARAMS,
        on_matched: Callable[[str], None] | None = None,
        catch_up: bool = False,
        on_unreadable: Callable[[str, str, str], None] | None = None,
    ) -> None:
        """`topics`: only these (all of the graph when None); `keep_all`: readers that drop nothing
        (a recorder's), else the depth of the topic's profile; `on_lost(topic, n)`: DDS reports
        that n messages of a topic never reached the reader (and whether it is a best-effort topic); `batched`: messages
        are handed over every DRAIN_PERIOD_S instead of one callback each (a recorder at 10x real time gets thousands a
        second); `held`: suite topics not subscribed until `release()`; `params`: the topic table's (stamped velocity
        commands); `on_matched(topic)`: a publisher matched or left one of the readers (however briefly it lived);
        `catch_up`: latched readers beside the volatile ones where every publisher latches (batched mode);
        `on_unreadable(topic, type, why)`: a topic whose type cannot be read here (its package is not installed), said
        once."""
        self.node, self.add, self.on_message, self.only, self.keep_all, self.on_lost = (
            node,
            add,
            on_message,
            topics,
            keep_all,
            on_lost,
        )
        self.on_matched, self.on_unreadable = on_matched, on_unreadable
        self.late: dict[str, Subscription] = {}  # topic -> its latched catch-up reader, while it has one
        self.late_qos = _late_readable(params) if catch_up and batched else {}
        self.seen: dict[str, deque[tuple[int, int]]] = {t: deque(maxlen=1000) for t in self.late_qos}
        self.group = DrainedReaders() if batched else None
        self.handled: set[str] = set(held)
        known = known_topics(params)
        self.held = {topic: (msgtype, profile, latched) for topic, msgtype, profile, latched in known if topic in held}
        self.subscriptions: dict[str, tuple[str, Subscription]] = {}  # topic -> (type name, subscription)
        for topic, msgtype, profile, latched in known:
            if self._wanted(topic) and topic not in held:
                self._subscribe(topic, msgtype, profile, latched)
        # Wall clock: topics must be found even before /clock runs.
        node.create_timer(1.0, self.discover, clock=Clock(clock_type=ClockType.STEADY_TIME))
        if batched:
            node.create_timer(DRAIN_PERIOD_S, self.drain, clock=Clock(clock_type=ClockType.STEADY_TIME))
        self.discover()

    def drain(self) -> None:
        """Hand over every message the readers hold (in batched mode; at shutdown in any)."""
        for topic, (msgtype, sub) in list(self.subscriptions.items()):
            if topic in self.seen:  # read by two readers: each message once
                for data in self._once(
                    topic, [take_all_with_info(sub), take_all_with_info(self.late[topic]) if topic in self.late else []]
                ):
                    self.on_message(topic, msgtype, data)
                continue
            for data in take_all(sub):
                self.on_message(topic, msgtype, data)

    def _once(self, topic: str, batches: list[list[tuple[bytes, dict[str, Any]]]]) -> list[bytes]:
        seen, out = self.seen[topic], []
        for batch in batches:
            for data, info in batch:
                key = (info["source_timestamp"], info["publication_sequence_number"])
                if key not in seen:
                    seen.append(key)
                    out.append(data)
        return out

    def catch_up(self, topic: str) -> None:
        """A latched reader beside the volatile one while every publisher of `topic` latches."""
        if topic not in self.late_qos or topic not in self.subscriptions:
            return
        durabilities = {i.qos_profile.durability for i in self.node.get_publishers_info_by_topic(topic)}
        wanted = durabilities == {DurabilityPolicy.TRANSIENT_LOCAL}
        if wanted and topic not in self.late:
            msgtype, sub = self.subscriptions[topic]
            self.late[topic] = self.node.create_subscription(
                sub.msg_type,
                topic,
                functools.partial(self.on_message, topic, msgtype),
                self.late_qos[topic],
                raw=True,
                callback_group=self.group,
            )
        elif not wanted and topic in self.late:
            self._drain_late(topic)
            self.node.destroy_subscription(self.late.pop(topic))

    def _drain_late(self, topic: str) -> None:
        msgtype, _ = self.subscriptions[topic]
        for data in self._once(topic, [take_all_with_info(self.late[topic])]):
            self.on_message(topic, msgtype, data)

    def _wanted(self, topic: str) -> bool:
        return (
            topic not in IGNORED
            and not topic.startswith(IGNORED)
            and not hidden(topic)
            and (self.only is None or topic in self.only)
        )

    def release(self) -> None:
        """Subscribe the held topics (with the topic table's QoS)."""
        for topic, (msgtype, profile, latched) in self.held.items():
            if self._wanted(topic):
                self._subscribe(topic, msgtype, profile, latched)
        self.held = {}

    def discover(self) -> None:
        for topic in self.late_qos:
            self.catch_up(topic)
        for topic, types in self.node.get_topic_names_and_types():
            if topic in self.handled or not self._wanted(topic) or self.node.count_publishers(topic) == 0:
                continue
            profile = matching_qos(self.node, topic)
            self._subscribe(topic, types[0], profile, profile.durability == DurabilityPolicy.TRANSIENT_LOCAL)

    def _subscribe(self, topic: str, msgtype: str, profile: QoSProfile, latched: bool) -> None:
        self.handled.add(topic)
        try:
            cls = message_class(msgtype)
        except (ImportError, AttributeError):  # e.g. tf2_msgs where the pip setup could not build it
            if self.on_unreadable is not None:
                package = msgtype.split("/")[0]
                installed = importlib.util.find_spec(package) is not None
                self.on_unreadable(
                    topic,
                    msgtype,
                    f"no such type in its package {package}"
                    if installed
                    else f"its package {package} is not installed here",
                )
            return
        if not self.add(topic, msgtype, latched):
            return
        if self.keep_all:
            profile = QoSProfile(
                history=HistoryPolicy.KEEP_ALL, reliability=profile.reliability, durability=profile.durability
            )
        callbacks: dict[str, Any] = {}
        if self.on_lost is not None:
            on_lost = self.on_lost
            best_effort = profile.reliability == ReliabilityPolicy.BEST_EFFORT
            callbacks["message_lost"] = lambda info: on_lost(topic, int(info.total_count_change), best_effort)
        if self.on_matched is not None or topic in self.late_qos:
            callbacks["matched"] = lambda info: self._matched(topic)
        events = qos.quiet_reader(**callbacks)  # (the reader takes the publishers' own QoS)
        sub = self.node.create_subscription(
            cls,
            topic,
            functools.partial(self.on_message, topic, msgtype),
            profile,
            raw=True,
            event_callbacks=events,
            callback_group=self.group,
        )
        self.subscriptions[topic] = (msgtype, sub)
        self.catch_up(topic)

    def _matched(self, topic: str) -> None:
        self.catch_up(topic)
        if self.on_matched is not None:
            self.on_matched(topic)
