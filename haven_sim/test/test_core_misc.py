"""Odometry noise, the real-time pacer and the velocity mux: small rules with time as an argument."""

import math

import pytest

from haven_sim.common.geometry import Pose2D, Twist2D
from haven_sim.common.topics import PACE_IDLE
from haven_sim.nav.mux import ESTOP, IDLE, NAV, TELEOP, VelocityMux
from haven_sim.sim.odometry import Odometry, OdometryNoise
from haven_sim.sim.pacer import ControlPace, Pacer


def _circle(n=500):
    return [Pose2D(math.cos(k * 0.01), math.sin(k * 0.01), k * 0.01 + math.pi / 2) for k in range(n)]


def test_noise_free_odometry_is_ground_truth():
    path = _circle()
    odo = Odometry(path[0])
    for p in path:
        assert odo.update(p) == p


def test_noisy_odometry_drifts_reproducibly():
    path = _circle()
    finals = []
    for seed in (1, 1, 2):
        odo = Odometry(path[0], OdometryNoise(0.05, 0.05), seed=seed)
        for p in path[1:]:
            odo.update(p)
        finals.append(odo.pose)
    assert finals[0] == finals[1] != finals[2]
    drift = finals[0].distance_to(path[-1])
    assert 1e-4 < drift < 0.2


def test_pacer_keeps_average_rate_and_caps_catch_up():
    pacer = Pacer(step_s=0.02, real_time_factor=2.0, max_catch_up_steps=10)
    assert pacer.tick_period_s == pytest.approx(0.01)
    assert pacer.due_steps(100.0) == 0
    assert sum(pacer.due_steps(100.0 + k * 0.013) for k in range(1, 101)) == 130  # 1.3 s wall = 2.6 s sim
    assert pacer.due_steps(200.0) == 10  # a stall: no burst beyond the cap
    assert pacer.due_steps(200.01) == 1
    with pytest.raises(ValueError):
        Pacer(0.02, 0.0)


def test_a_control_loop_that_falls_behind_slows_the_clock_without_a_burst_after():
    """The clock runs at most control_lag_s (and two control ticks) past what the controller has
    acted at; the steps it held are not owed, and the factor achieved is reported."""
    step, pacer, pace = 0.02, Pacer(0.02, 1.0), ControlPace(lag_s=0.1)
    sim, wall, seen, reported = 0.0, 0.0, [(0.0, 0.0)], []  # (wall, sim) as the clock went; factors reported

    def run(seconds: float, controller_lag_s: float | None) -> None:
        nonlocal sim, wall
        for _ in range(round(seconds / 0.01)):
            wall += 0.01
            if controller_lag_s is not None:  # ticks at 20 Hz of the sim time it saw controller_lag_s of wall time ago
                saw = (
                    max(s for w, s in seen if w <= wall - controller_lag_s + 1e-9) if wall >= controller_lag_s else 0.0
                )
                pace.report(math.floor(saw / 0.05 + 1e-9) * 0.05, wall)
            sim += step * pacer.due_steps(wall, pace.allowed_steps(sim, step, wall))
            seen.append((wall, sim))
            if (factor := pace.factor(sim, wall, pacer.holding)) is not None:  # as the simulator node asks, each tick
                reported.append(factor)

    run(2.0, None)  # nobody reports: not held
    assert sim == pytest.approx(2.0, abs=0.03) and pace.allowed_steps(sim, step, wall) is None
    run(5.0, 0.0)  # a controller that keeps up holds nothing
    assert sim == pytest.approx(7.0, abs=0.05) and reported == []
    before = sim
    run(6.0, 0.4)  # one that is 0.4 s behind: the clock waits for it
    assert 0.1 < (sim - before) / 6.0 < 0.9 and pace.acted_at is not None and sim - pace.acted_at <= 0.1 + step
    assert len(reported) == 1 and 0.1 < reported[0] < 0.9
    before = sim
    run(1.0, 0.0)  # caught up: back at 1x, no burst for the time held
    assert sim - before == pytest.approx(1.0, abs=0.15)
    run(6.0, None)  # silent for longer than silence_s: no longer held
    assert pace.allowed_steps(sim, step, wall) is None
    # A starved controller ticks late, its timer skipping the ticks it missed: a long gap between
    # two reports is not its period, and does not let the clock run further ahead.
    late = ControlPace(lag_s=0.1)
    for t, w in ((1.0, 0.0), (1.05, 0.05), (1.55, 0.6)):
        late.report(t, w)
    assert late.allowed_steps(1.55, step, 0.6) == 5
    late.report(PACE_IDLE, 0.7)  # the controller drives nothing now: nothing is held
    assert late.allowed_steps(9.0, step, 0.7) is None


def test_mux_priorities_and_timeouts():
    mux = VelocityMux(teleop_timeout_s=0.5, nav_timeout_s=0.5)
    assert mux.output(0.0).source == IDLE
    mux.on_nav(Twist2D(0.2, 0, 0), 1.0)
    assert mux.output(1.1) == mux.output(1.1) and mux.output(1.1).source == NAV
    mux.on_teleop(Twist2D(-0.1, 0, 0.5), 1.2)
    mux.on_nav(Twist2D(0.2, 0, 0), 1.3)
    out = mux.output(1.3)
    assert out.source == TELEOP and out.twist == Twist2D(-0.1, 0, 0.5)
    assert mux.output(1.7).source == TELEOP
    mux.on_nav(Twist2D(0.2, 0, 0), 1.7)
    assert mux.output(1.71).source == NAV  # teleop quiet for 0.51 s: control returns to nav
    mux.set_estop(True, 1.75)
    mux.on_teleop(Twist2D(0.3, 0, 0), 1.8)
    assert mux.output(1.8).source == ESTOP and mux.output(1.8).twist == Twist2D()
    mux.set_estop(False, 3.8)  # 2 s after the last true
    mux.on_teleop(Twist2D(0.3, 0, 0), 3.8)
    assert mux.output(3.8).source == TELEOP
    assert mux.output(5.0).source == IDLE


def test_estop_from_several_publishers_a_true_wins_over_a_false_from_another():
    """`ros2 topic pub` repeats its true once a second; another node keeps saying false: stopped."""
    mux = VelocityMux(estop_hold_s=2.0)
    mux.on_nav(Twist2D(0.2, 0, 0), 0.0)
    for t in range(10):
        mux.set_estop(True, float(t))  # the repeating true
        mux.set_estop(False, t + 0.5)  # the other publisher
        mux.on_nav(Twist2D(0.2, 0, 0), t + 0.5)
        assert mux.output(t + 0.5).source == ESTOP
    mux.set_estop(False, 11.5)  # the true has stopped: the next false releases it
    mux.on_nav(Twist2D(0.2, 0, 0), 11.5)
    assert mux.output(11.5).source == NAV
    mux.set_estop(True, 12.0)  # a single latched true holds for good
    assert mux.output(100.0).source == ESTOP
