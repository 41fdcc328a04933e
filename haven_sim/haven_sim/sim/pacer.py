"""Keeps sim time running at `real_time_factor` x wall time, in whole physics steps.

The simulator node calls `due_steps(wall_now)` from a short wall-clock timer and runs that many
steps (wall_now from a `WallClock`, so a pause stops it without a burst after). Tying steps to
elapsed wall time (not to timer callbacks) keeps the average rate exact even when individual
callbacks fire late; a cap stops a long stall from turning into a burst.
"""

from __future__ import annotations

import time
from collections.abc import Callable


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

    @property
    def tick_period_s(self) -> float:
        """A wall-clock timer period that sees every step on time (bounded for high factors)."""
        return max(self.step_s / self.real_time_factor, 0.001)

    def due_steps(self, wall_now: float) -> int:
        if self._wall0 is None:
            self._wall0 = wall_now
        target = int((wall_now - self._wall0) * self.real_time_factor / self.step_s + 1e-9)
        due = target - self._steps
        if due > self.max_catch_up_steps:
            # Fell behind (a stall, or the CPU cannot keep up): drop the backlog instead of bursting.
            self._steps = target - self.max_catch_up_steps
            due = self.max_catch_up_steps
        due = max(due, 0)
        self._steps += due
        return due
