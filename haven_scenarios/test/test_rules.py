"""Scenario rules: dwell with reset, only-target collection, routes, obstructions, trial end."""

import pytest

from haven_scenarios.study.rules import EndRule, GemRules, ObstructionRules, RouteRules
from haven_scenarios.study.scenario import load_scenario
from haven_sim.common.events import EventKind
from haven_sim.common.geometry import Pose2D
from haven_sim.sim.world import Gem

GEMS = [Gem("r1", "robot", (2.0, 0.0), 0.3), Gem("r2", "robot", (1.0, 0.0), 0.3), Gem("m1", "human", (5.0, 5.0), 0.35)]


def test_robot_collects_only_its_target_not_gems_it_brushes_past():
    rules = GemRules(GEMS)
    rules.robot_target = "r1"
    assert rules.update(0.0, Pose2D(1.0, 0.0), {}) == []  # on top of r2, which is not the target
    events = rules.update(0.1, Pose2D(1.9, 0.1), {})
    assert [e.to_dict() for e in events] == [
        {"stamp": 0.1, "source": "scenario", "type": "gem_collected", "gem": "r1", "by": "robot"}
    ]
    assert [g.id for g in rules.remaining("robot")] == ["r2"] and rules.robot_target is None


def test_robot_does_not_collect_human_gems_nor_humans_robot_gems():
    rules = GemRules(GEMS, dwell_time_s=0.0)
    rules.robot_target = "m1"
    assert rules.update(0.0, Pose2D(5.0, 5.0), {"h1": Pose2D(2.0, 0.0)}) == []


def test_human_dwell_must_be_continuous_and_restarts_on_leaving():
    rules = GemRules(GEMS, dwell_time_s=3.0)
    on, off = Pose2D(5.1, 5.0), Pose2D(6.0, 5.0)
    types = []
    for t, pose in [(0.0, on), (2.9, on), (3.0, off), (4.0, on), (6.9, on), (7.0, on)]:
        types += [(t, e.kind) for e in rules.update(t, Pose2D(0, 0), {"h1": pose})]
    assert types == [
        (0.0, EventKind.DWELL_STARTED),
        (3.0, EventKind.DWELL_RESET),
        (4.0, EventKind.DWELL_STARTED),
        (7.0, EventKind.GEM_COLLECTED),
    ]
    assert rules.collected == {"m1": "h1"}
    assert rules.update(8.0, Pose2D(0, 0), {"h1": on}) == []  # gone: collected once


def test_routes_in_order():
    scenario = load_scenario("hallway")
    rules = RouteRules(scenario.world, {"robot": ["B", "C"]})
    c = scenario.world.room("C").centre
    assert rules.update(0.0, {"robot": Pose2D(*c)}) == []  # C before B does not count
    b = scenario.world.room("B").centre
    reached = rules.update(1.0, {"robot": Pose2D(*b)})[0]
    assert (reached.kind, reached.data) == (EventKind.ROOM_REACHED, {"room": "B", "by": "robot", "index": 1})
    rules.update(2.0, {"robot": Pose2D(*c)})
    assert rules.done("robot")
    with pytest.raises(ValueError, match="rooms not in world"):
        RouteRules(scenario.world, {"robot": ["Z"]})


def test_obstruction_cleared_when_a_human_reaches_its_room():
    scenario = load_scenario("hallway_hard")
    rules = ObstructionRules(scenario.world)
    b = scenario.world.room("B").centre
    assert rules.update(0.0, {"h1": Pose2D(b[0] + 2.0, b[1])}) == []
    (cleared,) = rules.update(1.0, {"h1": Pose2D(*b)})
    assert (cleared.kind, cleared.data) == (EventKind.OBSTRUCTION_CLEARED, {"id": "crate", "by": "h1", "room": "B"})
    assert rules.update(2.0, {"h1": Pose2D(*b)}) == []


def test_trial_end_reasons():
    end = EndRule(timeout_s=100.0, end_on_contact=True)
    assert end.reason(10.0, all_done=False, contact=False) is None
    assert end.reason(10.0, all_done=True, contact=True) == "completed"
    assert end.reason(10.0, all_done=False, contact=True) == "contact"
    assert end.reason(100.0, all_done=False, contact=False) == "timeout"
    assert EndRule(100.0).reason(10.0, False, True) is None  # contact ends trials only when asked
