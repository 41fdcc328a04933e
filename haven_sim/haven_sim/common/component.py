"""How behaviour runs in both modes: components that take messages and time, and return messages.

A `Component` is a node's whole behaviour with no ROS in it. It names the topics it reads
(`handlers`: topic -> handler) and writes (`outputs`), reacts to each input, and, if it has a
`period_s`, does periodic work in `tick`. A node (ROS mode) calls the handlers from subscription
callbacks and `tick` from a timer; batch mode calls the very same methods from the in-process loop
(`runtime.loop`), at the same rates. Payloads are the core types (Pose2D, Twist2D, Event, ...) and
each outgoing `Message` carries the sim time it belongs to (the header stamp on the wire).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Protocol

NS_PER_S = 1_000_000_000


@dataclass(frozen=True)
class Message:
    topic: str
    data: Any
    stamp: float  # sim seconds


Handler = Callable[[Any, float], Sequence[Message]]


class Component(Protocol):
    name: str  # the node's name
    unread: frozenset[str]  # outputs nobody reads (set by the runtime): the component may skip them

    @property
    def period_s(self) -> float | None: ...  # None: no periodic work

    def handlers(self) -> Mapping[str, Handler]: ...

    def outputs(self) -> Sequence[str]: ...

    def tick(self, now: float) -> Sequence[Message]: ...


def period_ns(rate_hz: float) -> int:
    return round(NS_PER_S / rate_hz)


def due(step: int, step_ns: int, every_ns: int) -> bool:
    """Whether a component with period `every_ns` ticks at physics step `step`: at step 0 and at the
    first step at or after each further multiple of its period (what a sim-time timer does when the
    clock advances in steps), computed on integers so every mode agrees."""
    return step == 0 or (step * step_ns) // every_ns != ((step - 1) * step_ns) // every_ns
