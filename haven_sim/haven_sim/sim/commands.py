"""Velocity commands: limits, clamping, acceleration ramps and the command watchdog.

Time is always an argument (`now`, `dt`), so every rule here is unit-tested without a clock.
"""

from __future__ import annotations

import math
from enum import Enum

from haven_sim.common.geometry import ZERO_TWIST, Twist2D
from haven_sim.common.params import NOT_NEGATIVE, POSITIVE, config, internal, param
from haven_sim.robots.description import Limits


@config
class VelocityLimits:
    """Speed and acceleration limits (a robot's from its robot file: `VelocityLimits.of(robot)`)."""

    max_linear_speed_mps: float = param(0.7, "top speed", POSITIVE)
    max_angular_speed_rps: float = param(math.pi, "top turn rate", POSITIVE)
    max_linear_accel_mps2: float = param(0.5, "acceleration limit", POSITIVE)
    max_angular_accel_rps2: float = param(3.5, "angular acceleration limit", POSITIVE)
    max_lateral_speed_mps: float = internal(0.0, NOT_NEGATIVE)  # 0: differential drive

    @staticmethod
    def of(limits: Limits) -> VelocityLimits:
        """A robot's limits, from its description."""
        return VelocityLimits(
            limits.max_linear_speed_mps,
            limits.max_angular_speed_rps,
            limits.max_linear_accel_mps2,
            limits.max_angular_accel_rps2,
            limits.max_lateral_speed_mps,
        )

    @staticmethod
    def human(max_speed_mps: float = 1.5) -> VelocityLimits:
        """A walking person: holonomic, quick to start and stop."""
        return VelocityLimits(max_speed_mps, 2.0 * math.pi, 3.0, 12.0, max_speed_mps)


class CommandStatus(Enum):
    ACCEPTED = "accepted"
    CLAMPED = "clamped"
    REJECTED = "rejected"  # non-finite


def clamp(cmd: Twist2D, limits: VelocityLimits) -> Twist2D:
    return Twist2D(
        _within(cmd.vx, limits.max_linear_speed_mps),
        _within(cmd.vy, limits.max_lateral_speed_mps),
        _within(cmd.wz, limits.max_angular_speed_rps),
    )


def _within(x: float, limit: float) -> float:
    """max(-limit, min(limit, x)) without the calls, and as it is (a zero limit gives -0.0)."""
    y = x if x < limit else limit
    return y if y > -limit else -limit


def _approach(current: float, target: float, max_step: float) -> float:
    if target > current:
        return min(target, current + max_step)
    return max(target, current - max_step)


def ramp(current: Twist2D, target: Twist2D, limits: VelocityLimits, dt: float) -> Twist2D:
    """Move `current` toward `target` no faster than the acceleration limits allow."""
    if current == target:
        return current
    dv = limits.max_linear_accel_mps2 * dt
    return Twist2D(
        _approach(current.vx, target.vx, dv),
        _approach(current.vy, target.vy, dv),
        _approach(current.wz, target.wz, limits.max_angular_accel_rps2 * dt),
    )


class CommandGate:
    """One agent's command input: drops non-finite commands, clamps to limits, stops after a timeout,
    and ramps the applied velocity within the acceleration limits."""

    def __init__(self, limits: VelocityLimits, timeout_s: float = 0.5) -> None:
        self.limits = limits
        self.timeout_s = timeout_s
        self.reset()

    def reset(self) -> None:
        self._target = ZERO_TWIST
        self._stamp = -math.inf
        self.applied = ZERO_TWIST

    def command(self, cmd: Twist2D, now: float) -> CommandStatus:
        if not cmd.is_finite():
            return CommandStatus.REJECTED
        limited = clamp(cmd, self.limits)
        self._target = limited
        self._stamp = now
        return CommandStatus.ACCEPTED if limited == cmd else CommandStatus.CLAMPED

    def is_stale(self, now: float) -> bool:
        """No command for `timeout_s` (a stamp exactly that old counts: sim time comes in steps)."""
        return now - self._stamp >= self.timeout_s - 1e-9

    def target(self, now: float) -> Twist2D:
        """The commanded velocity, or zero once the last command is stale."""
        return ZERO_TWIST if self.is_stale(now) else self._target

    def update(self, now: float, dt: float, enabled: bool = True) -> Twist2D:
        """Advance the ramp by dt; returns the velocity to apply during the next step."""
        goal = self._target if enabled and not self.is_stale(now) else ZERO_TWIST
        if goal != self.applied:
            self.applied = ramp(self.applied, goal, self.limits, dt)
        return self.applied
