"""The lockstep clock over DDS (the rule itself is `haven_sim.runtime.lockstep`).

The simulator node coordinates. For each step it publishes its state and sends each participant
that acts a tick on /haven/lockstep/tick/<node> with the number of messages the suite has published
so far on each topic; it waits for their acknowledgements on /haven/lockstep/ack (each says how many
messages it published on each topic), then for every command those announce to be in its own
readers, applies them and advances. It does not wait for observers, whose outputs no participant
reads: they work through their ticks at their own pace, with the same inputs. (The viz node is not
one: the scenario node hands its simulated participants what /haven/cue_state shows.)

A participant's readers are left alone until a tick comes (they are in a callback group the
executor never waits on, so a participant wakes for its ticks only). On a tick it takes from its
readers until it holds as many messages on each input topic as the tick announces, handles
exactly those (on a topic with one writer: the first so many, of a state stream the newest of
them; on /haven/events, which every node writes: the simulator's up to this step and the others'
from earlier steps, by their stamps), does its periodic work if due, and acknowledges with what it
published. Messages on topics no suite node writes (teleop, e-stop) are handled when the
participant next acts.

DDS acknowledgements cannot pace this: Fast DDS acknowledges on its heartbeat, every few seconds.
Counting is exact with every publisher of the suite's topics inside the suite; a message from
outside on such a topic is handled a step late at worst. Participants and the coordinator wait at
most `WAIT_S` for an announced message, then go on with a warning.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Mapping
from typing import Any, TypeVar

from rclpy.callback_groups import CallbackGroup
from rclpy.clock import Clock, ClockType
from rclpy.node import Node
from rclpy.publisher import Publisher
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy
from rclpy.serialization import deserialize_message
from rclpy.subscription import Subscription
from std_msgs.msg import String

from haven_sim.common import topics
from haven_sim.common.events import Event, Sequencer, Source
from haven_sim.nodes.runner import THROTTLE_S, handle, refused, stop_requested
from haven_sim.nodes.wire import TopicSpec
from haven_sim.runtime.component import NS_PER_S, Component, Message, due
from haven_sim.runtime.lockstep import Ack, Hello, ParticipantInfo, Schedule, Tick, inbox_order

T = TypeVar("T")
TICKS, ACK, HELLO = "haven/lockstep/tick", "haven/lockstep/ack", "haven/lockstep/hello"


def tick_topic(participant: str) -> str:
    return f"{TICKS}/{participant}"


CONTROL = QoSProfile(history=HistoryPolicy.KEEP_ALL, reliability=ReliabilityPolicy.RELIABLE)
# Each participant keeps its last hello for late readers; the coordinator keeps every one it gets
# (several writers' hellos arrive at once, and a reader of depth 1 would keep only the last).
ANNOUNCE = QoSProfile(depth=1, history=HistoryPolicy.KEEP_LAST, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL)
ANNOUNCED = QoSProfile(history=HistoryPolicy.KEEP_ALL, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL)
STEADY = Clock(clock_type=ClockType.STEADY_TIME)
WAIT_S = 5.0  # longest wait for an announced message before going on without it


def keep_all(profile: QoSProfile) -> QoSProfile:
    """A reader that drops nothing: in lockstep every announced message must be there to count."""
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
    out = []
    with sub.handle:
        while (taken := sub.handle.take_message(sub.msg_type, sub.raw)) is not None:
            out.append(taken[0])
    return out


def unmatched(node: Node, subs: Mapping[str, Subscription], pubs: Mapping[str, Publisher]) -> list[str]:
    """Our topics where a writer (for our readers) or a reader (for our writers) that the graph
    shows has not matched ours yet; none means a message sent now reaches everyone who is there."""
    out = [t for t, sub in subs.items() if sub.get_publisher_count() < node.count_publishers(node.resolve_topic_name(t))]
    return out + [t for t, pub in pubs.items() if pub.get_subscription_count() < node.count_subscribers(node.resolve_topic_name(t))]


class Inbox:
    """A node's deferred readers: raw messages per topic, counted as they are taken, decoded only
    when handed over."""

    def __init__(self, node: Node, specs: Mapping[str, TopicSpec], inputs: list[str]) -> None:
        self.node, self.specs = node, specs
        self.queued: dict[str, list[bytes]] = {t: [] for t in inputs}
        self.received: dict[str, int] = dict.fromkeys(inputs, 0)
        group = Deferred()
        self.subs = {
            t: node.create_subscription(specs[t].msg_type, t, _never, keep_all(specs[t].sub_qos), callback_group=group, raw=True) for t in inputs
        }

    def take(self, only: list[str] | None = None) -> None:
        for t in self.subs if only is None else only:
            raw = take_all(self.subs[t])
            self.queued[t] += raw
            self.received[t] += len(raw)

    def fill(self, counts: Mapping[str, int]) -> None:
        """Take from the readers until each topic has received the announced number of messages."""
        self.take()
        deadline = time.monotonic() + WAIT_S
        while short := [t for t in self.subs if self.received[t] < counts.get(t, 0)]:
            if stop_requested():
                return
            if time.monotonic() > deadline:
                self.node.get_logger().warning(f"lockstep: announced messages on {', '.join(short)} did not arrive; going on")
                return
            time.sleep(0.0001)
            self.take(short)

    def pop(self, topic: str, n: int | None = None) -> tuple[list[Message], int]:
        """The first `n` queued messages of a topic (all when None), decoded, and how many were
        refused (with a throttled warning): those came from outside the suite, which sends none
        that cannot be read. Of a state stream only the newest readable one is handed over."""
        queued = self.queued[topic]
        n = len(queued) if n is None else n
        taken, self.queued[topic] = queued[:n], queued[n:]
        spec, out = self.specs[topic], []
        for raw in taken:
            try:
                out.append(Message(topic, spec.decode(deserialize_message(raw, spec.msg_type)), 0.0))
            except ValueError as e:
                refused(self.node, topic, e)
        return (out[-1:] if topic in topics.STATE else out), len(taken) - len(out)


def _parse(node: Node, parse: Callable[[str], T], msg: String) -> T | None:
    """A protocol message, or None (with a throttled warning) for anything else on its topic."""
    try:
        return parse(msg.data)
    except ValueError as e:
        node.get_logger().warning(f"ignored a lockstep message: {e}", throttle_duration_sec=THROTTLE_S)
        return None


def _never(msg: Any) -> None:  # pragma: no cover - deferred subscriptions have no callback
    raise AssertionError("a deferred subscription's callback ran")


class LockstepParticipant:
    """Defers a component node's inputs to the ticks that name it."""

    def __init__(
        self,
        node: Node,
        component: Component,
        specs: Mapping[str, TopicSpec],
        publish: Callable[[list[Message]], list[Publisher]],
        outputs: Mapping[str, Publisher],
    ) -> None:
        self.node, self.component, self.publish, self.outputs = node, component, publish, outputs
        self.info = ParticipantInfo.of(component)
        self.handlers = dict(component.handlers())
        self.rank = {t: i for i, t in enumerate(self.handlers)}
        self.inbox = Inbox(node, specs, list(self.handlers))
        self.handled: dict[str, int] = dict.fromkeys(self.handlers, 0)  # messages handled per topic
        self.later_events: list[Message] = []  # received, stamped at or after the last tick
        self.ack_pub = node.create_publisher(String, ACK, CONTROL)
        self.hello_pub = node.create_publisher(String, HELLO, ANNOUNCE)
        self._ready: bool | None = None
        self._ticked = False
        self._since = time.monotonic()
        node.create_subscription(String, tick_topic(component.name), self._on_tick, CONTROL)
        node.create_timer(0.1, self._announce, clock=STEADY)

    def _announce(self) -> None:
        """Say hello, and whether every reader and writer of our topics that the graph shows has
        matched ours (re-said when that changes, until the first tick)."""
        if self._ticked:
            return
        waiting = unmatched(self.node, self.inbox.subs, self.outputs)
        ready = not waiting
        if not ready and time.monotonic() - self._since > 5.0:
            self._since = time.monotonic()
            self.node.get_logger().info(f"lockstep: waiting for {', '.join(waiting)} to match")
        if ready != self._ready:
            self._ready = ready
            hello = Hello(self.component.name, self.info.period_ns, sorted(self.info.inputs), sorted(self.outputs), ready)
            self.hello_pub.publish(String(data=hello.to_json()))

    def _due_messages(self, counts: Mapping[str, int], now: float) -> list[Message]:
        """This step's share of the queue: on one-writer topics the first announced messages, on
        the events topic those stamped before this step (and the simulator's of this step).
        Messages from outside the suite must not shift the count: a refused one is not counted,
        and while a topic has a writer besides the suite's all its queue is handled and the count
        starts again from the announced one (such a topic's timing is the outsider's anyway)."""
        out: list[Message] = []
        for topic in self.inbox.queued:
            if topic == topics.EVENTS:
                events = self.later_events + self.inbox.pop(topic)[0]
                out += [m for m in events if _before(m.data, now)]
                self.later_events = [m for m in events if not _before(m.data, now)]
                continue
            outsiders = topic in counts and self.node.count_publishers(self.node.resolve_topic_name(topic)) > 1
            n = None if topic not in counts or outsiders else max(0, counts[topic] - self.handled[topic])
            before = len(self.inbox.queued[topic])
            messages, refused = self.inbox.pop(topic, n)
            out += messages
            self.handled[topic] = counts[topic] if outsiders else self.handled[topic] + before - len(self.inbox.queued[topic]) - refused
        return out

    def _on_tick(self, msg: String) -> None:
        tick = _parse(self.node, Tick.from_json, msg)
        if tick is None:
            return
        self._ticked = True
        counts = tick.counts
        self.inbox.fill(counts)
        step, now = tick.step, tick.t_ns / NS_PER_S
        out: list[Message] = []
        for m in inbox_order(self.rank, self._due_messages(counts, now)):
            out += handle(self.node, m.topic, self.handlers[m.topic], m.data, now)
        if self.info.period_ns is not None and due(step, tick.step_ns, self.info.period_ns):
            out += self.component.tick(now)
        self.publish(out)
        sent: dict[str, int] = {}
        for m in out:
            if m.topic in self.outputs:
                sent[m.topic] = sent.get(m.topic, 0) + 1
        self.ack_pub.publish(String(data=Ack(self.component.name, step, sent).to_json()))


def _before(e: Event, now: float) -> bool:
    """An event handled at the step of time `now`: the simulator's up to now, the others' before."""
    return e.stamp <= now + 1e-9 if e.source == Source.SIM else e.stamp < now - 1e-9


class LockstepCoordinator:
    """The simulator's side: steps when every participant that acts has acknowledged its tick and
    every command it announced is in."""

    def __init__(
        self,
        node: Node,
        sim: Any,  # SimulatorComponent
        participants: list[str],
        observers: list[str],
        wait_for: list[str],
        real_time_factor: float,
        specs: Mapping[str, TopicSpec],
        outputs: Mapping[str, Publisher],
    ) -> None:
        self.node, self.sim, self.specs, self.outputs = node, sim, specs, outputs
        self.sequencer = Sequencer()
        self.expected, self.observers, self.wait_for, self.rtf = set(participants), set(observers), list(wait_for), real_time_factor
        self.handlers = dict(sim.handlers())
        self.inbox = Inbox(node, specs, list(self.handlers))
        self.schedule = Schedule(sim.config.sim.step_ns)
        self.counts: dict[str, int] = {}  # messages the suite has published per topic
        self.ready: dict[str, bool] = {}
        self.waiting: set[str] | None = None  # None until the first step
        self.step = -1
        self._stable, self._since = 0, time.monotonic()
        self.tick_pubs = {name: node.create_publisher(String, tick_topic(name), CONTROL) for name in participants}
        node.create_subscription(String, HELLO, self._on_hello, ANNOUNCED)
        node.create_subscription(String, ACK, self._on_ack, CONTROL)
        self._timer = node.create_timer(0.05, self._check_ready, clock=STEADY)
        node.create_timer(5.0, self._watchdog, clock=STEADY)

    def _on_hello(self, msg: String) -> None:
        hello = _parse(self.node, Hello.from_json, msg)
        if hello is not None and hello.node in self.expected:
            self.schedule.add(ParticipantInfo(hello.node, hello.period_ns, frozenset(hello.inputs)))
            self.ready[hello.node] = hello.ready
            for topic in hello.outputs:  # a suite topic: counted from zero (others are outsiders')
                self.counts.setdefault(topic, 0)

    def _check_ready(self) -> None:
        """Start once every participant is there and matched, the `wait_for` nodes (the recorder)
        listen, and that has held for half a second of wall time."""
        clock_readers = {i.node_name for i in self.node.get_subscriptions_info_by_topic("/clock")}
        missing = sorted(self.expected - set(self.ready)) + sorted(n for n, r in self.ready.items() if not r)
        missing += sorted(set(self.wait_for) - clock_readers)
        missing += unmatched(self.node, self.inbox.subs, {**self.outputs, **{tick_topic(n): p for n, p in self.tick_pubs.items()}})
        self._stable = 0 if missing else self._stable + 1
        if missing and time.monotonic() - self._since > 5.0:
            self._since = time.monotonic()
            self.node.get_logger().info(f"lockstep: waiting for {', '.join(dict.fromkeys(missing))}")
        if self._stable >= 10:
            self._timer.cancel()
            self.node.get_logger().info(f"lockstep: {len(self.expected)} participant(s) ready; stepping")
            for topic in self.outputs:
                self.counts.setdefault(topic, 0)
            self._wall0 = time.monotonic()
            self.waiting = set()
            self._run()

    def _watchdog(self) -> None:
        if self.waiting and time.monotonic() - self._since > 5.0:
            self.node.get_logger().warning(f"lockstep: step {self.step} still waits for {', '.join(sorted(self.waiting))}")

    def _publish(self, messages: list[Message]) -> None:
        for m in messages:
            pub = self.outputs.get(m.topic)
            if pub is not None:
                data = self.sequencer.number(m.data) if isinstance(m.data, Event) else m.data
                pub.publish(self.specs[m.topic].encode(data, m.stamp))
                self.counts[m.topic] = self.counts.get(m.topic, 0) + 1

    def _run(self) -> None:
        """Step until a step needs acknowledgements."""
        while True:
            k = self.sim.sim.steps
            self._publish(self.sim.sense())
            acting = self.schedule.acting(k)
            if acting:
                step_ns = self.schedule.step_ns
                tick = String(data=Tick(k, k * step_ns, step_ns, self.counts).to_json())
                for name in acting:
                    self.tick_pubs[name].publish(tick)
                self.step, self.waiting, self._since = k, set(acting) - self.observers, time.monotonic()
                if self.waiting:
                    return
            self._advance()

    def _on_ack(self, msg: String) -> None:
        ack = _parse(self.node, Ack.from_json, msg)
        if ack is None or self.waiting is None or ack.step != self.step or ack.node not in self.waiting:
            return
        for topic, n in ack.sent.items():
            self.counts[topic] = self.counts.get(topic, 0) + n
        self.schedule.published(ack.node, ack.sent)
        self.waiting.discard(ack.node)
        if not self.waiting:
            self._advance()
            self._run()

    def _advance(self) -> None:
        """Apply every command announced (and any from outside), keep below the real-time factor, step."""
        self.inbox.fill(self.counts)
        now = self.sim.sim.time
        for topic in self.handlers:
            for m in self.inbox.pop(topic)[0]:
                handle(self.node, topic, self.handlers[topic], m.data, now)
        ahead = self.sim.sim.time / self.rtf - (time.monotonic() - self._wall0)
        if ahead > 0:
            time.sleep(ahead)
        self.sim.advance()
