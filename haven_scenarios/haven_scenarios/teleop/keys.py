"""Keyboard to velocity for a participant at a terminal: the pure part of `haven teleop`.

Terminals report key presses, not releases, so a key counts as held while its auto-repeat keeps
arriving: the command lasts `hold_s` after the latest press of its key.
"""

from __future__ import annotations

from dataclasses import dataclass

from haven_sim.common.geometry import Twist2D

HELP = "w/s forward/back, a/d step left/right, q/e turn left/right, space stop, x quit"


@dataclass
class KeyMapper:
    speed_mps: float = 1.0
    turn_rps: float = 1.5
    hold_s: float = 0.35

    def __post_init__(self) -> None:
        self._pressed: dict[str, float] = {}

    def press(self, key: str, now: float) -> None:
        if key == " ":
            self._pressed.clear()
        elif key in "wsadqe":
            self._pressed[key] = now

    def command(self, now: float) -> Twist2D:
        held = {k for k, t in self._pressed.items() if now - t <= self.hold_s}
        v = self.speed_mps * (("w" in held) - ("s" in held))
        side = self.speed_mps * (("a" in held) - ("d" in held))
        w = self.turn_rps * (("q" in held) - ("e" in held))
        return Twist2D(float(v), float(side), float(w))
