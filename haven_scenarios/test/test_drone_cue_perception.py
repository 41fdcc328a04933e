"""A simulated participant perceives the drone's cues (Walker et al. 2018) by the common rule: NavPoints'
points where they are drawn, when in view; the Arrow and Gaze with the drone."""

import math

import pytest

from haven_scenarios.study.perception import Sight, cue_ways, perceive
from haven_scenarios.study.person import PersonParams
from haven_sim.common.geometry import Pose2D
from haven_sim.robots.robot_kind import resolve_robot
from haven_sim.sim.occupancy import rasterise
from haven_sim.sim.world_file import parse_world
from haven_viz.cues import ArCues, Toggles

pytestmark = pytest.mark.unit

ROOM = {  # 10 m x 6 m, one wall at x = 5 from y = 0 to y = 4
    "name": "room",
    "walls": [
        {"segment": s, "thickness": 0.1}
        for s in ([[0, 0], [10, 0]], [[10, 0], [10, 6]], [[10, 6], [0, 6]], [[0, 6], [0, 0]], [[5, 0], [5, 4]])
    ],
    "robot": {"start": [1.0, 5.0, 0.0]},
    "humans": [{"id": "h1", "start": [1.0, 2.0, 0.0]}],
}
SIGHT = Sight(rasterise(parse_world(ROOM)))
DRONE = resolve_robot("quadrotor")
PATH = [Pose2D(1.0 + 0.5 * i, 5.0, 0.0) for i in range(9)]  # 4 m along y = 5, above the wall's end


def percept(me, toggles=None):
    cues = ArCues(robot=DRONE)
    cues.set_path(PATH)
    robot = PATH[0]
    frame = cues.frame(robot, toggles=toggles or Toggles(), altitude_m=1.5)
    ways = cue_ways(cues, frame.state, robot, [(me.x, me.y)], None, "", 0.0)
    return perceive(PersonParams(), SIGHT, 0.0, me, robot, frame.state, ways=ways, robot_radius_m=DRONE.radius_m), frame


def test_navpoints_in_view_are_perceived_where_they_are():
    p, frame = percept(Pose2D(3.0, 2.0, math.pi / 2))  # facing the route (+y)
    points = frame.ways["nav_points"][0]
    assert points in p.ways and p.shown["nav_points"] == len(points) == 3
    assert p.shown.keys() >= {"nav_points", "arrow", "gaze"}


def test_navpoints_out_of_view_are_not_perceived_and_a_switched_off_cue_never_is():
    p, frame = percept(Pose2D(3.0, 2.0, -math.pi / 2))  # facing away
    assert "nav_points" not in p.shown and frame.ways["nav_points"][0] not in p.ways
    q, _ = percept(Pose2D(3.0, 2.0, math.pi / 2), Toggles().replaced({"nav_points": False}))
    assert "nav_points" not in q.shown and "gaze" in q.shown
