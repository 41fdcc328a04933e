"""Human awareness: wait near the robot or the goal, detour on the roomier side, revert, resume."""

import math

import pytest
from helpers import corridor, drive_closed_loop

from haven_sim.common.events import EventKind
from haven_sim.common.geometry import Pose2D, Twist2D
from haven_sim.nav.follower import PathFollower, Status
from haven_sim.nav.navigator import Navigator, NavigatorParams, NavState
from haven_sim.sim.simulation import Simulation

GOAL = Pose2D(11.0, 1.5, 0.0)


def setup(human_xy, width=3.0):
    world = corridor(width=width, humans=[{"id": "h", "start": [human_xy[0], human_xy[1], 0.0]}])
    sim = Simulation(world)
    nav = Navigator(sim.occupancy())
    follower = PathFollower()
    out = nav.set_goal(sim.robot_pose(), GOAL, 0.0)
    follower.set_path(out.path)
    assert out.events[0].kind is EventKind.PLAN_MADE
    return sim, nav, follower


def types(events):
    return [e.kind for e in events]


def walk_away_after(seconds, vy=1.0):
    def script(sim, t):
        if sim.time >= seconds:
            sim.command_human("h", Twist2D(0.0, vy, 0.0))  # sideways out of the way

    return script


@pytest.mark.parametrize("human,near", [((2.6, 1.5), "robot"), ((9.8, 1.5), "goal")])
def test_waits_for_a_human_near_the_robot_or_the_goal_then_resumes(human, near):
    sim, nav, follower = setup(human)
    events = drive_closed_loop(sim, follower, 60.0, nav, walk_away_after(6.0))
    assert types(events)[:2] == [EventKind.WAITING, EventKind.RESUMED]
    assert near in events[0]["reason"]
    assert events[1].stamp >= 6.0
    assert follower.status is Status.ARRIVED
    assert sim.robot_pose().distance_to((GOAL.x, GOAL.y)) <= 0.1
    assert not [e for e in sim.pop_events() if e.kind is EventKind.CONTACT_BEGIN]


def test_robot_does_not_move_while_waiting():
    sim, nav, follower = setup((2.6, 1.5))
    drive_closed_loop(sim, follower, 5.0, nav)
    assert nav.state is NavState.WAITING and follower.status is Status.WAITING
    assert sim.robot_pose().distance_to((1.0, 1.5)) < 0.02


@pytest.mark.parametrize("human_y,side", [(1.2, "left"), (1.8, "right")])
def test_detours_around_a_human_on_the_side_with_more_room(human_y, side):
    sim, nav, follower = setup((6.0, human_y))
    events = drive_closed_loop(sim, follower, 60.0, nav)
    assert types(events) == [EventKind.REPLANNED] and events[0]["side"] == side
    ys = [p.y for p in nav.active if 5.5 < p.x < 6.5]
    assert all((y > human_y) if side == "left" else (y < human_y) for y in ys)
    assert follower.status is Status.ARRIVED
    assert not [e for e in sim.pop_events() if e.kind is EventKind.CONTACT_BEGIN]


def test_human_leaving_before_the_detour_sends_the_robot_back_to_the_original_path():
    sim, nav, follower = setup((7.0, 1.5), width=4.0)  # more room on the left: the detour goes there
    events = drive_closed_loop(sim, follower, 60.0, nav, walk_away_after(0.5, vy=-1.0))  # human goes right
    assert types(events)[:2] == [EventKind.REPLANNED, EventKind.REVERTED]
    assert nav.active is nav.original
    assert follower.status is Status.ARRIVED


def test_unreachable_goal_is_refused_with_a_reason():
    sim, nav, follower = setup((6.0, 2.5))
    out = nav.set_goal(sim.robot_pose(), Pose2D(30.0, 1.5, 0.0), 0.0)
    assert out.path == [] and out.events[0].kind is EventKind.PLAN_REFUSED
    assert "outside the map" in out.events[0]["reason"]
    assert nav.state is NavState.IDLE


def test_wait_distance_is_a_parameter():
    world = corridor(humans=[{"id": "h", "start": [4.5, 1.5, 0.0]}])
    sim = Simulation(world)
    nav = Navigator(sim.occupancy(), params=NavigatorParams(wait_distance_m=4.0))
    nav.set_goal(sim.robot_pose(), GOAL, 0.0)
    out = nav.update(sim.robot_pose(), [(4.5, 1.5)], 0.2)
    assert types(out.events) == [EventKind.WAITING] and out.waiting is True
    assert math.isclose(nav.params.wait_distance_m, 4.0)
