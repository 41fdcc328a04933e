"""Velocity multiplexer: teleop beats navigation, an emergency stop beats both.

Teleop holds control while its commands keep coming and hands it back `teleop_timeout_s` after the
last one; navigation commands go stale after `nav_timeout_s`.

The e-stop (/haven/estop, std_msgs/Bool) may have several publishers: a latched one (`haven estop`),
`ros2 topic pub` repeating once a second, a watchdog node. Messages do not say who sent them, so a
`true` from anyone stops the robot at once, and a `false` releases it only when no `true` has come
for `estop_hold_s` (longer than `ros2 topic pub`'s 1 s repeat): one publisher that keeps the stop
on is never overridden by another that says all is well. `MuxComponent` is the whole mux node
without ROS: it forwards the winning command on every input and at `rate_hz`, sends one zero when
every source has gone quiet (so the robot stops at once instead of waiting for the simulator's
watchdog), and reports every change of source as a `cmd_source` event (a teleop takeover is part
of a study's record). Time is an argument.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from haven_sim.common import nodes, topics
from haven_sim.common.component import Handler, Message
from haven_sim.common.events import EventKind, Source, event
from haven_sim.common.geometry import ZERO_TWIST, Twist2D
from haven_sim.common.params import POSITIVE, config, param
from haven_sim.sim.estop import ESTOP_HOLD_S, EStopLatch

NAV, TELEOP, ESTOP, IDLE = "nav", "teleop", "estop", "idle"


@config
class MuxConfig:
    teleop_timeout_s: float = param(0.5, "teleop hands control back this long after its last command", POSITIVE)
    nav_timeout_s: float = param(0.5, "navigation commands older than this are stale", POSITIVE)
    rate_hz: float = param(20.0, "/cmd_vel is re-sent at this rate while a source is active", POSITIVE)
    estop_hold_s: float = param(
        ESTOP_HOLD_S, "a false on /haven/estop releases the stop only when no true has come for this long", POSITIVE
    )


@dataclass(frozen=True)
class MuxOutput:
    twist: Twist2D
    source: str  # nav | teleop | estop | idle


class VelocityMux:
    def __init__(
        self, teleop_timeout_s: float = 0.5, nav_timeout_s: float = 0.5, estop_hold_s: float = ESTOP_HOLD_S
    ) -> None:
        self.teleop_timeout_s = teleop_timeout_s
        self.nav_timeout_s = nav_timeout_s
        self.latch = EStopLatch(estop_hold_s)
        self._teleop = (ZERO_TWIST, -math.inf)
        self._nav = (ZERO_TWIST, -math.inf)

    def on_teleop(self, twist: Twist2D, now: float) -> None:
        self._teleop = (twist, now)

    def on_nav(self, twist: Twist2D, now: float) -> None:
        self._nav = (twist, now)

    def set_estop(self, engaged: bool, now: float) -> None:
        self.latch.said(engaged, now)

    def estop(self, now: float) -> bool:
        return self.latch.engaged(now)

    def output(self, now: float) -> MuxOutput:
        if self.estop(now):
            return MuxOutput(ZERO_TWIST, ESTOP)
        twist, stamp = self._teleop
        if now - stamp <= self.teleop_timeout_s:
            return MuxOutput(twist, TELEOP)
        twist, stamp = self._nav
        if now - stamp <= self.nav_timeout_s:
            return MuxOutput(twist, NAV)
        return MuxOutput(ZERO_TWIST, IDLE)


class MuxComponent:
    name = nodes.MUX.name
    unread: frozenset[str] = frozenset()
    relays_pace = True  # on the free-running clock, passes the controller's pace on to the simulator (topics.PACE)

    def __init__(self, config: MuxConfig | None = None) -> None:
        self.config = config or MuxConfig()
        self.mux = VelocityMux(self.config.teleop_timeout_s, self.config.nav_timeout_s, self.config.estop_hold_s)
        self._last_source = IDLE

    @property
    def period_s(self) -> float:
        return 1.0 / self.config.rate_hz

    def handlers(self) -> Mapping[str, Handler]:
        return {topics.CMD_VEL_NAV: self.on_nav, topics.CMD_VEL_TELEOP: self.on_teleop, topics.ESTOP: self.on_estop}

    def outputs(self) -> Sequence[str]:
        return (topics.CMD_VEL, topics.EVENTS)

    def on_nav(self, twist: Twist2D, now: float) -> list[Message]:
        self.mux.on_nav(twist, now)
        return self.tick(now)

    def on_teleop(self, twist: Twist2D, now: float) -> list[Message]:
        self.mux.on_teleop(twist, now)
        return self.tick(now)

    def on_estop(self, engaged: bool, now: float) -> list[Message]:
        self.mux.set_estop(engaged, now)
        return self.tick(now)

    def tick(self, now: float) -> list[Message]:
        out = self.mux.output(now)
        msgs: list[Message] = []
        if out.source != self._last_source:
            change = event(EventKind.CMD_SOURCE, now, Source.MUX, **{"from": self._last_source, "to": out.source})
            msgs.append(Message(topics.EVENTS, change, now))
        if out.source != IDLE or self._last_source != IDLE:
            msgs.append(Message(topics.CMD_VEL, out.twist, now))
        self._last_source = out.source
        return msgs
