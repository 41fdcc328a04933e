"""The lockstep rule both modes keep, so that a trial's outcome does not depend on machine load.

Sim time advances in physics steps. At step k:
  1. the simulator publishes its state for step k (clock, /odom, /humans, ...);
  2. the participants that *act* at k handle what they have received so far (the simulator's
     messages up to step k, other participants' messages up to step k - 1), in a fixed order,
     then do their periodic work if it is due; what they publish reaches the simulator before it
     advances and the other participants at step k + 1;
  3. the simulator applies the commands and advances to step k + 1.
A participant acts at step k when its period is due, or when another participant published one of
its input topics during step k - 1. The simulator's own messages do not make anyone act: they carry
state that a participant reads when it next acts (the handlers of state topics only keep the
latest value), which keeps most steps free of any round trip.

Batch mode applies this rule in one process (`runtime.loop`); in ROS mode the simulator node is the
coordinator (it sends a tick naming who acts and waits for their acknowledgements) and each
participant node defers its subscriptions until its tick (`haven_sim.nodes.lockstep`).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field

from haven_sim.common import topics
from haven_sim.common.events import Event
from haven_sim.common.params import param
from haven_sim.runtime.component import Component, Message, due, period_ns

UNCAPPED_RTF = 1e6  # a lockstep real-time factor this high means "as fast as the participants go"


@dataclass(frozen=True)
class LockstepParams:
    lockstep: bool = param(False, "step with the simulator's lockstep clock (haven run sets it for simulated participants)")


@dataclass(frozen=True)
class ParticipantInfo:
    """What the coordinator knows of a participant: its period and the topics it reads."""

    name: str
    period_ns: int | None
    inputs: frozenset[str]

    @staticmethod
    def of(component: Component) -> ParticipantInfo:
        every = period_ns(1.0 / component.period_s) if component.period_s else None
        return ParticipantInfo(component.name, every, frozenset(component.handlers()))


@dataclass
class Schedule:
    """Who acts at each step: due periods, and readers of what participants published last step."""

    step_ns: int
    participants: dict[str, ParticipantInfo] = field(default_factory=dict)
    _pending: set[str] = field(default_factory=set)

    def add(self, info: ParticipantInfo) -> None:
        self.participants[info.name] = info

    def published(self, by: str, topics: Iterable[str]) -> None:
        """Participant `by` published these topics while acting: their other readers act at the
        next step (a participant hears its own messages when it next acts anyway)."""
        wanted = set(topics)
        self._pending |= {p.name for p in self.participants.values() if p.inputs & wanted and p.name != by}

    def acting(self, step: int) -> list[str]:
        """The participants that act at `step` (in registration order); clears their pending flag."""
        out = [
            p.name
            for p in self.participants.values()
            if p.name in self._pending or (p.period_ns is not None and due(step, self.step_ns, p.period_ns))
        ]
        self._pending -= set(out)
        return out


def inbox_order(rank: Mapping[str, int], inbox: Sequence[Message]) -> list[Message]:
    """The order a participant handles what it received: by its topics' order (`rank`), events by
    (stamp, source), other topics as they came (each has one publisher); of a state stream
    (`topics.STATE`) only the newest message."""
    newest = {m.topic: i for i, m in enumerate(inbox) if m.topic in topics.STATE}
    inbox = [m for i, m in enumerate(inbox) if m.topic not in topics.STATE or newest[m.topic] == i]
    if len(inbox) < 2:
        return list(inbox)

    def key(m: Message) -> tuple[int, float, str]:
        if isinstance(m.data, Event):
            return (rank.get(m.topic, len(rank)), m.data.stamp, m.data.source)
        return (rank.get(m.topic, len(rank)), 0.0, "")

    return sorted(inbox, key=key)
