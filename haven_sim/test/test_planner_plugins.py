"""Path planners are plugins (nav/planner_kind.py): ours (`visibility`) is registered as a lab's is;
the planner's `algorithm` parameter picks one, and its points are shaped into HAVEN's path."""

from __future__ import annotations

import pytest
from fake_plugins import Entry
from helpers import box_world

from haven_sim.common import plugins, topics
from haven_sim.common.events import EventKind
from haven_sim.common.geometry import Point, Pose2D
from haven_sim.common.params import ParamsError
from haven_sim.common.state import Goal, RobotState
from haven_sim.nav.planner import Plan, PlannerParams
from haven_sim.nav.planning import PlannerComponent, PlannerConfig
from haven_sim.robots.fields import build_config
from haven_sim.sim.occupancy import OccupancyGridData, rasterise


class Corner:
    """A lab's planner: along x first, then along y (an L, where ours goes straight)."""

    def __init__(self, grid: OccupancyGridData, params: PlannerParams) -> None:
        self.grid, self.params = grid, params

    def plan(self, start: Point, goal: Point) -> Plan:
        points = [start, (goal[0], start[1]), goal]
        return Plan(points, abs(goal[0] - start[0]) + abs(goal[1] - start[1]))


class Crashing(Corner):
    """A lab's planner with a bug."""

    def plan(self, start: Point, goal: Point) -> Plan:
        raise RuntimeError("index out of range\nmore")


@pytest.fixture
def with_corner(monkeypatch):
    reg = plugins.load(
        "planners",
        [
            Entry(
                "visibility",
                "haven_sim.nav.planner:GridPlanner",
                "haven_sim",
                plugins.registry("planners").get("visibility"),
            ),
            Entry("corner", "lab.planners:Corner", "lab_planners", Corner),
            Entry("crashing", "lab.planners:Crashing", "lab_planners", Crashing),
            Entry("number", "lab.planners:N", "lab_planners", 3),
        ],
    )
    real = plugins.registry
    monkeypatch.setattr(plugins, "registry", lambda kind: reg if kind == "planners" else real(kind))
    return reg


def plan_of(config: PlannerConfig) -> list[Pose2D]:
    planner = PlannerComponent(config)
    planner.on_map(rasterise(box_world(10.0)), 0.0)
    planner.on_odom(RobotState(Pose2D(2.0, 2.0, 0.0)), 0.0)
    (poses,) = [m.data for m in planner.on_goal(Goal(Pose2D(8.0, 8.0, 0.0)), 0.1) if m.topic == topics.PLAN]
    return list(poses)


def test_ours_is_a_registered_plugin():
    item = plugins.registry("planners").items["visibility"]
    assert (item.package, item.target) == ("haven_sim", "haven_sim.nav.planner:GridPlanner")


def test_the_algorithm_parameter_picks_a_labs_planner_whose_points_are_shaped(with_corner):
    ours, lab = plan_of(PlannerConfig()), plan_of(build_config(PlannerConfig, {"algorithm": "corner"}))

    def by_the_corner(path: list[Pose2D]) -> bool:
        return any(p.x > 7.5 and p.y < 2.5 for p in path)

    assert not by_the_corner(ours) and by_the_corner(lab)  # ours goes straight; the lab's by (8, 2), shaped
    assert (lab[-1].x, lab[-1].y) == (pytest.approx(8.0, abs=0.05), pytest.approx(8.0, abs=0.05))
    assert "haven.planners number (lab.planners:N, from lab_planners): is not a planner" in with_corner.problems[0]


def test_an_unknown_algorithm_is_one_line_naming_the_known_ones(with_corner):
    with pytest.raises(
        ParamsError,
        match=r"^planner: parameter algorithm: unknown planner 'astar' \(known: corner, crashing, visibility\)$",
    ):
        build_config(PlannerConfig, {"algorithm": "astar"}, where="planner: parameter ")


def test_a_labs_planner_that_raises_refuses_the_goal_in_one_line_and_the_trial_goes_on(with_corner):
    planner = PlannerComponent(build_config(PlannerConfig, {"algorithm": "crashing"}))
    planner.on_map(rasterise(box_world(10.0)), 0.0)
    planner.on_odom(RobotState(Pose2D(2.0, 2.0, 0.0)), 0.0)
    (refused,) = [m.data for m in planner.on_goal(Goal(Pose2D(8.0, 8.0, 0.0)), 0.1) if m.topic == topics.EVENTS]
    assert (
        refused.kind is EventKind.PLAN_REFUSED
        and refused["reason"] == "the planner failed: RuntimeError: index out of range"
    )
    assert planner.warnings == ["refused goal (8.00, 8.00): the planner failed: RuntimeError: index out of range"]
