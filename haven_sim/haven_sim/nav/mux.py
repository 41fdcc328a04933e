"""Velocity multiplexer: teleop beats navigation, an emergency stop beats both.

Teleop holds control while its commands keep coming and hands it back `teleop_timeout_s` after the
last one; navigation commands go stale after `nav_timeout_s`. Time is an argument.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from haven_sim.common.geometry import ZERO_TWIST, Twist2D

NAV, TELEOP, ESTOP, IDLE = "nav", "teleop", "estop", "idle"


@dataclass(frozen=True)
class MuxOutput:
    twist: Twist2D
    source: str  # nav | teleop | estop | idle


class VelocityMux:
    def __init__(self, teleop_timeout_s: float = 0.5, nav_timeout_s: float = 0.5) -> None:
        self.teleop_timeout_s = teleop_timeout_s
        self.nav_timeout_s = nav_timeout_s
        self.estop = False
        self._teleop = (ZERO_TWIST, -math.inf)
        self._nav = (ZERO_TWIST, -math.inf)

    def on_teleop(self, twist: Twist2D, now: float) -> None:
        self._teleop = (twist, now)

    def on_nav(self, twist: Twist2D, now: float) -> None:
        self._nav = (twist, now)

    def set_estop(self, engaged: bool) -> None:
        self.estop = engaged

    def output(self, now: float) -> MuxOutput:
        if self.estop:
            return MuxOutput(ZERO_TWIST, ESTOP)
        twist, stamp = self._teleop
        if now - stamp <= self.teleop_timeout_s:
            return MuxOutput(twist, TELEOP)
        twist, stamp = self._nav
        if now - stamp <= self.nav_timeout_s:
            return MuxOutput(twist, NAV)
        return MuxOutput(ZERO_TWIST, IDLE)
