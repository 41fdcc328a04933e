"""The trial director as the scenario node runs it: start, goals, control through topics, the end."""

import json
from dataclasses import replace

import pytest

from haven_scenarios.study.director import TrialDirector
from haven_scenarios.study.rules import EndReason
from haven_scenarios.study.scenario import load_scenario
from haven_sim.common import topics
from haven_sim.common.events import EventKind, Source, event
from haven_sim.common.geometry import Pose2D
from haven_sim.common.state import Goal, RobotState
from haven_sim.sim.battery import BatteryReading, PowerStatus
from haven_sim.sim.occupancy import rasterise


def by_topic(messages, topic):
    return [m.data for m in messages if m.topic == topic]


def battery(level):
    return BatteryReading(level, PowerStatus.DISCHARGING, 15.0, 1.0, 2.2, 10.0)


ROBOT_AT = Pose2D(2.0, 2.0, 0.0)  # where ready() puts the robot and the human unless told
HUMAN_AT = Pose2D(16.0, 16.0, 3.14)


def ready(director, robot=ROBOT_AT, human=HUMAN_AT, level=1.0):
    world = director.scenario.world
    director.on_map(rasterise(world), 0.0)
    director.on_odom(RobotState(robot), 0.0)
    director.on_humans({"h1": human}, 0.0)
    director.on_battery(battery(level), 0.0)


def test_starts_only_when_allowed_and_sends_the_first_goal():
    d = TrialDirector(load_scenario("hallway"))
    d.start_allowed = False
    ready(d)
    assert [m.topic for m in d.tick(0.0)] == [topics.TRIAL_STATUS]  # held: the node waits for its listeners
    d.start_allowed = True
    out = d.tick(0.1)
    assert [e.kind for e in by_topic(out, topics.EVENTS)][:2] == [EventKind.TRIAL_START, EventKind.TARGET_SELECTED]
    (goal,) = by_topic(out, topics.GOAL)
    assert isinstance(goal, Goal) and (goal.pose.x, goal.pose.y) == (16.0, 2.0) and goal.frame == "map"
    assert by_topic(out, topics.THOUGHT) == ["Going to room B"]
    assert by_topic(out, topics.human_cmd_vel("h1")) == []  # participants start moving from the next tick
    assert len(by_topic(d.tick(0.2), topics.human_cmd_vel("h1"))) == 1


def test_a_robot_sent_off_on_another_nodes_goal_is_sent_back_on_its_mission_once_it_stands_still():
    """RViz (or a flood) on /goal_pose in a free-running trial: the planner plans for that goal; once
    the robot stands there, the mission asks for its own target again, logged as a goal_sent."""
    d = TrialDirector(load_scenario("hallway"))
    d.start_allowed = True
    ready(d)
    (ours,) = by_topic(d.tick(0.1), topics.GOAL)
    d.on_event(event(EventKind.PLAN_MADE, 0.2, Source.PLANNER, goal=[16.0, 2.0]), 0.2)  # the mission's own plan
    d.on_event(event(EventKind.PLAN_MADE, 0.5, Source.PLANNER, goal=[3.0, 7.0]), 0.5)  # another node's goal won
    assert d.diverted
    d.on_odom(RobotState(Pose2D(3.0, 7.0, 0.0)), 3.0)  # there, standing still
    assert by_topic(d.tick(3.0), topics.GOAL) == []
    out = d.tick(4.1)  # still for longer than RESEND_AFTER_S
    (again,) = by_topic(out, topics.GOAL)
    assert (again.pose.x, again.pose.y) == (ours.pose.x, ours.pose.y) and not d.diverted
    assert [e.kind for e in by_topic(out, topics.EVENTS)].count(EventKind.GOAL_SENT) == 1


def test_an_obstruction_is_removed_through_its_control_topic_and_logged():
    d = TrialDirector(load_scenario("hallway_hard"))
    ready(d)
    d.tick(0.0)
    room_b = d.scenario.world.room("B").centre
    d.on_humans({"h1": Pose2D(*room_b)}, 0.1)
    out = d.tick(0.1)
    assert by_topic(out, topics.REMOVE_OBSTRUCTION) == ["crate"]
    assert EventKind.OBSTRUCTION_CLEARED in [e.kind for e in by_topic(out, topics.EVENTS)]


def test_waiting_comes_from_the_wait_topic_and_shows_in_the_thought():
    d = TrialDirector(load_scenario("hallway"))
    ready(d)
    d.tick(0.0)
    d.on_event(event(EventKind.WAITING, 0.1, Source.PLANNER, reason="x"), 0.1)  # the log alone changes nothing
    assert by_topic(d.tick(0.1), topics.THOUGHT) == []
    d.on_wait(True, 0.15)
    assert by_topic(d.tick(0.2), topics.THOUGHT) == ["Waiting for you to pass"]


def test_contact_ends_the_trial_when_the_scenario_says_so_and_a_flat_battery_does_off_the_base():
    d = TrialDirector(replace(load_scenario("hallway"), end_on_contact=True))
    ready(d)
    d.tick(0.0)
    d.on_event(event(EventKind.CONTACT_BEGIN, 0.1, Source.SIM, other="human:h1"), 0.1)
    out = d.tick(0.2)
    assert d.ended is EndReason.CONTACT and by_topic(out, topics.EVENTS)[-1]["reason"] == "contact"
    assert d.tick(0.3) == []  # over
    flat = TrialDirector(load_scenario("hallway"))
    ready(flat)
    flat.tick(0.0)
    flat.on_battery(battery(0.0), 1.0)
    flat.tick(1.0)  # flat from here
    flat.tick(5.9)
    assert flat.ended is None
    flat.tick(6.1)
    assert flat.ended is EndReason.BATTERY_EMPTY


def test_a_trial_stopped_from_outside_ends_interrupted_at_the_last_tick_once():
    d = TrialDirector(load_scenario("hallway"))
    ready(d)
    assert d.interrupt() == []  # nothing began: nothing to end
    d.tick(0.1)
    d.tick(0.2)
    (end,) = by_topic(d.interrupt(), topics.EVENTS)
    assert (end.kind, end.stamp, end["reason"]) == (EventKind.TRIAL_END, 0.2, EndReason.INTERRUPTED)
    assert d.interrupt() == [] and d.tick(0.3) == []


def test_a_teleoperated_trial_ends_when_the_person_is_done_too():
    """Defect: a teleop trial ended "completed" as soon as the robot finished, whatever the
    person had done (the end rule counted simulated participants only)."""
    scenario = load_scenario("hallway")
    scenario = replace(scenario, humans=[replace(h, model="teleop") for h in scenario.humans])
    d = TrialDirector(scenario)
    ready(d)
    d.tick(0.0)  # the start
    t, ends = 0.0, []
    for room in scenario.robot_route:  # the robot drives its whole route; the person stands still
        t += 1.0
        d.on_odom(RobotState(Pose2D(*scenario.world.room(room).centre)), t)
        ends += [e for e in by_topic(d.tick(t), topics.EVENTS) if e.kind is EventKind.TRIAL_END]
    assert d.mission is not None and d.mission.phase.name == "DONE" and ends == []
    for room in scenario.humans[0].route:  # now the person walks theirs
        t += 1.0
        d.on_humans({"h1": Pose2D(*scenario.world.room(room).centre)}, t)
        events = by_topic(d.tick(t), topics.EVENTS)
    assert [e.kind for e in events][-2:] == [EventKind.TASK_DONE, EventKind.TRIAL_END]
    assert events[-2]["by"] == "h1" and events[-1]["reason"] == EndReason.COMPLETED


def status(messages):
    (text,) = by_topic(messages, topics.TRIAL_STATUS)
    return json.loads(text)


def test_a_held_trial_starts_on_the_researchers_start_and_says_so_on_the_latched_status():
    d = TrialDirector(load_scenario("hallway"))
    d.held = True
    ready(d)
    assert status(d.tick(0.0))["state"] == "held"
    assert d.tick(0.1) == []  # the status is sent only when it changes
    d.on_control("start", 0.15)
    out = d.tick(0.2)
    assert EventKind.TRIAL_START in [e.kind for e in by_topic(out, topics.EVENTS)]
    s = status(out)
    assert s["state"] == "running" and s["humans"]["h1"] == {
        "rooms": ["B", "A", "D", "C"],
        "rooms_done": 0,
        "next_room": "B",
        "done": False,
    }


@pytest.mark.parametrize(
    ("command", "started", "reason"),
    [("stop", True, "stopped"), ("abort", True, "aborted"), ("stop", False, "aborted")],
)
def test_stop_and_abort_end_the_trial_with_their_reason(command, started, reason):
    d = TrialDirector(load_scenario("hallway"))
    d.held = not started
    ready(d)
    d.tick(0.0)
    out = d.on_control(command, 1.0)
    (end,) = by_topic(out, topics.EVENTS)
    assert end.kind is EventKind.TRIAL_END and end["reason"] == reason and end["by"] == "researcher"
    assert d.ended == reason and status(out)["state"] == "ended"
    assert d.on_control("abort", 2.0) == []  # ended once


def test_an_unknown_trial_command_is_refused_in_one_line():
    with pytest.raises(ValueError, match="unknown trial command 'go' \\(expected start, stop, abort\\)"):
        TrialDirector(load_scenario("hallway")).on_control("go", 0.0)
    with pytest.raises(ValueError, match="who asked must be"):
        TrialDirector(load_scenario("hallway")).on_control("abort by me", 0.0)


def test_an_abort_says_who_asked_for_it():
    d = TrialDirector(load_scenario("hallway"))
    d.held = False
    ready(d)
    d.tick(0.0)
    (end,) = by_topic(d.on_control("abort dropout:h1", 1.0), topics.EVENTS)  # the web node's drop-out policy
    assert (end["reason"], end["by"]) == ("aborted", "dropout:h1")


def test_the_status_shows_a_participants_gems_and_dwell_progress():
    d = TrialDirector(load_scenario("shared_room"))
    world = d.scenario.world
    human_gems = [g for g in world.gems if g.owner == "human"]
    ready(d, robot=world.robot_start)
    d.tick(0.0)
    d.on_humans({"h1": Pose2D(*human_gems[0].position)}, 0.5)
    d.tick(0.5)
    out = d.tick(0.5 + d.scenario.dwell_time_s / 2)
    h1 = status(out)["humans"]["h1"]
    assert (h1["gems_total"], h1["gems_done"], h1["dwell"]) == (len(human_gems), 0, 0.5)
    out = d.tick(0.5 + d.scenario.dwell_time_s)
    h1 = status(out)["humans"]["h1"]
    assert (h1["gems_done"], h1["dwell"]) == (1, None)
