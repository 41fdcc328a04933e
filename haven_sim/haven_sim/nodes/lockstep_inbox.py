"""A lockstep node's deferred readers (`Inbox`): raw messages per topic, taken only when a tick
asks, matched against what the tick announces (`runtime.suite_messages`), decoded only when handed
over; and the `outside_input` / `input_lost` events a node publishes about them (`OutsideReport`).
The clock itself is `nodes/lockstep.py`."""

from __future__ import annotations

import time
from collections import Counter, deque
from collections.abc import Mapping, Sequence
from typing import Any

from rclpy.callback_groups import CallbackGroup
from rclpy.event_handler import SubscriptionEventCallbacks
from rclpy.node import Node
from rclpy.publisher import Publisher
from rclpy.qos import HistoryPolicy, QoSProfile
from rclpy.serialization import deserialize_message
from rclpy.subscription import Subscription

from haven_sim.common import topics
from haven_sim.common.component import Message
from haven_sim.common.events import EventKind, event
from haven_sim.nodes.qos import best_effort
from haven_sim.nodes.runner import refused, stop_requested
from haven_sim.nodes.wire import TopicSpec
from haven_sim.runtime.suite_messages import OutsideInputs, Queue

WAIT_S = 5.0  # longest wait for an announced message before going on without it
OUTSIDE_REPORT_S = 1.0  # sim time between a node's `outside_input` events on one topic while they go on


def keep_all(profile: QoSProfile) -> QoSProfile:
    """A reader that drops nothing: in lockstep every announced message must be there."""
    return QoSProfile(history=HistoryPolicy.KEEP_ALL, reliability=profile.reliability, durability=profile.durability)


class Deferred(CallbackGroup):
    """Entities the executor never waits on: their readers are read only when a tick asks, so a
    participant wakes for its ticks alone, not for every message of every stream."""

    def can_execute(self, entity: Any) -> bool:
        return False

    def beginning_execution(self, entity: Any) -> bool:
        return False

    def ending_execution(self, entity: Any) -> None:
        pass


def take_all(sub: Subscription) -> list[bytes]:
    """Everything a (raw) subscription's reader holds now."""
    return [data for data, _ in take_all_with_info(sub)]


def take_all_with_info(sub: Subscription) -> list[tuple[bytes, dict[str, Any]]]:
    """Everything a (raw) subscription's reader holds now, each with its message info (the
    publisher's source timestamp and sequence number among it)."""
    out = []
    with sub.handle:
        while (taken := sub.handle.take_message(sub.msg_type, sub.raw)) is not None:
            out.append((taken[0], taken[1]))
    return out


def unmatched(node: Node, subs: Mapping[str, Subscription], pubs: Mapping[str, Publisher]) -> list[str]:
    """Our topics where a writer (for our readers) or a reader (for our writers) that the graph
    shows has not matched ours yet; none means a message sent now reaches everyone who is there."""
    out = [
        t for t, sub in subs.items() if sub.get_publisher_count() < node.count_publishers(node.resolve_topic_name(t))
    ]
    return out + [
        t
        for t, pub in pubs.items()
        if pub.get_subscription_count() < node.count_subscribers(node.resolve_topic_name(t))
    ]


class Inbox:
    """A node's deferred readers: raw messages per topic, matched against what the ticks announce
    and decoded only when handed over; outside messages go by `outside`'s rule."""

    def __init__(
        self, node: Node, specs: Mapping[str, TopicSpec], inputs: list[str], settle: int, outside: OutsideInputs
    ) -> None:
        self.node, self.specs, self.outside = node, specs, outside
        self.queues = {t: Queue(t, settle) for t in inputs}
        self.lost: Counter[str] = Counter()  # announced messages that never came, per topic
        group = Deferred()
        # (a best-effort publisher: the second reader's)
        quiet = SubscriptionEventCallbacks(incompatible_qos=lambda _: None)
        self.subs = {
            t: node.create_subscription(
                specs[t].msg_type,
                t,
                _never,
                keep_all(specs[t].sub_qos),
                callback_group=group,
                raw=True,
                event_callbacks=quiet if specs[t].best_effort_too else None,
            )
            for t in inputs
        }
        # A topic read best effort too (the e-stop) has a second reader; a reliable publisher's
        # message that both get is taken once (the publisher's timestamp and sequence number).
        self.best_effort = {
            t: node.create_subscription(
                specs[t].msg_type, t, _never, keep_all(best_effort(specs[t].sub_qos)), callback_group=group, raw=True
            )
            for t in inputs
            if specs[t].best_effort_too
        }
        self.seen: dict[str, deque[tuple[int, int]]] = {t: deque(maxlen=256) for t in self.best_effort}

    @property
    def readers(self) -> dict[str, Subscription]:
        """A reader per topic that matches every publisher there is (the best-effort one where
        there are two): what `unmatched` asks about."""
        return {t: self.best_effort.get(t, sub) for t, sub in self.subs.items()}

    def take(self, only: Sequence[str] | None = None) -> None:
        for t in self.subs if only is None else only:
            if t not in self.best_effort:
                self.queues[t].add(take_all(self.subs[t]))
                continue
            new = []
            for data, info in take_all_with_info(self.subs[t]) + take_all_with_info(self.best_effort[t]):
                key = (info["source_timestamp"], info["publication_sequence_number"])
                if key not in self.seen[t]:
                    self.seen[t].append(key)
                    new.append(data)
            self.queues[t].add(new)

    def fill(self, expect: Mapping[str, Sequence[str]]) -> None:
        """Take from the readers until every announced message is in; give up after WAIT_S."""
        self.take()
        deadline = time.monotonic() + WAIT_S
        while missing := {t: m for t, ds in expect.items() if t in self.queues and (m := self.queues[t].missing(ds))}:
            if stop_requested():
                return
            if time.monotonic() > deadline:
                for t, m in missing.items():
                    self.queues[t].give_up(m)
                    self.lost[t] += sum(m.values())
                said = ", ".join(f"{sum(m.values())} on {t}" for t, m in missing.items())
                self.node.get_logger().warning(
                    f"lockstep: announced messages did not arrive within {WAIT_S:g} s ({said}); going on without them"
                )
                return
            time.sleep(0.0001)
            self.take(list(missing))

    def pop(self, topic: str, expected: Sequence[str], now: float) -> list[Message]:
        """The suite's announced messages on `topic`, then the outside ones `outside` lets through, decoded."""
        ours, others = self.queues[topic].split(expected)
        spec, out = self.specs[topic], []
        for raw in ours + self.outside.take(topic, others, now):
            try:
                out.append(Message(topic, spec.decode(deserialize_message(raw, spec.msg_type)), 0.0))
            except ValueError as e:
                refused(self.node, topic, e)
        return out


class OutsideReport:
    """The `outside_input` and `input_lost` events a node publishes about its inbox."""

    def __init__(self, source: str) -> None:
        self.source = source
        self.said: dict[str, tuple[float, int, int, int]] = {}  # topic -> (when, ignored, taken, dropped) last said
        self.lost_said: Counter[str] = Counter()

    def events(self, inbox: Inbox, now: float) -> list[Message]:
        o, out = inbox.outside, []
        for topic in sorted(set(o.ignored) | set(o.taken)):
            counts = (o.ignored[topic], o.taken[topic], o.limit.dropped[topic])
            when, *before = self.said.get(topic, (-OUTSIDE_REPORT_S, 0, 0, 0))
            if counts != tuple(before) and (topic not in self.said or now - when >= OUTSIDE_REPORT_S):
                self.said[topic] = (now, *counts)
                new = dict(
                    zip(
                        ("ignored", "taken", "dropped"),
                        (c - b for c, b in zip(counts, before, strict=True)),
                        strict=True,
                    )
                )
                out.append(
                    Message(topics.EVENTS, event(EventKind.OUTSIDE_INPUT, now, self.source, topic=topic, **new), now)
                )
        for topic, n in (inbox.lost - self.lost_said).items():
            out.append(
                Message(
                    topics.EVENTS,
                    event(EventKind.INPUT_LOST, now, self.source, topic="/" + topic.lstrip("/"), messages=n),
                    now,
                )
            )
        self.lost_said = Counter(inbox.lost)
        return out


def _never(msg: Any) -> None:  # pragma: no cover - deferred subscriptions have no callback
    raise AssertionError("a deferred subscription's callback ran")
