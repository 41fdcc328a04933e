"""Any-angle planning on inflated grids: clearance, optimality, refusals, foreign maps."""

import itertools
import math

import numpy as np
import pytest
from helpers import box_world

from haven_sim.common.geometry import distance_point_to_edges
from haven_sim.nav.planner import GridPlanner, PlannerParams, PlanningError, convex_corners, inflate_square
from haven_sim.sim.occupancy import OccupancyGridData, rasterise
from haven_sim.sim.world import packaged_world
from haven_sim.sim.world_file import load_world


def min_clearance(world, points):
    edges = world.edges()
    worst = math.inf
    for a, b in itertools.pairwise(points):
        for t in np.linspace(0, 1, max(2, int(math.dist(a, b) / 0.02))):
            worst = min(worst, distance_point_to_edges(a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, edges))
    return worst


@pytest.fixture(scope="module")
def small():
    world = load_world(packaged_world("small_test"))
    return world, GridPlanner(rasterise(world))


def test_inflation_and_corners_on_a_tiny_grid():
    occ = np.zeros((7, 7), dtype=bool)
    occ[3, 3] = True
    blocked = inflate_square(occ, 1)
    assert blocked.sum() == 9 and blocked[2:5, 2:5].all()
    corners = {tuple(rc) for rc in convex_corners(blocked)}
    assert corners == {(1, 1), (1, 5), (5, 1), (5, 5)}


def test_straight_line_when_visible(small):
    _, planner = small
    plan = planner.plan((1.0, 2.5), (3.0, 1.0))
    assert plan.points == [(1.0, 2.5), (3.0, 1.0)]
    assert plan.length_m == pytest.approx(2.5)


def test_path_through_the_door_keeps_clear_of_walls_and_is_near_shortest(small):
    world, planner = small
    plan = planner.plan((1.0, 1.0), (7.0, 1.0))
    assert len(plan.points) >= 3  # around the door jamb
    assert min_clearance(world, plan.points) >= planner.params.inflation_m - 0.01
    # the door is at x = 4, y in 1.9 .. 3.1: the shortest path bends around (4, 1.9 + inflation)
    via = (4.0, 1.9 + 0.05 + planner.params.inflation_m)
    lower = math.dist((1, 1), via) + math.dist(via, (7, 1))
    assert lower <= plan.length_m <= lower * 1.05


@pytest.mark.parametrize(
    "goal,reason",
    [((20.0, 2.0), "outside the map"), ((6.3, 3.8), "inside an obstacle"), ((4.0, 1.0), "inside an obstacle")],
)
def test_unreachable_goals_are_refused_with_a_reason(small, goal, reason):
    _, planner = small
    with pytest.raises(PlanningError, match=reason):
        planner.plan((1.0, 2.5), goal)


def test_disconnected_goal_is_refused():
    closed = box_world(
        6.0, obstacles=[{"segment": [[3.0, 0.0], [3.0, 6.0]], "thickness": 0.2}], robot={"start": [1.0, 3.0, 0.0]}
    )
    planner = GridPlanner(rasterise(closed))
    with pytest.raises(PlanningError, match=r"not reachable|no way out"):
        planner.plan((1.0, 3.0), (5.0, 3.0))


def test_goal_near_a_wall_is_snapped_onto_free_space(small):
    _, planner = small
    plan = planner.plan((1.0, 2.5), (2.0, 0.2))  # 0.15 m from the wall face: inside the inflation
    end = plan.points[-1]
    assert planner.is_free(*end)
    assert math.dist(end, (2.0, 0.2)) <= planner.params.snap_radius_m


def test_plans_on_a_map_it_did_not_make():
    """A hand-made OccupancyGrid (rows = y, unknown cells = -1), like one from SLAM."""
    data = np.zeros((60, 100), dtype=np.int8)
    data[0, :] = data[-1, :] = data[:, 0] = data[:, -1] = 100
    data[:45, 50] = 100  # a wall from the bottom with a gap at the top
    data[20:25, 70:75] = -1  # an unknown patch
    grid = OccupancyGridData(0.1, 100, 60, -2.0, 1.0, data)
    planner = GridPlanner(grid, PlannerParams(safety_margin_m=0.05, body_radius_m=0.2))
    plan = planner.plan((0.0, 2.0), (6.0, 2.0))
    assert max(p[1] for p in plan.points) > 1.0 + 4.5  # over the top of the wall
    assert all(
        planner.visible(np.array([a]), np.array([b]))[0] for a, b in zip(plan.points, plan.points[1:], strict=False)
    )
    with pytest.raises(PlanningError, match="inside an obstacle"):
        planner.plan((0.0, 2.0), (5.2, 3.2))  # in the unknown patch


def test_random_queries_on_the_small_world_are_all_clear(small):
    world, planner = small
    rng = np.random.default_rng(1)
    done = 0
    while done < 30:
        s, g = tuple(rng.uniform((0, 0), (8, 5))), tuple(rng.uniform((0, 0), (8, 5)))
        if not (planner.is_free(*s) and planner.is_free(*g)):
            continue
        plan = planner.plan(s, g)
        assert min_clearance(world, plan.points) >= planner.params.inflation_m - 0.02
        assert plan.length_m >= math.dist(s, g) - 1e-9
        done += 1


def test_free_run_to_the_walls_of_a_box_one_ray_or_many_at_once():
    planner = GridPlanner(rasterise(box_world(4.0)))  # walls 0.1 thick on the border: inner faces at 0.05 and 3.95
    start = (1.0, 2.0)
    dirs = np.array([(1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)])
    one_by_one = [planner.free_run(start, (float(x), float(y))) for x, y in dirs]
    assert one_by_one == pytest.approx([2.95, 0.95, 1.95, 1.95], abs=planner.grid.resolution_m)
    assert planner.free_run(start, dirs).tolist() == one_by_one  # the same samples, the same first hit
    assert planner.free_run(start, dirs, max_m=0.5).tolist() == [0.5] * 4  # nothing within reach
