"""Batch mode's loop: the simulator and the components in one process, keeping the lockstep rule
(`runtime.lockstep`) that ROS mode's lockstep clock keeps, so both modes compute the same trial.

Every message goes through the same value changes a ROS message round trip makes
(`runtime.wire`), and a component handles its inbox only at the steps where it acts, as a node does.
"""

from __future__ import annotations

import heapq
import itertools
from collections.abc import Callable, Collection, Sequence

from haven_sim.common.component import Component, Message
from haven_sim.common.events import Event, Sequencer
from haven_sim.runtime.lockstep import ParticipantInfo, Schedule, inbox_order
from haven_sim.runtime.wire import on_the_wire
from haven_sim.sim.simulator import SimulatorComponent

Observer = Callable[[Message], None]
DelayFn = Callable[[str], float]  # topic -> seconds its next message is held back


class InProcessLoop:
    def __init__(
        self,
        sim: SimulatorComponent,
        components: Sequence[Component],
        observers: Sequence[Observer] = (),
        observed: Collection[str] = (),
        delay: DelayFn | None = None,
    ) -> None:
        """`observers` see every message on the `observed` topics, as received (a recorder, say).
        `delay(topic)` holds each message on a topic back for that many seconds of sim time, as a
        loaded machine's transport would (0: delivered in the same step)."""
        self.delay = delay
        self._held: list[tuple[float, int, Message, bool]] = []  # (due, order, message, to the simulator)
        self._order = itertools.count()
        self.sim = sim
        self.components = list(components)
        self.observers = list(observers)
        self.observed = frozenset(observed)
        self._inbox: dict[str, list[Message]] = {c.name: [] for c in self.components}
        self._handlers = {c.name: dict(c.handlers()) for c in self.components}
        self._rank = {c.name: {t: i for i, t in enumerate(self._handlers[c.name])} for c in self.components}
        self._sim_handlers = dict(sim.handlers())
        self.schedule = Schedule(sim.config.sim.step_ns)
        self.sequencer = Sequencer()
        for c in self.components:
            self.schedule.add(ParticipantInfo.of(c))
        # Tell each component which of its outputs nobody reads, so it may skip making them.
        read = set(observed) | set(self._sim_handlers) | {t for h in self._handlers.values() for t in h}
        self._read = frozenset(read)  # a message on any other topic reaches no one: it is not routed
        for c in [sim, *self.components]:
            c.unread = frozenset(t for t in c.outputs() if t not in read)
        # Per step, by name: the component, its handlers and its topics' rank (lookups done once).
        self._parts = {c.name: (c, self._handlers[c.name], self._rank[c.name]) for c in self.components}
        self._readers = {t: [c.name for c in self.components if t in self._handlers[c.name]] for t in read}

    def _route(self, messages: Sequence[Message], to_sim: bool) -> None:
        read, delay = self._read, self.delay
        for sent in messages:
            topic, data = sent.topic, sent.data
            if topic not in read:
                continue
            if isinstance(data, Event):
                data = self.sequencer.number(data)
            wired = on_the_wire(topic, data)
            # unchanged: the same (frozen) message
            m = sent if wired is sent.data else Message(topic, wired, sent.stamp)
            late = delay(topic) if delay is not None else 0.0
            if late > 0.0:
                heapq.heappush(self._held, (self.sim.sim.time + late, next(self._order), m, to_sim))
                continue
            self._deliver(m, to_sim)

    def _release(self) -> None:
        """Deliver the held messages that are due."""
        now = self.sim.sim.time + 1e-9
        while self._held and self._held[0][0] <= now:
            _, _, m, to_sim = heapq.heappop(self._held)
            self._deliver(m, to_sim)

    def _deliver(self, m: Message, to_sim: bool) -> None:
        topic = m.topic
        if topic in self.observed:
            for observer in self.observers:
                observer(m)
        inbox = self._inbox
        for name in self._readers[topic]:
            inbox[name].append(m)
        if to_sim:
            handler = self._sim_handlers.get(topic)
            if handler is not None:
                handler(m.data, m.stamp)

    def publish(self, messages: Sequence[Message]) -> None:
        """Messages from outside the loop (a study condition set by the caller, say)."""
        self._route(messages, to_sim=True)

    def step(self) -> None:
        k, now = self.sim.sim.steps, self.sim.sim.time
        if self._held:
            self._release()
        self._route(self.sim.sense(), to_sim=False)
        produced = []
        for name, ticks in self.schedule.acting_ticks(k):  # in registration order: the components' order
            c, handlers, rank = self._parts[name]
            inbox = self._inbox[name]
            out: list[Message] = []
            if inbox:
                self._inbox[name] = []
                for m in inbox_order(rank, inbox):
                    out += handlers[m.topic](m.data, now)
            if ticks:
                out += c.tick(now)
            if out:
                self.schedule.published(name, [m.topic for m in out])
                produced += out
        self._route(produced, to_sim=True)
        self.sim.advance()

    def run_until(self, stop: Callable[[], bool], max_steps: int) -> None:
        for _ in range(max_steps):
            if stop():
                return
            self.step()
