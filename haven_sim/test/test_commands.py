import math

import pytest

from haven_sim.common.geometry import Twist2D
from haven_sim.sim.commands import CommandGate, CommandStatus, VelocityLimits, clamp, ramp


def test_clamp_to_turtlebot_limits():
    lim = VelocityLimits()
    assert clamp(Twist2D(2.0, 1.0, -10.0), lim) == Twist2D(0.7, 0.0, -math.pi)


def test_ramp_respects_acceleration():
    lim = VelocityLimits(max_linear_accel_mps2=0.5, max_angular_accel_rps2=2.0)
    out = ramp(Twist2D(), Twist2D(0.7, 0.0, 1.0), lim, 0.1)
    assert out == pytest.approx(Twist2D(0.05, 0.0, 0.2))
    assert ramp(Twist2D(0.5, 0, 0), Twist2D(0.0, 0, 0), lim, 0.1).vx == pytest.approx(0.45)


def test_gate_rejects_non_finite_and_keeps_last_command():
    gate = CommandGate(VelocityLimits(), timeout_s=0.5)
    assert gate.command(Twist2D(0.3, 0, 0), 0.0) is CommandStatus.ACCEPTED
    assert gate.command(Twist2D(math.nan, 0, 0), 0.1) is CommandStatus.REJECTED
    assert gate.command(Twist2D(0.1, 0, math.inf), 0.1) is CommandStatus.REJECTED
    assert gate.target(0.2) == Twist2D(0.3, 0, 0)
    assert gate.command(Twist2D(5.0, 0, 0), 0.3) is CommandStatus.CLAMPED
    assert gate.target(0.3).vx == pytest.approx(0.7)


def test_gate_watchdog_stops_after_timeout():
    gate = CommandGate(VelocityLimits(), timeout_s=0.5)
    gate.command(Twist2D(0.3, 0, 0.2), 1.0)
    assert gate.target(1.48) == Twist2D(0.3, 0, 0.2)
    assert gate.target(1.5) == Twist2D()  # exactly 0.5 s without a command: stopped
    assert gate.is_stale(1.5) and not gate.is_stale(1.48)
