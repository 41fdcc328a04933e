"""The path follower on the simulator core: HAVEN's rotate/arc style, finishing, any planner's path."""

import math

import numpy as np
import pytest
from foreign_paths import GOAL, arc_path
from helpers import box_world, drive_closed_loop

from haven_sim.common.events import EventKind
from haven_sim.common.geometry import Pose2D, Twist2D
from haven_sim.nav.follower import FollowerParams, PathFollower, Status
from haven_sim.nav.path_style import shape_path
from haven_sim.nav.planner import GridPlanner
from haven_sim.sim.occupancy import rasterise
from haven_sim.sim.simulation import Simulation
from haven_sim.sim.world import packaged_world
from haven_sim.sim.world_file import load_world


def contacts(sim):
    return [e for e in sim.pop_events() if e.kind is EventKind.CONTACT_BEGIN]


def test_reaches_goal_through_the_door_without_touching_anything():
    world = load_world(packaged_world("small_test"))
    sim = Simulation(world)
    planner = GridPlanner(rasterise(world))
    plan = planner.plan((1.0, 2.5), (7.2, 4.5))
    follower = PathFollower()
    follower.set_path(shape_path(plan.points, 0.0, is_clear=planner.hard_clear, goal_yaw=math.pi))
    drive_closed_loop(sim, follower, 90.0)
    p = sim.robot_pose()
    assert follower.status is Status.ARRIVED
    assert math.hypot(p.x - 7.2, p.y - 4.5) <= 0.1
    assert abs(math.remainder(p.yaw - math.pi, 2 * math.pi)) <= math.radians(5.0)
    assert contacts(sim) == []
    # finished means finished: it stays put instead of circling the goal
    sim.run(5.0)
    assert follower.command(sim.robot_pose()) == Twist2D()
    assert sim.robot_pose().distance_to(p) < 0.02


def test_rotates_in_place_at_50_degrees_per_second_then_drives():
    sim = Simulation(box_world(10.0))
    follower = PathFollower()
    follower.set_path(shape_path([(5.0, 5.0), (5.0, 8.0)], 0.0))  # 90 deg left: rotate first
    yaws, xs = [], []

    def watch(s, t):
        yaws.append(s.robot_twist().wz)
        xs.append(s.robot_pose().x)

    drive_closed_loop(sim, follower, 30.0, on_tick=watch)
    assert follower.status is Status.ARRIVED
    assert max(yaws) == pytest.approx(math.radians(50.0), abs=0.02)
    assert max(abs(x - 5.0) for x in xs) < 0.02  # turning on the spot, not driving off


def test_tiny_heading_errors_do_not_stall():
    """The original crashed on errors under 3 degrees and never moved."""
    sim = Simulation(box_world(10.0, robot={"start": [2.0, 5.0, math.radians(2.0)]}))
    follower = PathFollower()
    follower.set_path([Pose2D(2.0, 5.0, 0.0), Pose2D(6.0, 5.0, 0.0)])
    drive_closed_loop(sim, follower, 30.0)
    assert follower.status is Status.ARRIVED
    assert sim.robot_pose().distance_to((6.0, 5.0)) <= 0.1


def test_follows_a_path_made_by_another_planner():
    """A dense circle arc with tangent yaws, the way a smoothing planner would publish it."""
    sim = Simulation(box_world(10.0, robot={"start": [3.0, 3.0, 0.0]}))
    ts = np.linspace(0.0, math.pi, 80)
    poses = [Pose2D(3.0 + 2.0 * math.sin(t), 5.0 - 2.0 * math.cos(t), t) for t in ts]
    follower = PathFollower()
    follower.set_path(poses)
    worst = []

    def track(s, t):
        p = s.robot_pose()
        worst.append(abs(math.hypot(p.x - 3.0, p.y - 5.0) - 2.0))

    drive_closed_loop(sim, follower, 60.0, on_tick=track)
    assert follower.status is Status.ARRIVED
    assert sim.robot_pose().distance_to((3.0, 7.0)) <= 0.1
    assert max(worst[20:]) < 0.08  # stays on the 2 m circle


SHAPES = [dict(spacing_m=0.05), dict(spacing_m=0.05, orientation="tangent", yaw_jitter_deg=1.0), dict(spacing_m=0.4)]


@pytest.mark.parametrize("shape", SHAPES, ids=["navfn", "smac", "sparse"])
def test_a_nav2_shaped_path_is_followed_to_its_goal_pose(shape):
    """NavFn-like (identity orientations, the goal yaw on the last pose), Smac-like (noisy yaws),
    sparse: followed along the arc, then rotated to the goal yaw."""
    sim = Simulation(box_world(10.0, robot={"start": [2.0, 2.0, 0.0]}))
    poses = arc_path(origin=(2.0, 2.0), **shape)
    follower = PathFollower()
    follower.set_path(poses)
    drive_closed_loop(sim, follower, 60.0)
    p = sim.robot_pose()
    assert follower.status is Status.ARRIVED
    assert p.distance_to((GOAL.x + 2.0, GOAL.y + 2.0)) <= 0.15
    assert abs(math.remainder(p.yaw - GOAL.yaw, 2 * math.pi)) <= 0.15


def test_waiting_holds_still_and_empty_path_is_idle():
    follower = PathFollower()
    assert follower.command(Pose2D(0, 0, 0)) == Twist2D() and follower.status is Status.IDLE
    follower.set_path([Pose2D(0, 0, 0), Pose2D(3, 0, 0)])
    assert follower.command(Pose2D(0, 0, 0)).vx > 0
    follower.waiting = True
    assert follower.command(Pose2D(0.5, 0, 0)) == Twist2D() and follower.status is Status.WAITING
    follower.waiting = False
    assert follower.command(Pose2D(0.5, 0, 0)).vx > 0


def test_big_heading_error_mid_path_stops_and_rotates_first():
    follower = PathFollower(FollowerParams())
    follower.set_path([Pose2D(0, 0, 0), Pose2D(3, 0, 0)])
    cmd = follower.command(Pose2D(1.0, 0.0, math.radians(120.0)))  # pushed round by someone
    assert cmd.vx == 0.0 and cmd.wz < 0 and follower.status is Status.ROTATING


def test_invalid_params_are_refused():
    with pytest.raises(ValueError, match="lookahead_m"):
        FollowerParams(lookahead_m=0.0)


def test_projection_at_the_very_end_of_a_piece_does_not_fail():
    """A robot pushed onto the last point of a two-pose piece (seen in a 10x ROS trial)."""
    follower = PathFollower()
    follower.set_path([Pose2D(0, 0, 0), Pose2D(1, 0, 0), Pose2D(1, 0, 1.0), Pose2D(2, 0, 1.0)])
    for x in (0.5, 0.97, 1.0, 1.0):
        follower.command(Pose2D(x, 0.0, 0.0))
    follower._progress = 10.0  # beyond the piece's end
    cmd = follower.command(Pose2D(1.0, 0.0, 0.0))
    assert follower.status is Status.ROTATING and cmd.vx == 0.0 and cmd.wz > 0  # on to the rotation that follows
