"""Kinematics against the analytic unicycle, walls that stop bodies, contact events, humans."""

import math

import pytest
from helpers import box_world, robot_with

from haven_sim.common.events import EventKind
from haven_sim.common.geometry import Pose2D, Twist2D
from haven_sim.robots.fields import DEFAULT as ROBOT_BODY
from haven_sim.sim.simulation import SimConfig, Simulation

INSTANT = robot_with(max_linear_accel_mps2=1e6, max_angular_accel_rps2=1e6)


def drive(sim, cmd, seconds, human=None, human_cmd=None):
    for _ in range(round(seconds / sim.config.step_s)):
        sim.command_robot(cmd)
        if human:
            sim.command_human(human, human_cmd)
        sim.step()


@pytest.mark.parametrize("v,w", [(0.5, 0.0), (0.5, 0.5), (0.3, -1.0), (0.0, 1.5)])
def test_motion_matches_unicycle_model(v, w):
    """Once the motors have spun up (bounded force and torque take a few steps), the body follows
    the unicycle x' = v cos(th), y' = v sin(th), th' = w from wherever it is."""
    sim = Simulation(box_world(20.0), SimConfig(robot=INSTANT))
    drive(sim, Twist2D(v, 0, w), 0.5)
    x0, y0, th0 = sim.robot_pose()
    t = 3.0
    drive(sim, Twist2D(v, 0, w), t)
    p = sim.robot_pose()
    if abs(w) < 1e-9:
        ex, ey = x0 + v * t * math.cos(th0), y0 + v * t * math.sin(th0)
    else:
        ex = x0 + v / w * (math.sin(th0 + w * t) - math.sin(th0))
        ey = y0 - v / w * (math.cos(th0 + w * t) - math.cos(th0))
    assert p.x == pytest.approx(ex, abs=0.005)
    assert p.y == pytest.approx(ey, abs=0.005)
    assert math.remainder(p.yaw - th0 - w * t, 2 * math.pi) == pytest.approx(0.0, abs=0.005)
    tw = sim.robot_twist()
    assert tw.vx == pytest.approx(v, abs=1e-3) and abs(tw.vy) < 1e-3 and tw.wz == pytest.approx(w, abs=1e-3)


def test_acceleration_is_limited():
    sim = Simulation(box_world(20.0))
    drive(sim, Twist2D(0.7, 0, 0), 0.4)
    assert sim.robot_twist().vx == pytest.approx(0.2, abs=0.011)  # 0.5 m/s^2 default


def test_wall_stops_robot_without_tunnelling_and_reports_contact():
    sim = Simulation(box_world(4.0, thickness=0.1), SimConfig(robot=INSTANT))
    drive(sim, Twist2D(0.7, 0, 0), 8.0)
    x = sim.robot_pose().x
    limit = 4.0 - 0.05 - ROBOT_BODY.radius_m
    assert limit - 0.03 < x <= limit + 0.005
    events = sim.pop_events()
    assert [e.kind for e in events] == [EventKind.CONTACT_BEGIN] and events[0].data == {"other": "wall"}
    assert sim.contacts() == ["wall"]
    drive(sim, Twist2D(-0.3, 0, 0), 1.0)
    assert [(e.kind, e["other"]) for e in sim.pop_events()] == [(EventKind.CONTACT_END, "wall")]


def test_watchdog_stops_robot_half_a_second_after_last_command():
    sim = Simulation(box_world(20.0), SimConfig(robot=INSTANT))
    drive(sim, Twist2D(0.5, 0, 0), 1.0)
    x_last_cmd = sim.robot_pose().x
    sim.run(0.48)
    assert sim.robot_twist().vx == pytest.approx(0.5, abs=1e-3)  # still obeying the last command
    sim.run(0.1)
    assert sim.robot_twist().vx == pytest.approx(0.0, abs=1e-3)
    x_stop = sim.robot_pose().x
    sim.run(2.0)
    assert sim.robot_pose().x == pytest.approx(x_stop, abs=1e-3)
    assert x_stop - x_last_cmd == pytest.approx(0.5 * 0.5, abs=0.02)


def test_human_moves_holonomically_within_its_speed_limit_and_bumps_robot():
    world = box_world(10.0, humans=[{"id": "ann", "start": [8.0, 5.0, math.pi]}])
    sim = Simulation(world)
    drive(sim, Twist2D(), 2.0, "ann", Twist2D(5.0, 0.0, 0.0))  # asks for 5 m/s, gets 1.5
    h = sim.human_poses()["ann"]
    assert sim.human_poses()["ann"].x < 8.0 - 1.5 * 1.5
    assert h.y == pytest.approx(5.0, abs=0.05)
    types = [(e.kind, e.get("other")) for e in sim.pop_events()]
    assert (EventKind.CONTACT_BEGIN, "human:ann") in types
    # sideways (linear.y) works for humans, not for the differential-drive robot
    sim2 = Simulation(world)
    drive(sim2, Twist2D(0.0, 0.5, 0.0), 1.0, "ann", Twist2D(0.0, 1.0, 0.0))
    assert sim2.robot_pose().y == pytest.approx(5.0, abs=1e-3)
    assert sim2.human_poses()["ann"].y < 5.0 - 0.5  # facing -x, its left is -y


def test_reset_restores_start_state_but_time_runs_on():
    world = box_world(10.0, humans=[{"id": "ann", "start": [8.0, 5.0, 0.0]}])
    sim = Simulation(world)
    drive(sim, Twist2D(0.5, 0, 0.3), 2.0, "ann", Twist2D(0.5, 0, 0))
    t = sim.time
    sim.reset()
    assert sim.robot_pose() == Pose2D(5.0, 5.0, 0.0)
    assert sim.human_poses()["ann"] == Pose2D(8.0, 5.0, 0.0)
    assert sim.battery.level == 1.0
    assert sim.time == t
    assert [e.kind for e in sim.pop_events()][-1] is EventKind.RESET
    sim.run(1.0)
    assert sim.robot_pose() == pytest.approx(Pose2D(5.0, 5.0, 0.0), abs=1e-6)


def test_unknown_human_is_refused():
    sim = Simulation(box_world(10.0))
    with pytest.raises(KeyError):
        sim.command_human("nobody", Twist2D(1, 0, 0))


def test_removed_obstruction_lets_robot_pass():
    wall = {"id": "gate", "segment": [[7.0, 0.0], [7.0, 10.0]], "thickness": 0.1}
    world = box_world(10.0, obstructions=[wall])
    sim = Simulation(world, SimConfig(robot=INSTANT))
    drive(sim, Twist2D(0.7, 0, 0), 5.0)
    assert sim.robot_pose().x < 7.0
    assert sim.scan()[180] == pytest.approx(7.0 - 0.05 - sim.robot_pose().x, abs=1e-6)
    sim.remove_obstruction("gate")
    drive(sim, Twist2D(0.7, 0, 0), 3.0)
    assert sim.robot_pose().x > 7.5
    assert any(e.kind is EventKind.OBSTRUCTION_REMOVED for e in sim.pop_events())
    assert sim.occupancy().is_occupied(7.0, 5.0) is False
