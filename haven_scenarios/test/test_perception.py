"""What a simulated participant perceives (field of view, distance, walls, the condition), how late
they act on it, their parameters in scenario files, and what the director hands them."""

import math
from dataclasses import replace

import numpy as np
import pytest

from haven_scenarios.record.hesitation import hesitations
from haven_scenarios.run.trial import Trial
from haven_scenarios.study.anticipation import DelayLine, intent_ways
from haven_scenarios.study.conditions import parse_condition
from haven_scenarios.study.perception import Percept, Sight, perceive
from haven_scenarios.study.person import PersonParams
from haven_scenarios.study.scenario import ScenarioError, load_scenario, parse_scenario
from haven_sim.common.geometry import Pose2D
from haven_sim.sim.occupancy import rasterise
from haven_sim.sim.world_file import parse_world
from haven_viz.cues import CueState, Toggles

# A 10 m x 6 m room split by a wall at x = 5 from y = 0 to y = 4 (a gap above it).
ROOM = {
    "name": "room",
    "walls": [
        {"segment": s, "thickness": 0.1}
        for s in ([[0, 0], [10, 0]], [[10, 0], [10, 6]], [[10, 6], [0, 6]], [[0, 6], [0, 0]], [[5, 0], [5, 4]])
    ],
    "robot": {"start": [3.0, 2.0, 0.0]},
    "humans": [{"id": "h1", "start": [1.0, 2.0, 0.0]}],
}
SIGHT = Sight(rasterise(parse_world(ROOM)))
P = PersonParams()
ME = Pose2D(1.0, 2.0, 0.0)  # facing +x
ALL = CueState(Toggles(), {"path_markers": 3, "turn_signal": 1, "thought": "Going to gem rg1", "battery_level": 0.7})
MARKERS = [(3.4, 2.0), (3.8, 2.0), (4.2, 2.0), (4.6, 2.0)]


def look(robot, cues=ALL, me=ME, markers=MARKERS, params=P):
    return perceive(params, SIGHT, 0.0, me, robot, cues, markers)


def test_the_robot_and_its_cues_are_seen_in_front_within_the_field_of_view_and_distance():
    p = look(Pose2D(3.0, 2.0, math.pi))
    assert p.robot == Pose2D(3.0, 2.0, math.pi)
    assert p.path == tuple(MARKERS[:3])  # the markers on show, not the fourth one of the plan
    assert (p.signal, p.thought, p.battery) == (1, "Going to gem rg1", 0.7)
    behind = look(Pose2D(3.0, 2.0, 0.0), me=Pose2D(1.0, 2.0, math.pi))  # the person faces away
    assert behind.robot is None and behind.path == () and behind.signal == 0 and behind.thought == ""
    side = Pose2D(1.0, 2.0 + 2.0, 0.0)  # 90 deg off the heading: outside 110 deg, inside 200 deg
    assert look(side, markers=()).robot is None
    assert look(side, markers=(), params=replace(P, fov_deg=200.0)).robot == side
    far = Pose2D(4.5, 2.0, 0.0)
    assert look(far, markers=(), params=replace(P, view_m=3.0)).robot is None and look(far, markers=()).robot == far


def test_a_wall_hides_the_robot_and_the_markers_behind_it():
    robot = Pose2D(7.0, 2.0, math.pi)  # beyond the wall at x = 5
    p = look(robot, markers=[(6.0, 2.0), (6.0, 5.0)])
    assert p.robot is None and p.signal == 0 and p.thought == ""  # drawn on the robot: hidden with it
    assert p.path == ((6.0, 5.0),)  # the marker above the wall's end is in the open
    assert look(Pose2D(7.0, 5.5, math.pi), markers=()).robot is not None  # past the wall's end


@pytest.mark.parametrize("cue", ["path_projection", "turn_signals", "thought_bubble", "battery_indicator"])
def test_a_cue_off_in_the_condition_is_not_perceived(cue):
    off = replace(ALL, toggles=replace(Toggles(), **{cue: False}))
    p, q = look(Pose2D(3.0, 2.0, math.pi)), look(Pose2D(3.0, 2.0, math.pi), cues=off)
    shown = {
        "path_projection": "path",
        "turn_signals": "signal",
        "thought_bubble": "thought",
        "battery_indicator": "battery",
    }[cue]
    assert getattr(p, shown) and not getattr(q, shown)
    # before the viz says anything
    assert look(Pose2D(3.0, 2.0, math.pi), cues=None) == Percept(0.0, Pose2D(3.0, 2.0, math.pi))


def test_without_a_cue_the_robot_shows_no_way_and_with_one_it_does():
    robot = Pose2D(3.0, 2.0, math.pi)
    assert intent_ways(look(robot, cues=CueState(Toggles(False, False, False, False)))) == []
    ways = intent_ways(look(robot))
    assert len(ways) == 2 and ways[1] == MARKERS[:3]
    assert all(y < 2.0 for _, y in ways[0])  # the signal lit to the robot's left: facing -x, that is -y


def test_the_person_acts_one_reaction_time_late():
    line = DelayLine(1.0)
    for k in range(30):
        line.push(Percept(k * 0.1, Pose2D(k * 0.05, 0.0, 0.0)))
        acted = line.acted_on(k * 0.1)
        if k * 0.1 < 1.0 - 1e-9:
            assert acted is None
        else:
            assert acted is not None and acted.percept.stamp == pytest.approx(k * 0.1 - 1.0)
    assert acted.robot_v == pytest.approx((0.5, 0.0))  # the robot's motion as seen


def test_person_params_in_a_scenario_file_and_their_one_line_errors():
    def scenario(params):
        return {
            "name": "s",
            "world": "small_test",
            "kind": "retrieval",
            "humans": [{"id": "h1", "model": "yielder", "params": params}],
        }

    task = parse_scenario(scenario({"reaction_s": 1.5, "fov_deg": 90}), "s.yaml").humans[0]
    assert task.params == PersonParams(reaction_s=1.5, fov_deg=90.0)
    assert replace(task.params, view_m=4.0).view_m == 4.0  # what a sweep does
    assert load_scenario("hallway").humans[0].params == PersonParams()
    for params, message in (
        ({"reaction": 1.0}, "humans[0].params.reaction: unknown key"),
        ({"reaction_s": "soon"}, "humans[0].params.reaction_s: must be a finite number"),
        ({"reaction_s": True}, "humans[0].params.reaction_s: must be a finite number"),
        ({"reaction_s": -1.0}, "humans[0].params: reaction_s must not be negative"),
        ({"fov_deg": 400}, "humans[0].params: fov_deg must be within (0, 360]"),
        ([1, 2], "humans[0].params: must be a mapping"),
    ):
        with pytest.raises(ScenarioError, match=r"^s\.yaml: " + message.replace("[", r"\[").replace("(", r"\(")) as e:
            parse_scenario(scenario(params), "s.yaml")
        assert "\n" not in str(e.value)


def test_hesitation_is_slowing_while_walking_not_at_a_stop_nor_after_the_task():
    t = np.arange(0.0, 20.0, 0.02)
    speed = np.ones_like(t)
    speed[(t >= 5.0) & (t < 6.0)] = 0.2  # slows for 1 s mid-walk
    speed[(t >= 9.0) & (t < 9.3)] = 0.2  # a blip too short to count
    speed[(t >= 12.0) & (t < 15.0)] = 0.0  # stands on a stop
    speed[t >= 18.0] = 0.0  # done
    xy = np.column_stack([np.concatenate([[0.0], np.cumsum(speed[:-1] * 0.02)]), np.zeros_like(t)])
    stop = xy[np.searchsorted(t, 13.0)]
    count, seconds = hesitations(t, xy, np.array([stop]), 18.0)
    assert count == 1 and seconds == pytest.approx(1.0, abs=0.3)
    assert hesitations(t, xy, np.zeros((0, 2)), None)[0] == 3  # the stop and the end count without them


@pytest.mark.parametrize(
    "condition, sees_path", [(["none"], False), (["turn_signals"], False), (["path_projection"], True)]
)
def test_the_director_hands_the_blocker_the_path_only_when_the_projection_shows_it(condition, sees_path):
    s = load_scenario("hallway")
    s = replace(s, humans=tuple(replace(h, model="blocker") for h in s.humans))
    trial = Trial(s, 0, parse_condition(condition))
    seen_path, seen_robot = False, False
    for _ in range(40 * 50):  # 40 s: the person meets the robot in hallway A-B
        trial.loop.step()
        p = trial.director.percepts.get("h1")
        if p is not None:
            seen_path |= bool(p.path)
            seen_robot |= p.robot is not None
            me = trial.director.humans["h1"]
            assert all(math.hypot(x - me.x, y - me.y) <= P.view_m for x, y in p.path)  # what they can see of it
    assert trial.director.cue_state is not None and trial.director.cue_state.toggles == parse_condition(condition)
    assert seen_robot and seen_path is sees_path
