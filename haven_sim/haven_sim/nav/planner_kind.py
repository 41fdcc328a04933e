"""What a path planner is: the plugin kind `haven.planners` (common/plugins.py).

A planner is a class (or factory) taking `(grid: OccupancyGridData, params: PlannerParams)` — the
map (ours from the world file, or any /map) and the inflation settings — whose objects answer
`plan(start, goal) -> Plan` (`nav/planner.py`: the points from start to goal, and the length) or
raise `PlanningError` with a one-line reason. The planner node and batch mode make one per map (and
one per detour, on the map with the people in it), name it with the planner's `algorithm`
parameter, and shape whatever points it returns into HAVEN's arc / straight / rotate path, so the
cues, the controller and the metrics work the same with any planner. HAVEN's `visibility`
(`planner.GridPlanner`: any-angle shortest paths on a visibility graph) registers as a lab's does.
"""

from __future__ import annotations

import inspect
from typing import Any, Protocol, cast

from haven_sim.common import contain, plugins
from haven_sim.common.geometry import Point
from haven_sim.nav.planner import GridPlanner, Plan, PlanFailure, PlanningError

DEFAULT = "visibility"


class PathSearch(Protocol):
    def plan(self, start: Point, goal: Point) -> Plan: ...


class PlannerFactory(Protocol):
    """A `haven.planners` plugin: a class or function that makes a search on the occupancy grid."""

    def __call__(self, grid: Any, params: Any) -> PathSearch: ...


def accept_plugin(name: str, value: Any) -> PlannerFactory:
    """A `haven.planners` plugin: a class or factory taking (grid, params) whose objects plan(start, goal)."""
    if not callable(value) or (inspect.isclass(value) and not callable(getattr(value, "plan", None))):
        raise ValueError("is not a planner: a class taking (grid, params) with a plan(start, goal) method")
    return cast(PlannerFactory, value)


def planner_class(name: str) -> Any:
    """The planner registered as `name` (PluginError naming the known ones otherwise); a lab's
    `Contained` (ours, HAVEN's `visibility`, is trusted: the navigator asks it things beyond plans)."""
    found = plugins.registry("planners").get(name)
    return found if found is GridPlanner else Contained(name, found)


class Contained:
    """A lab's planner called as every plugin is (common/contain.py): made like its class, it makes
    searches whose failures (a raise other than PlanningError, or an overrun of the deadline) are a
    PlanningError for the navigator (the goal refused) and kept in `failed` for the trial to end on."""

    def __init__(self, name: str, made_by: Any) -> None:
        self.name, self.made_by = name, made_by
        self.failed: list[contain.PluginFailed] = []

    def __call__(self, grid: Any, params: Any) -> PathSearch:
        try:
            return _Search(self, contain.call("planners", self.name, self.made_by, grid, params))
        except contain.PluginFailed as e:
            self.failed.append(e)
            return _Search(self, None)


class _Search:
    def __init__(self, owner: Contained, inner: Any) -> None:
        self.owner, self.inner = owner, inner

    def plan(self, start: Point, goal: Point) -> Plan:
        if self.inner is None:
            raise PlanningError("the planner could not be made", PlanFailure.UNKNOWN)
        try:
            made: Plan = contain.call(
                "planners", self.owner.name, self.inner.plan, start, goal, expected=(PlanningError,)
            )
        except contain.PluginFailed as e:
            self.owner.failed.append(e)
            raise PlanningError(f"the planner failed: {e.error}", PlanFailure.UNKNOWN) from None
        return made
