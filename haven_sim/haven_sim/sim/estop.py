"""The e-stop rule every reader of /haven/estop keeps (the velocity mux, and the simulator, which
nothing bypasses). Messages do not say who sent them, so a `true` from anyone stops the robot at
once, and a `false` releases it only when no `true` has come for `ESTOP_HOLD_S`: one publisher that
keeps the stop on (`ros2 topic pub` repeats once a second) is never overridden by another that says
all is well. Time is an argument.
"""

from __future__ import annotations

import math

ESTOP_HOLD_S = 2.0  # longer than `ros2 topic pub`'s 1 s repeat (the rule above)


class EStopLatch:
    """The e-stop as each of its readers keeps it (the mux, and the simulator, which nothing
    bypasses): a true from anyone stops at once; a false releases only when no true has come for
    `hold_s`. Time is an argument."""

    def __init__(self, hold_s: float = ESTOP_HOLD_S) -> None:
        self.hold_s = hold_s
        self._said = False  # the latest e-stop message
        self._true_at = -math.inf  # when a true last came

    def said(self, engaged: bool, now: float) -> None:
        self._said = engaged
        if engaged:
            self._true_at = now

    def engaged(self, now: float) -> bool:
        return self._said or now - self._true_at < self.hold_s
