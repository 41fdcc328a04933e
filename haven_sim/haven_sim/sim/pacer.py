"""Keeps sim time running at `real_time_factor` x wall time, in whole physics steps.

The simulator node calls `due_steps(wall_now)` from a short wall-clock timer and runs that many
steps (wall_now from a `WallClock`, so a pause stops it without a burst after). Tying steps to
elapsed wall time (not to timer callbacks) keeps the average rate exact even when individual
callbacks fire late; a cap stops a long stall from turning into a burst.

A control loop that falls behind holds the clock (`due_steps`' `allowed`): the steps it has not
kept up with are dropped, not owed, so simulated time runs slower than asked (a real-time factor
below 1 at 1x) instead of the robot driving on a command computed from an old pose.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable

from haven_sim.common.topics import PACE_IDLE


class WallClock:
    """Wall time with the pauses taken out: pacing against it neither steps while paused nor
    catches up for the pause afterwards (the simulator's pause, `haven/pause`)."""

    def __init__(self, source: Callable[[], float] = time.monotonic) -> None:
        self.source = source
        self._paused_at: float | None = None
        self._paused_total = 0.0

    @property
    def paused(self) -> bool:
        return self._paused_at is not None

    def now(self) -> float:
        return (self._paused_at if self._paused_at is not None else self.source()) - self._paused_total

    def pause(self) -> bool:
        """Stop the clock; False if it already was."""
        if self._paused_at is not None:
            return False
        self._paused_at = self.source()
        return True

    def resume(self) -> float | None:
        """Start it again: how long it stood (wall seconds), None if it was not paused."""
        if self._paused_at is None:
            return None
        stood = self.source() - self._paused_at
        self._paused_total += stood
        self._paused_at = None
        return stood


class Pacer:
    def __init__(self, step_s: float, real_time_factor: float, max_catch_up_steps: int = 10) -> None:
        if not step_s > 0:
            raise ValueError(f"step_s must be positive, got {step_s}")
        if not real_time_factor > 0:
            raise ValueError(f"real_time_factor must be positive, got {real_time_factor}")
        self.step_s = step_s
        self.real_time_factor = real_time_factor
        self.max_catch_up_steps = max_catch_up_steps
        self._wall0: float | None = None
        self._steps = 0
        self.holding = False  # the last call ran fewer steps than were due (held by a control loop)

    @property
    def tick_period_s(self) -> float:
        """A wall-clock timer period that sees every step on time (bounded for high factors)."""
        return max(self.step_s / self.real_time_factor, 0.001)

    def due_steps(self, wall_now: float, allowed: int | None = None) -> int:
        """Steps to run now; at most `allowed` (what a control loop that lags lets the clock go
        ahead), the rest dropped: simulated time slows rather than catching up in a burst later."""
        if self._wall0 is None:
            self._wall0 = wall_now
        target = int((wall_now - self._wall0) * self.real_time_factor / self.step_s + 1e-9)
        due = target - self._steps
        if due > self.max_catch_up_steps:
            # Fell behind (a stall, or the CPU cannot keep up): drop the backlog instead of bursting.
            self._steps = target - self.max_catch_up_steps
            due = self.max_catch_up_steps
        due = max(due, 0)
        self.holding = allowed is not None and due > max(allowed, 0)
        if self.holding:
            self._steps = target  # (held: the steps not run are not owed)
            return max(allowed or 0, 0)
        self._steps += due
        return due


class ControlPace:
    """How far simulated time may run ahead of a control loop (free-running clock only).

    The controller says after each of its ticks which sim time it has acted at (`report`); the
    clock goes at most `lag_s` (and never less than two of its periods, the shortest interval seen
    between reports, so it can always tick again) beyond it. A loop that stays silent for `silence_s` of wall time
    (stopped, or left out with `--without`) holds nothing. `factor` is the real-time factor achieved over each REPORT_S
    of wall time in which the clock was held: the price of an exact trial on a busy machine, which the simulator
    reports."""

    REPORT_S = 5.0

    def __init__(self, lag_s: float, silence_s: float = 5.0) -> None:
        self.lag_s, self.silence_s = lag_s, silence_s
        self.acted_at: float | None = None
        self._heard = -math.inf  # wall time of the last report
        self._interval = math.inf  # the shortest between two reports (sim time): the loop's own period
        self._window: tuple[float, float] | None = None  # (wall, sim) when the report window began
        self.held = False  # held in the current window

    def report(self, acted_at: float, wall_now: float) -> None:
        """`acted_at`: the sim time the loop has acted at, or topics.PACE_IDLE: it drives nothing
        now (no path, or waiting), and holds nothing."""
        if acted_at >= PACE_IDLE:
            self.acted_at = None
            return
        if self.acted_at is not None and acted_at > self.acted_at:  # (a late loop's gaps are longer: not its period)
            self._interval = min(self._interval, acted_at - self.acted_at)
        self.acted_at, self._heard = acted_at, wall_now

    def allowed_steps(self, sim_now: float, step_s: float, wall_now: float) -> int | None:
        """Steps the clock may take now; None: not held."""
        if self.lag_s <= 0 or self.acted_at is None or wall_now - self._heard > self.silence_s:
            return None
        ahead = (
            self.acted_at + max(self.lag_s, 2.0 * self._interval if math.isfinite(self._interval) else 0.0) - sim_now
        )
        return max(0, int(ahead / step_s + 1e-9))

    def factor(self, sim_now: float, wall_now: float, held: bool) -> float | None:
        """At the end of a report window in which the clock was held: the factor it achieved."""
        self.held = self.held or held
        if self._window is None:
            self._window = (wall_now, sim_now)
            return None
        wall0, sim0 = self._window
        if wall_now - wall0 < self.REPORT_S:
            return None
        was_held, self.held, self._window = self.held, False, (wall_now, sim_now)
        return (sim_now - sim0) / (wall_now - wall0) if was_held else None
