"""The nodes' behaviour as components, without ROS: what the mux, controller, planner and simulator
publish in answer to what they receive."""

import math

import pytest
from helpers import box_world

from haven_sim.common import topics
from haven_sim.common.events import EventKind
from haven_sim.common.geometry import Pose2D, Twist2D
from haven_sim.common.state import Goal, RobotState
from haven_sim.nav.controller import ControllerComponent
from haven_sim.nav.mux import MuxComponent
from haven_sim.nav.planning import PlannerComponent
from haven_sim.sim.occupancy import rasterise
from haven_sim.sim.simulator import SimulatorComponent, SimulatorConfig


def by_topic(messages, topic):
    return [m.data for m in messages if m.topic == topic]


def test_mux_reports_each_change_of_source_and_stops_once_when_all_go_quiet():
    mux = MuxComponent()
    out = mux.on_nav(Twist2D(0.3, 0, 0), 0.0)
    assert by_topic(out, topics.CMD_VEL) == [Twist2D(0.3, 0, 0)]
    assert [(e["from"], e["to"]) for e in by_topic(out, topics.EVENTS)] == [("idle", "nav")]
    out = mux.on_teleop(Twist2D(0.1, 0, 0.5), 0.1)
    assert by_topic(out, topics.CMD_VEL) == [Twist2D(0.1, 0, 0.5)] and by_topic(out, topics.EVENTS)[0]["to"] == "teleop"
    out = mux.on_estop(True, 0.2)
    assert by_topic(out, topics.CMD_VEL) == [Twist2D()] and by_topic(out, topics.EVENTS)[0]["to"] == "estop"
    mux.on_estop(False, 0.3)
    held = mux.tick(1.0)  # still stopped: a true came 0.8 s ago (the hold is 2 s)
    assert by_topic(held, topics.CMD_VEL) == [Twist2D()] and by_topic(held, topics.EVENTS) == []
    quiet = mux.tick(2.2)  # released; teleop and nav both stale: one zero, then silence
    assert by_topic(quiet, topics.CMD_VEL) == [Twist2D()] and by_topic(quiet, topics.EVENTS)[0]["to"] == "idle"
    assert mux.tick(2.25) == []


def test_controller_reports_arrival_once_per_path():
    ctrl = ControllerComponent()
    ctrl.on_odom(RobotState(Pose2D(0, 0, 0)), 0.0)
    assert by_topic(ctrl.tick(0.0), topics.EVENTS) == []  # no path: nothing to report
    path = [Pose2D(0, 0, 0), Pose2D(0.05, 0, 0)]
    ctrl.on_plan(path, 0.0)
    ctrl.on_odom(RobotState(Pose2D(0.05, 0, 0)), 0.1)
    arrived = by_topic(ctrl.tick(0.1), topics.EVENTS)
    assert [e.kind for e in arrived] == [EventKind.GOAL_REACHED] and arrived[0]["goal"] == [0.05, 0.0]
    assert by_topic(ctrl.tick(0.15), topics.EVENTS) == []
    ctrl.on_plan(path, 0.2)  # the same goal sent again is a new path: reported again
    assert [e.kind for e in by_topic(ctrl.tick(0.25), topics.EVENTS)] == [EventKind.GOAL_REACHED]
    assert by_topic(ctrl.on_plan([], 0.3), topics.CMD_VEL_NAV) == [Twist2D()]  # a cleared plan stops at once
    # The plan being followed, sent again mid-way (a planner re-sending it), does not restart it.
    long = [Pose2D(0.05 * k, 0, 0) for k in range(80)]
    ctrl.on_plan(long, 0.4)
    ctrl.on_odom(RobotState(Pose2D(1.0, 0, 0)), 0.5)
    ctrl.tick(0.5)
    ctrl.on_plan(long, 0.6)
    assert ctrl.follower._progress > 0.9  # not back to the start


def test_planner_refuses_bad_goals_and_keeps_a_goal_until_it_has_map_and_pose():
    planner = PlannerComponent()
    for goal, why in [
        (Goal(Pose2D(1, 1, 0), "base_link"), "goal frame 'base_link' is not 'map'"),
        (Goal(Pose2D(math.nan, 1, 0)), "not finite"),
    ]:
        (refused,) = by_topic(planner.on_goal(goal, 0.0), topics.EVENTS)
        assert refused.kind is EventKind.PLAN_REFUSED and why in refused["reason"]
    assert planner.on_goal(Goal(Pose2D(7, 5, 0)), 0.0) == []  # no map, no pose yet: kept
    assert planner.on_map(rasterise(box_world(10.0)), 0.1) == []
    out = planner.on_odom(RobotState(Pose2D(5, 5, 0)), 0.2)
    assert by_topic(out, topics.WAIT) == [False] and len(by_topic(out, topics.PLAN)[0]) > 2
    assert by_topic(out, topics.EVENTS)[0].kind is EventKind.PLAN_MADE and planner.pending is None


def test_a_goal_storm_costs_one_plan_per_interval_the_newest_wins_and_is_told_once():
    planner = PlannerComponent()
    planner.on_map(rasterise(box_world(10.0)), 0.0)
    planner.on_odom(RobotState(Pose2D(5, 5, 0)), 0.0)
    plans, t = 0, 1.0
    for k in range(1000):  # 1 kHz of sim time for one second
        t = 1.0 + k * 0.001
        out = planner.on_goal(Goal(Pose2D(2.0 + (k % 5), 3.0, 0)), t)
        out += planner.on_odom(RobotState(Pose2D(5, 5, 0)), t)
        plans += len(by_topic(out, topics.PLAN))
    assert 9 <= plans <= 11  # one each goal_interval_s (0.1 s)
    assert len(planner.warnings) == 1 and "goal storm" in planner.warnings[0]
    last = planner.tick(t + 0.2)  # the newest goal, held, is planned at the next check
    assert by_topic(last, topics.EVENTS)[0]["goal"] == [2.0 + (999 % 5), 3.0]
    (storm,) = [e for e in by_topic(planner.tick(t + 1.5), topics.EVENTS) if e.kind is EventKind.GOAL_STORM]
    assert storm["goals"] == 1000 and storm["superseded"] >= 980 and storm["seconds"] == pytest.approx(0.999)
    assert planner.on_goal(Goal(Pose2D(3, 3, 0)), t + 3.0) != []  # after the storm, a goal is planned at once


@pytest.mark.parametrize("own", [True, False])
def test_map_to_odom_can_be_left_to_a_localization_node(own):
    sim = SimulatorComponent(box_world(10.0), SimulatorConfig(publish_map_to_odom=own))
    (static,) = by_topic(sim.sense(), topics.TF_STATIC)
    assert (("map", "odom") in {(f.parent, f.child) for f in static}) is own
    assert ("base_footprint", "base_link") in {(f.parent, f.child) for f in static}


def test_simulator_publishes_each_topic_at_its_rate():
    sim = SimulatorComponent(box_world(10.0, humans=[{"id": "h1", "start": [2.0, 2.0, 0.0]}]), SimulatorConfig())
    counts: dict[str, int] = {}
    for _ in range(50):  # one second
        for m in sim.sense():
            counts[m.topic] = counts.get(m.topic, 0) + 1
        sim.advance()
    assert counts[topics.CLOCK] == counts[topics.ODOM] == counts[topics.TF] == 50
    assert (counts[topics.HUMANS], counts[topics.SCAN], counts[topics.BATTERY]) == (20, 10, 5)
    assert counts[topics.MAP] == counts[topics.TF_STATIC] == 1
    sim.on_remove_obstruction("nope", 1.0)
    assert sim.warnings == ["no obstruction 'nope' in world 'box'"]
    sim.on_cmd_vel(Twist2D(math.nan, 0, 0), 1.0)
    assert sim.warnings[-1] == "dropped a non-finite command on /cmd_vel"


@pytest.mark.parametrize("rate", [7.0, 20.0, 33.0])
def test_rates_that_do_not_divide_the_physics_rate_hold_on_average(rate):
    sim = SimulatorComponent(
        box_world(10.0, humans=[{"id": "h1", "start": [2.0, 2.0, 0.0]}]), SimulatorConfig(humans_rate_hz=rate)
    )
    n = 0
    for _ in range(500):  # ten seconds
        n += sum(1 for m in sim.sense() if m.topic == topics.HUMANS)
        sim.advance()
    assert n == pytest.approx(10 * rate, abs=1)


def test_the_simulator_honours_the_estop_whatever_publishes_its_commands():
    """A command straight on /cmd_vel (past the mux) does not move the robot while the e-stop is
    on; a false releases it only after the hold, as in the mux."""
    sim = SimulatorComponent(box_world(10.0), SimulatorConfig(estop_hold_s=1.0))

    def drive(seconds: float) -> float:
        x0 = sim.sim.odometry_pose().x
        for _ in range(round(seconds * 50)):
            sim.on_cmd_vel(Twist2D(0.4, 0, 0), sim.sim.time)
            sim.advance()
        return sim.sim.odometry_pose().x - x0

    assert drive(1.0) > 0.2
    sim.on_estop(True, sim.sim.time)
    for _ in range(50):  # (the robot brakes from its speed)
        sim.advance()
    assert drive(2.0) == pytest.approx(0.0, abs=1e-3)
    sim.on_estop(False, sim.sim.time)  # the true came 2 s ago, beyond the 1 s hold: released
    assert drive(1.0) > 0.2


def test_goal_reached_comes_once_the_final_rotation_has_braked_to_rest():
    """A plan that ends turning in place: the event waits for the robot to stop turning, and its
    pose is the one the robot rests at (no overshoot after it)."""
    sim = SimulatorComponent(box_world(10.0), SimulatorConfig())
    ctrl = ControllerComponent()
    plan = [Pose2D(5.0 + 0.1 * k, 5.0, 0.0) for k in range(11)] + [Pose2D(6.0, 5.0, math.pi / 2)]
    ctrl.on_plan(plan, 0.0)
    reached, states = [], []
    for step in range(50 * 20):
        state = by_topic(sim.sense(), topics.ODOM)[0]
        states.append(state)
        ctrl.on_odom(state, sim.sim.time)
        if step % 2 == 0:  # (20 Hz of the simulator's 50)
            for m in ctrl.tick(sim.sim.time):
                if m.topic == topics.CMD_VEL_NAV:
                    sim.on_cmd_vel(m.data, sim.sim.time)
                elif m.data.kind is EventKind.GOAL_REACHED:
                    reached.append((m.data, state))
        sim.advance()
    (event, at), last = reached[0], states[-1]
    assert len(reached) == 1 and abs(at.twist.wz) < 0.02 and abs(at.twist.vx) < 0.01
    assert event["pose"][2] == pytest.approx(last.pose.yaw, abs=0.01)  # where it rests, nothing after
    assert last.pose.yaw == pytest.approx(math.pi / 2, abs=0.15)


def test_goal_reached_only_within_the_goal_checkers_tolerances_when_commands_come_late():
    """A control loop that falls behind (its commands applied 0.3 s late, as on a busy machine on
    the free-running clock) overshoots the goal and over-turns: the controller goes back until the
    pose it rests at is within its xy and yaw tolerances, and only then says the goal is reached."""
    sim = SimulatorComponent(box_world(10.0), SimulatorConfig())
    ctrl = ControllerComponent()
    plan = [Pose2D(4.0 + 0.1 * k, 5.0, 0.0) for k in range(21)] + [Pose2D(6.0, 5.0, math.pi / 2)]
    ctrl.on_plan(plan, 0.0)
    late: list[list[Twist2D]] = [[] for _ in range(15)]  # 15 physics steps: 0.3 s
    reached, farthest = [], 0.0
    for step in range(50 * 40):
        state = by_topic(sim.sense(), topics.ODOM)[0]
        farthest = max(farthest, state.pose.x - 6.0)
        ctrl.on_odom(state, sim.sim.time)
        sent = []
        if step % 2 == 0:
            for m in ctrl.tick(sim.sim.time):
                if m.topic == topics.CMD_VEL_NAV:
                    sent.append(m.data)
                elif m.data.kind is EventKind.GOAL_REACHED:
                    reached.append((m.data, state.pose))
        late.append(sent)
        for cmd in late.pop(0):
            sim.on_cmd_vel(cmd, sim.sim.time)
        sim.advance()
    assert farthest > 0.1 and ctrl.corrections >= 1  # it did overshoot, and went back
    assert len(reached) == 1
    event, at = reached[0]
    assert math.hypot(at.x - 6.0, at.y - 5.0) <= 0.1 and abs(at.yaw - math.pi / 2) <= 0.1
    assert event["pose"] == pytest.approx([at.x, at.y, at.yaw], abs=1e-3)
