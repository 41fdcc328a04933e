"""Centre-line travel: routes through a hallway run down its centre line, rooms entered on it."""

import numpy as np
import pytest
from helpers import corridor

from haven_sim.common.geometry import Pose2D
from haven_sim.nav.lanes import Lane, onto_lanes
from haven_sim.nav.navigator import Navigator
from haven_sim.nav.planning import world_lanes
from haven_sim.sim.simulation import Simulation
from haven_sim.sim.world_file import load_world


def hallway_navigator(lanes=True):
    world = load_world(_hallway_file())
    sim = Simulation(world)
    return Navigator(sim.occupancy(), lanes=world_lanes(world) if lanes else ())


def _hallway_file():
    from importlib import resources

    return resources.files("haven_scenarios") / "worlds" / "hallway.yaml"


def _off_centre(path, x_range, y_range, centre_x=None, centre_y=None):
    pts = np.array([(p.x, p.y) for p in path])
    inside = (pts[:, 0] > x_range[0]) & (pts[:, 0] < x_range[1]) & (pts[:, 1] > y_range[0]) & (pts[:, 1] < y_range[1])
    assert inside.sum() >= 2
    return (
        float(np.max(np.abs(pts[inside, 0] - centre_x)))
        if centre_x is not None
        else float(np.max(np.abs(pts[inside, 1] - centre_y)))
    )


@pytest.mark.parametrize("start", [(15.6, 2.3, 1.2), (16.4, 1.7, 0.3), (15.2, 2.8, 2.0)])
def test_a_leg_started_off_a_room_centre_runs_down_the_hallway_centre_line(start):
    nav = hallway_navigator()
    out = nav.set_goal(Pose2D(*start), Pose2D(16.0, 16.0, float("nan")), 0.0)
    # Hallway BC: x in [15, 17], y in [4, 14]; its centre line is x = 16.
    assert _off_centre(out.path, (15.0, 17.0), (4.5, 13.5), centre_x=16.0) < 0.03
    # Into room C on the centre line too.
    assert _off_centre(out.path, (15.0, 17.0), (14.0, 15.0), centre_x=16.0) < 0.03


def test_without_lanes_the_same_leg_is_a_diagonal():
    nav = hallway_navigator(lanes=False)
    out = nav.set_goal(Pose2D(15.6, 2.3, 1.2), Pose2D(16.0, 16.0, float("nan")), 0.0)
    assert _off_centre(out.path, (15.0, 17.0), (4.5, 13.5), centre_x=16.0) > 0.1


def test_a_route_that_only_crosses_a_hallway_keeps_its_shape():
    lane = Lane(((0.0, 5.0), (10.0, 5.0)), 2.0)
    route = [(5.0, 0.0), (5.0, 10.0)]  # across the lane, not along it
    assert onto_lanes(route, [lane], lambda a, b: True) == route


def test_a_centre_line_that_would_hit_a_wall_is_not_used():
    lane = Lane(((0.0, 5.0), (10.0, 5.0)), 2.0)
    route = [(0.0, 4.5), (10.0, 4.5)]
    assert onto_lanes(route, [lane], lambda a, b: False) == route
    moved = onto_lanes(route, [lane], lambda a, b: True)
    assert all(abs(y - 5.0) < 1e-9 for _, y in moved[1:-1])


def test_a_corridor_world_without_hallways_plans_as_before():
    sim = Simulation(corridor())
    nav = Navigator(sim.occupancy())
    out = nav.set_goal(sim.robot_pose(), Pose2D(11.0, 1.5, 0.0), 0.0)
    assert all(abs(p.y - 1.5) < 1e-9 for p in out.path)
