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

import json
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import asdict, dataclass, field
from typing import Any

from haven_sim.common import topics
from haven_sim.common.component import Component, Message, due, period_ns
from haven_sim.common.events import Event
from haven_sim.common.params import config, param

UNCAPPED_RTF = 1e6  # a lockstep real-time factor this high means "as fast as the participants go"
MAX_DIGESTS = 100_000  # more messages announced in one tick or ack than any step makes: refused as forged


@config
class LockstepParams:
    lockstep: bool = param(
        False, "step with the simulator's lockstep clock (haven run sets it for simulated participants)"
    )
    lockstep_open: tuple[str, ...] = param(
        (),
        "topics the suite writes on which messages from outside "
        "are still taken on the lockstep clock (haven run --allow)",
    )


# -- the protocol's messages (JSON strings on /haven/lockstep/*), checked as any input is ----------
def _load(text: str, what: str) -> dict[str, Any]:
    try:
        d = json.loads(text) if len(text) <= 1 << 20 else None
    except (ValueError, RecursionError):
        d = None
    if not isinstance(d, dict):
        raise ValueError(f"not a lockstep {what}: {text[:40]!r}")
    return d


def _int(d: Mapping[str, Any], key: str, what: str, optional: bool = False) -> int:
    v = d.get(key)
    if optional and v is None:
        return -1
    if isinstance(v, bool) or not isinstance(v, int) or not 0 <= v <= 2**62:
        raise ValueError(f"lockstep {what}: {key} must be a non-negative integer, got {str(v)[:40]}")
    return v


def _digests(d: Mapping[str, Any], key: str, what: str) -> dict[str, list[str]]:
    v = d.get(key)
    if (
        isinstance(v, dict)
        and all(
            isinstance(t, str) and isinstance(ds, list) and all(isinstance(x, str) for x in ds) for t, ds in v.items()
        )
        and sum(len(ds) for ds in v.values()) <= MAX_DIGESTS
    ):
        return {t: list(ds) for t, ds in v.items()}
    raise ValueError(f"lockstep {what}: {key} must map topics to message digests, got {str(v)[:40]}")


def _names(d: Mapping[str, Any], key: str, what: str) -> list[str]:
    v = d.get(key)
    if not isinstance(v, list) or not all(isinstance(t, str) for t in v):
        raise ValueError(f"lockstep {what}: {key} must be a list of names, got {str(v)[:40]}")
    return list(v)


def _name(d: Mapping[str, Any], what: str) -> str:
    v = d.get("node")
    if not isinstance(v, str):
        raise ValueError(f"lockstep {what}: node must be a name, got {str(v)[:40]}")
    return v


@dataclass(frozen=True)
class Tick:
    """Coordinator -> one participant: act at `step` (time `t_ns`), having received the suite's
    messages `expect` names (digests per topic, `runtime.suite_messages`); `owned`: its inputs
    that the suite writes."""

    step: int
    t_ns: int
    step_ns: int
    expect: dict[str, list[str]]
    owned: list[str]

    def to_json(self) -> str:
        return json.dumps(asdict(self))

    @staticmethod
    def from_json(text: str) -> Tick:
        d = _load(text, "tick")
        step, t_ns, step_ns = _int(d, "step", "tick"), _int(d, "t_ns", "tick"), max(1, _int(d, "step_ns", "tick"))
        return Tick(step, t_ns, step_ns, _digests(d, "expect", "tick"), _names(d, "owned", "tick"))


@dataclass(frozen=True)
class Hello:
    """Participant -> coordinator: who it is, its period, its topics, whether it has matched, and
    how many readers each of its publishers has matched (`matched`: the coordinator holds them to
    the readers it sees, the recorder's among them)."""

    node: str
    period_ns: int | None
    inputs: list[str]
    outputs: list[str]
    ready: bool
    matched: dict[str, int] = field(default_factory=dict)

    def to_json(self) -> str:
        return json.dumps(asdict(self))

    @staticmethod
    def from_json(text: str) -> Hello:
        d = _load(text, "hello")
        period = _int(d, "period_ns", "hello", optional=True)
        if not isinstance(d.get("ready"), bool):
            raise ValueError(f"lockstep hello: ready must be true or false, got {str(d.get('ready'))[:40]}")
        matched = d.get("matched", {})
        if not isinstance(matched, dict) or not all(
            isinstance(t, str) and type(n) is int and 0 <= n < 1 << 20 for t, n in matched.items()
        ):
            raise ValueError(f"lockstep hello: matched must map topics to reader counts, got {str(matched)[:40]}")
        name, inputs, outputs = _name(d, "hello"), _names(d, "inputs", "hello"), _names(d, "outputs", "hello")
        return Hello(name, None if period < 0 else max(1, period), inputs, outputs, d["ready"], dict(matched))


@dataclass(frozen=True)
class Ack:
    """Participant -> coordinator: done with `step`, having published the messages `sent` names
    (digests per topic)."""

    node: str
    step: int
    sent: dict[str, list[str]]

    def to_json(self) -> str:
        return json.dumps(asdict(self))

    @staticmethod
    def from_json(text: str) -> Ack:
        d = _load(text, "ack")
        return Ack(_name(d, "ack"), _int(d, "step", "ack"), _digests(d, "sent", "ack"))


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
        return [name for name, _ in self.acting_ticks(step)]

    def acting_ticks(self, step: int) -> list[tuple[str, bool]]:
        """`acting`, each with whether its period is due at `step` (it ticks as well as handling its inbox)."""
        pending, step_ns = self._pending, self.step_ns
        out = []
        for name, p in self.participants.items():
            ticks = p.period_ns is not None and due(step, step_ns, p.period_ns)
            if ticks or name in pending:
                out.append((name, ticks))
        pending.difference_update(name for name, _ in out)
        return out


def inbox_order(rank: Mapping[str, int], inbox: Sequence[Message]) -> list[Message]:
    """The order a participant handles what it received: by its topics' order (`rank`), events by
    (stamp, source), other topics as they came (each has one publisher); of a state stream
    (`topics.STATE`) only the newest message."""
    if len(inbox) < 2:
        return list(inbox)
    newest = {m.topic: i for i, m in enumerate(inbox) if m.topic in topics.STATE}
    inbox = [m for i, m in enumerate(inbox) if m.topic not in topics.STATE or newest[m.topic] == i]
    if len(inbox) < 2:
        return list(inbox)

    def key(m: Message) -> tuple[int, float, str]:
        if isinstance(m.data, Event):
            return (rank.get(m.topic, len(rank)), m.data.stamp, m.data.source)
        return (rank.get(m.topic, len(rank)), 0.0, "")

    return sorted(inbox, key=key)
