"""Which messages on the lockstep clock are the suite's, and what becomes of the others.

Every message a lockstep node publishes on a topic another node of the suite reads is named by a
digest of its serialized bytes; each participant's tick lists the digests of the suite's messages
it is to receive (`Expected`), so it waits for exactly those, whoever else publishes on the same
topic. A reader's queue is matched against the list (`Queue.split`): the suite's messages are
handled as the lockstep rule says, any other message is from outside the suite. On a topic the
suite writes (it owns it on this clock: a second suite's or a flooding node's goals, plans or
poses), outside messages are ignored and counted, unless the run opened the topic (`haven run
--allow`); on a topic no suite node writes (/haven/estop, /cmd_vel_teleop, /haven/trial_control)
they are the input and are handled, at most `InputLimit`'s rate. A message nobody announced stays
in the queue for one more act before it counts as outside: another participant acting at the same
step may have published it, and its digest comes with the next tick.

A message that was announced but does not arrive within the wait is given up (counted as lost,
said once), and if it arrives later it is dropped: a loss costs one wait, never every step after.
"""

from __future__ import annotations

import hashlib
from collections import Counter
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import TypeVar

from haven_sim.common import topics

T = TypeVar("T")
OUTSIDE_RATE_HZ = 100.0  # outside messages handled per topic per second of sim time (a joystick teleop sends 50)
OUTSIDE_BURST = 100  # ... and at once after a pause


def digest(data: bytes) -> str:
    """A message's name on the lockstep clock: 64 bits of BLAKE2b of its serialized bytes, trailing
    zero bytes left out (a reader gets the CDR data padded to a multiple of 4 bytes with zeros, as
    measured with Fast DDS here, while the header's padding count stays 0; CDR is length-prefixed,
    so two messages of one type never differ in trailing zeros alone)."""
    return hashlib.blake2b(data.rstrip(b"\0"), digest_size=8).hexdigest()


def is_state(topic: str) -> bool:
    """A state stream (`topics.STATE`): only its newest message matters to a reader."""
    return topic.lstrip("/") in {t.lstrip("/") for t in topics.STATE}


@dataclass
class Expected:
    """The coordinator's books: per participant, the digests of the suite's messages on its inputs
    published since its last tick (of a state stream only the newest)."""

    readers: dict[str, set[str]] = field(default_factory=dict)  # topic -> participants reading it
    pending: dict[str, dict[str, list[str]]] = field(default_factory=dict)  # participant -> topic -> digests

    def reads(self, participant: str, inputs: Iterable[str]) -> None:
        self.pending.setdefault(participant, {})
        for t in inputs:
            self.readers.setdefault(t, set()).add(participant)

    def sent(self, topic: str, digests: Sequence[str]) -> None:
        """The suite published these messages on `topic`: each reader is to receive them."""
        if not digests:
            return
        state = is_state(topic)
        for p in self.readers.get(topic, ()):
            queued = self.pending[p].setdefault(topic, [])
            if state:
                queued[:] = digests[-1:]
            else:
                queued += digests

    def take(self, participant: str) -> dict[str, list[str]]:
        """What `participant` is to receive now; its books start again."""
        out, self.pending[participant] = self.pending.get(participant, {}), {}
        return out


@dataclass
class Queued:
    digest: str
    raw: bytes
    waited: int = 0  # acts it has stayed unmatched


@dataclass
class Queue:
    """One reader's queue on one topic, in arrival order."""

    topic: str
    settle: int = 1  # acts an unannounced message waits before it counts as outside (the coordinator: 0)
    entries: list[Queued] = field(default_factory=list)
    given_up: Counter[str] = field(default_factory=Counter)  # announced, waited for in vain: dropped if they come
    # the digests queued (kept with the entries: a flood makes many)
    have: Counter[str] = field(default_factory=Counter)

    def add(self, raw: Iterable[bytes]) -> None:
        new = [Queued(digest(r), r) for r in raw]
        self.entries += new
        self.have.update(e.digest for e in new)

    def missing(self, expected: Sequence[str]) -> Counter[str]:
        """Announced digests not (yet) in the queue."""
        return Counter(expected) - self.have

    def give_up(self, missing: Counter[str]) -> None:
        self.given_up += missing

    def split(self, expected: Sequence[str]) -> tuple[list[bytes], list[bytes]]:
        """(the suite's announced messages, in arrival order; the messages from outside); what is
        neither yet stays queued. Of a state stream the suite's part is its announced newest
        message, everything before it is dropped, everything after it is from outside."""
        if is_state(self.topic):
            return self._split_state(expected[-1] if expected else None)
        wanted, ours, outside, kept = Counter(expected), [], [], []
        for e in self.entries:
            if wanted[e.digest] > 0:
                wanted[e.digest] -= 1
                ours.append(e.raw)
            elif self._late(e):
                continue
            elif e.waited >= self.settle:
                outside.append(e.raw)
            else:
                e.waited += 1
                kept.append(e)
        self.entries, self.have = kept, Counter(e.digest for e in kept)
        return ours, outside

    def _split_state(self, newest: str | None) -> tuple[list[bytes], list[bytes]]:
        # (the simulator publishes a state stream only before it ticks, announcing it at once: no
        # message of the suite's can be queued unannounced)
        at = max((i for i, e in enumerate(self.entries) if e.digest == newest), default=None)
        if at is None:
            ours, outside = [], [e.raw for e in self.entries if not self._late(e)]
        else:
            ours, outside = [self.entries[at].raw], [e.raw for e in self.entries[at + 1 :]]
        self.entries, self.have = [], Counter()
        return ours, outside

    def _late(self, e: Queued) -> bool:
        """An announced message that came after it was given up (dropped: handled as lost)."""
        if self.given_up[e.digest] > 0:
            self.given_up[e.digest] -= 1
            return True
        return False


@dataclass
class InputLimit:
    """At most `rate_hz` outside messages per topic per second of sim time (`burst` at once); the
    rest are dropped and counted. The newest are the ones kept."""

    rate_hz: float = OUTSIDE_RATE_HZ
    burst: int = OUTSIDE_BURST
    tokens: dict[str, float] = field(default_factory=dict)
    last: dict[str, float] = field(default_factory=dict)
    dropped: Counter[str] = field(default_factory=Counter)

    def admit(self, topic: str, messages: Sequence[T], now: float) -> list[T]:
        if not messages:
            return []
        elapsed = max(0.0, now - self.last.get(topic, now))
        tokens = min(float(self.burst), self.tokens.get(topic, float(self.burst)) + elapsed * self.rate_hz)
        n = min(len(messages), int(tokens + 1e-9))
        self.tokens[topic], self.last[topic] = tokens - n, now
        self.dropped[topic] += len(messages) - n
        return list(messages[len(messages) - n :])


@dataclass
class OutsideInputs:
    """What a lockstep reader does with messages from outside the suite, and how many there were."""

    owned: frozenset[str] = frozenset()  # topics the suite writes (on this clock, the suite's alone)
    opened: frozenset[str] = frozenset()  # ... of which the run takes outside messages all the same
    limit: InputLimit = field(default_factory=InputLimit)
    ignored: Counter[str] = field(default_factory=Counter)
    taken: Counter[str] = field(default_factory=Counter)

    def take(self, topic: str, messages: Sequence[bytes], now: float) -> list[bytes]:
        """The outside messages to handle (the rest counted as ignored or dropped)."""
        name = "/" + topic.lstrip("/")
        if (name in self.owned and name not in self.opened) or is_state(topic):
            self.ignored[name] += len(messages)
            return []
        admitted = self.limit.admit(name, messages, now)
        self.taken[name] += len(admitted)
        return admitted


def absolute(names: Iterable[str]) -> frozenset[str]:
    return frozenset("/" + n.lstrip("/") for n in names)


def owned_topics(outputs: Mapping[str, Iterable[str]]) -> frozenset[str]:
    """The topics some suite node writes (node -> its outputs)."""
    return absolute(t for ts in outputs.values() for t in ts)
