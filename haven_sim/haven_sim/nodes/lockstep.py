"""The lockstep clock over DDS (the rule itself is `haven_sim.runtime.lockstep`).

The simulator node coordinates. For each step it publishes its state and sends each participant
that acts a tick on /haven/lockstep/tick/<node> naming, by digest, the suite's messages on its
inputs since it last acted (`runtime.suite_messages.Expected`); it waits for their
acknowledgements on /haven/lockstep/ack (each names the messages it published), then for every
command those announce to be in its own readers, applies them and advances. It does not wait for
observers, whose outputs no participant reads. (The viz node is not one: the scenario node hands
its simulated participants what /haven/cue_state shows.)

A participant's readers are left alone until a tick comes (they are in a callback group the
executor never waits on, so a participant wakes for its ticks only). On a tick it takes from its
readers until it holds every announced message, handles exactly those (of a state stream the
newest), does its periodic work if due, and acknowledges with what it published.

Messages from outside the suite are told apart by their digests, whoever sends them and however
many (a second suite on the domain, a node flooding /goal_pose): on a topic the suite writes they
are ignored and counted, unless the run opened it (`lockstep_open`: `haven run --allow`); on a topic
no suite node writes (teleop, e-stop, trial control) they are handled when the participant next
acts, at most `suite_messages.OUTSIDE_RATE_HZ` a second. Each node says so once per topic in an
`outside_input` event (and again every OUTSIDE_REPORT_S of sim time while it goes on).

DDS acknowledgements cannot pace this: Fast DDS acknowledges on its heartbeat, every few seconds.
Participants and the coordinator wait at most `WAIT_S` for an announced message, then go on
without it (an `input_lost` event, the message dropped should it come later): a loss costs one
wait, never every step after it.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Mapping, Sequence
from typing import Any, TypeVar

from rclpy.clock import Clock, ClockType
from rclpy.node import Node
from rclpy.publisher import Publisher
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy
from rclpy.serialization import serialize_message
from std_msgs.msg import String

from haven_sim.common.component import NS_PER_S, Component, Message, due
from haven_sim.common.events import Event, Sequencer
from haven_sim.nodes.lockstep_inbox import Inbox, OutsideReport, unmatched
from haven_sim.nodes.runner import THROTTLE_S, handle
from haven_sim.nodes.wire import TopicSpec
from haven_sim.runtime.lockstep import Ack, Hello, LockstepParams, ParticipantInfo, Schedule, Tick, inbox_order
from haven_sim.runtime.suite_messages import Expected, OutsideInputs, absolute, digest
from haven_sim.sim.pacer import WallClock

T = TypeVar("T")
TICKS, ACK, HELLO = "haven/lockstep/tick", "haven/lockstep/ack", "haven/lockstep/hello"


def tick_topic(participant: str) -> str:
    return f"{TICKS}/{participant}"


CONTROL = QoSProfile(history=HistoryPolicy.KEEP_ALL, reliability=ReliabilityPolicy.RELIABLE)
# Each participant keeps its last hello for late readers; the coordinator keeps every one it gets
# (several writers' hellos arrive at once, and a reader of depth 1 would keep only the last).
ANNOUNCE = QoSProfile(
    depth=1,
    history=HistoryPolicy.KEEP_LAST,
    reliability=ReliabilityPolicy.RELIABLE,
    durability=DurabilityPolicy.TRANSIENT_LOCAL,
)
ANNOUNCED = QoSProfile(
    history=HistoryPolicy.KEEP_ALL, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL
)
STEADY = Clock(clock_type=ClockType.STEADY_TIME)


def _parse(node: Node, parse: Callable[[str], T], msg: String) -> T | None:
    """A protocol message, or None (with a throttled warning) for anything else on its topic."""
    try:
        return parse(msg.data)
    except ValueError as e:
        node.get_logger().warning(f"ignored a lockstep message: {e}", throttle_duration_sec=THROTTLE_S)
        return None


def digests(sent: Sequence[tuple[str, bytes]]) -> dict[str, list[str]]:
    out: dict[str, list[str]] = {}
    for topic, raw in sent:
        out.setdefault(topic, []).append(digest(raw))
    return out


class LockstepParticipant:
    """Defers a component node's inputs to the ticks that name it."""

    def __init__(
        self,
        node: Node,
        component: Component,
        specs: Mapping[str, TopicSpec],
        publish: Callable[[list[Message], bool], list[tuple[str, bytes]]],
        outputs: Mapping[str, Publisher],
        params: LockstepParams,
        deferred: list[Message],
    ) -> None:
        """`deferred`: what the node made between ticks (sent with the next)."""
        self.node, self.component, self.publish, self.outputs, self.deferred = (
            node,
            component,
            publish,
            outputs,
            deferred,
        )
        self.info = ParticipantInfo.of(component)
        self.handlers = dict(component.handlers())
        self.rank = {t: i for i, t in enumerate(self.handlers)}
        self.inbox = Inbox(
            node, specs, list(self.handlers), settle=1, outside=OutsideInputs(opened=absolute(params.lockstep_open))
        )
        self.report = OutsideReport(component.name)
        self.ack_pub = node.create_publisher(String, ACK, CONTROL)
        self.hello_pub = node.create_publisher(String, HELLO, ANNOUNCE)
        self._said: tuple[bool, dict[str, int]] | None = None
        self._ticked = False
        self.time = 0.0  # the last tick's (sim time)
        self._since = time.monotonic()
        node.create_subscription(String, tick_topic(component.name), self._on_tick, CONTROL)
        node.create_timer(0.1, self._announce, clock=STEADY)

    def _announce(self) -> None:
        """Say hello, whether every reader and writer of our topics that the graph shows has
        matched ours, and how many readers each publisher has matched (re-said when that changes,
        until the first tick)."""
        if self._ticked:
            return
        waiting = unmatched(self.node, self.inbox.readers, self.outputs)
        ready = not waiting
        if not ready and time.monotonic() - self._since > 5.0:
            self._since = time.monotonic()
            self.node.get_logger().info(f"lockstep: waiting for {', '.join(waiting)} to match")
        matched = {t: pub.get_subscription_count() for t, pub in self.outputs.items()}
        if (ready, matched) != self._said:
            self._said = (ready, matched)
            hello = Hello(
                self.component.name, self.info.period_ns, sorted(self.info.inputs), sorted(self.outputs), ready, matched
            )
            self.hello_pub.publish(String(data=hello.to_json()))

    def _on_tick(self, msg: String) -> None:
        tick = _parse(self.node, Tick.from_json, msg)
        if tick is None:
            return
        self._ticked = True
        self.inbox.outside.owned = absolute(tick.owned)
        self.inbox.fill(tick.expect)
        now = self.time = tick.t_ns / NS_PER_S
        received: list[Message] = []
        for topic in self.handlers:
            received += self.inbox.pop(topic, tick.expect.get(topic, ()), now)
        out: list[Message] = []
        for m in inbox_order(self.rank, received):
            out += handle(self.node, m.topic, self.handlers[m.topic], m.data, now)
        if self.info.period_ns is not None and due(tick.step, tick.step_ns, self.info.period_ns):
            out += self.component.tick(now)
        out += self.report.events(self.inbox, now) + self.deferred
        self.deferred.clear()
        sent = self.publish(out, True)
        self.ack_pub.publish(String(data=Ack(self.component.name, tick.step, digests(sent)).to_json()))


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
        params: LockstepParams,
        deferred: list[Message],
        clock: WallClock,
    ) -> None:
        """`deferred`: what the node made between steps (sent before the next); `clock`: the wall
        clock the real-time factor is kept against (paused: no step)."""
        self.node, self.sim, self.specs, self.outputs, self.deferred = node, sim, specs, outputs, deferred
        self.sequencer = Sequencer()
        self.expected_names, self.observers, self.wait_for, self.rtf = (
            set(participants),
            set(observers),
            list(wait_for),
            real_time_factor,
        )
        self.handlers = dict(sim.handlers())
        self.inbox = Inbox(
            node, specs, list(self.handlers), settle=0, outside=OutsideInputs(opened=absolute(params.lockstep_open))
        )
        self.report = OutsideReport(sim.name)
        self.schedule = Schedule(sim.config.sim.step_ns)
        self.expected = Expected()  # what each participant is to receive
        self.own: dict[str, list[str]] = {}  # the suite's messages on the simulator's inputs since it last stepped
        self.writes: dict[str, list[str]] = {"": list(outputs)}  # node -> its outputs (the simulator's under "")
        self.owned: frozenset[str] = frozenset()  # every topic the suite writes (known once stepping starts)
        self.ready: dict[str, bool] = {}
        self.matched: dict[str, dict[str, int]] = {}  # participant -> its publishers' matched readers
        self.waiting: set[str] | None = None  # None until the first step
        self.clock, self.held = clock, False  # held: a step due while paused, taken on resume
        self.step = -1
        self._stable, self._since = 0, time.monotonic()
        self.tick_pubs = {name: node.create_publisher(String, tick_topic(name), CONTROL) for name in participants}
        node.create_subscription(String, HELLO, self._on_hello, ANNOUNCED)
        node.create_subscription(String, ACK, self._on_ack, CONTROL)
        self._timer = node.create_timer(0.05, self._check_ready, clock=STEADY)
        node.create_timer(5.0, self._watchdog, clock=STEADY)

    def _on_hello(self, msg: String) -> None:
        hello = _parse(self.node, Hello.from_json, msg)
        if hello is not None and hello.node in self.expected_names:
            self.schedule.add(ParticipantInfo(hello.node, hello.period_ns, frozenset(hello.inputs)))
            self.expected.reads(hello.node, hello.inputs)
            self.writes[hello.node] = list(hello.outputs)
            self.ready[hello.node] = hello.ready
            self.matched[hello.node] = hello.matched

    def _check_ready(self) -> None:
        """Start once every participant is there and matched, the `wait_for` nodes (the recorder)
        read every topic the suite publishes without a history a late reader could catch up on
        (/odom, /humans, /goal_pose: their first messages are recorded) and each publisher has
        matched every reader this node sees there, and that has held for half a second of wall time."""
        missing = sorted(self.expected_names - set(self.ready)) + sorted(n for n, r in self.ready.items() if not r)
        writers: dict[str, dict[str, int]] = {
            "": {t: p.get_subscription_count() for t, p in self.outputs.items()},
            **self.matched,
        }
        for node, matched in writers.items():
            for topic in (
                t
                for t in matched
                if t in self.specs and self.specs[t].pub_qos.durability != DurabilityPolicy.TRANSIENT_LOCAL
            ):
                readers = [
                    i.node_name for i in self.node.get_subscriptions_info_by_topic(self.node.resolve_topic_name(topic))
                ]
                missing += [f"{name} on {topic}" for name in self.wait_for if name not in readers]
                missing += [f"{node} matching the readers of {topic}"] if matched[topic] < len(readers) else []
        missing += unmatched(
            self.node, self.inbox.readers, {**self.outputs, **{tick_topic(n): p for n, p in self.tick_pubs.items()}}
        )
        self._stable = 0 if missing else self._stable + 1
        if missing and time.monotonic() - self._since > 5.0:
            self._since = time.monotonic()
            self.node.get_logger().info(f"lockstep: waiting for {', '.join(dict.fromkeys(missing))}")
        if self._stable >= 10:
            self._timer.cancel()
            self.node.get_logger().info(f"lockstep: {len(self.expected_names)} participant(s) ready; stepping")
            self.owned = absolute(t for ts in self.writes.values() for t in ts)
            self.inbox.outside.owned = self.owned
            self._wall0 = self.clock.now()
            self.waiting = set()
            self._run()

    def _watchdog(self) -> None:
        if self.waiting and time.monotonic() - self._since > 5.0:
            self.node.get_logger().warning(
                f"lockstep: step {self.step} still waits for {', '.join(sorted(self.waiting))}"
            )

    def _publish(self, messages: list[Message]) -> None:
        """The simulator's messages; those a participant reads are named for its next tick."""
        for m in messages:
            pub = self.outputs.get(m.topic)
            if pub is None:
                continue
            data = self.sequencer.number(m.data) if isinstance(m.data, Event) else m.data
            msg = self.specs[m.topic].encode(data, m.stamp)
            if m.topic in self.expected.readers:
                raw = serialize_message(msg)
                pub.publish(raw)
                self.expected.sent(m.topic, [digest(raw)])
            else:
                pub.publish(msg)

    def _run(self) -> None:
        """Step until a step needs acknowledgements."""
        while True:
            k = self.sim.sim.steps
            self._publish(self.sim.sense())
            acting = self.schedule.acting(k)
            if acting:
                step_ns = self.schedule.step_ns
                for name in acting:
                    inputs = self.schedule.participants[name].inputs
                    owned = sorted(t for t in inputs if "/" + t.lstrip("/") in self.owned)
                    tick = Tick(k, k * step_ns, step_ns, self.expected.take(name), owned)
                    self.tick_pubs[name].publish(String(data=tick.to_json()))
                self.step, self.waiting, self._since = k, set(acting) - self.observers, time.monotonic()
                if self.waiting:
                    return
            if self.clock.paused:
                self.held = True
                return
            self._advance()

    def _on_ack(self, msg: String) -> None:
        ack = _parse(self.node, Ack.from_json, msg)
        if ack is None or self.waiting is None or ack.step != self.step or ack.node not in self.waiting:
            return
        for topic, names in ack.sent.items():
            self.expected.sent(topic, names)
            if topic in self.handlers:
                self.own.setdefault(topic, []).extend(names)
        self.schedule.published(ack.node, [t for t, names in ack.sent.items() if names])
        self.waiting.discard(ack.node)
        if not self.waiting:
            if self.clock.paused:
                self.held = True
                return
            self._advance()
            self._run()

    def resumed(self) -> None:
        """The clock runs again: take the step that was due when it stopped."""
        if self.held and not self.clock.paused:
            self.held = False
            self._advance()
            self._run()

    def _advance(self) -> None:
        """Apply every command announced (and those from outside the rule lets through), keep below
        the real-time factor, step."""
        self.inbox.fill(self.own)
        now = self.sim.sim.time
        for topic in self.handlers:
            for m in self.inbox.pop(topic, self.own.get(topic, ()), now):
                handle(self.node, topic, self.handlers[topic], m.data, now)
        self.own = {}
        self._publish(self.report.events(self.inbox, now) + self.deferred)
        self.deferred.clear()
        ahead = self.sim.sim.time / self.rtf - (self.clock.now() - self._wall0)
        if ahead > 0:
            time.sleep(ahead)
        self.sim.advance()
