"""Batch mode's loop: the simulator and the components in one process, exchanging messages in the
lockstep order that ROS mode's lockstep clock also keeps, so both modes compute the same trial.

One step of sim time k:
  1. sense: the simulator publishes its state for step k (clock, odom, humans, ...);
  2. act: each component handles the messages it has received (in a fixed order: topic by topic,
     events by stamp and source), then ticks if its period is due at step k; what it publishes
     now reaches the other components at step k + 1 and the simulator at once;
  3. the simulator applies the commands it received and advances to step k + 1.
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Mapping, Sequence

from haven_sim.common.events import Event
from haven_sim.runtime.component import Component, Message, due, period_ns
from haven_sim.sim.simulator import SimulatorComponent

Observer = Callable[[Message], None]


def inbox_order(rank: Mapping[str, int], inbox: Sequence[Message]) -> list[Message]:
    """The order a component handles what it received: by its topics' order (`rank`), events by
    (stamp, source), other topics as they came (one publisher each)."""
    if len(inbox) < 2:
        return list(inbox)

    def key(m: Message) -> tuple[int, float, str]:
        if isinstance(m.data, Event):
            return (rank.get(m.topic, len(rank)), m.data.stamp, m.data.source)
        return (rank.get(m.topic, len(rank)), 0.0, "")

    return sorted(inbox, key=key)


class InProcessLoop:
    def __init__(
        self, sim: SimulatorComponent, components: Sequence[Component], observers: Sequence[Observer] = (), observed: Collection[str] = ()
    ) -> None:
        """`observers` see every message on the `observed` topics (a recorder, say)."""
        self.sim = sim
        self.components = list(components)
        self.observers = list(observers)
        self._inbox: dict[str, list[Message]] = {c.name: [] for c in self.components}
        self._handlers = {c.name: dict(c.handlers()) for c in self.components}
        self._rank = {c.name: {t: i for i, t in enumerate(self._handlers[c.name])} for c in self.components}
        self._sim_handlers = dict(sim.handlers())
        self._periods = {c.name: period_ns(1.0 / c.period_s) if c.period_s else None for c in self.components}
        self.step_ns = sim.config.sim.step_ns
        # Tell each component which of its outputs nobody reads, so it may skip making them.
        read = set(observed) | set(self._sim_handlers) | {t for h in self._handlers.values() for t in h}
        for c in [sim, *self.components]:
            c.unread = frozenset(t for t in c.outputs() if t not in read)
        self.observed = frozenset(observed)

    def _route(self, messages: Sequence[Message], to_sim: bool) -> None:
        for m in messages:
            if m.topic in self.observed:
                for observer in self.observers:
                    observer(m)
            for c in self.components:
                if m.topic in self._handlers[c.name]:
                    self._inbox[c.name].append(m)
            if to_sim and m.topic in self._sim_handlers:
                self._sim_handlers[m.topic](m.data, m.stamp)

    def publish(self, messages: Sequence[Message]) -> None:
        """Messages from outside the loop (a study condition set by the caller, say)."""
        self._route(messages, to_sim=True)

    def step(self) -> None:
        k, now = self.sim.sim.steps, self.sim.sim.time
        self._route(self.sim.sense(), to_sim=False)
        produced: list[Message] = []
        for c in self.components:
            inbox, self._inbox[c.name] = self._inbox[c.name], []
            handlers = self._handlers[c.name]
            for m in inbox_order(self._rank[c.name], inbox):
                produced += handlers[m.topic](m.data, now)
            every = self._periods[c.name]
            if every is not None and due(k, self.step_ns, every):
                produced += c.tick(now)
        self._route(produced, to_sim=True)
        self.sim.advance()

    def run_until(self, stop: Callable[[], bool], max_steps: int) -> None:
        for _ in range(max_steps):
            if stop():
                return
            self.step()

