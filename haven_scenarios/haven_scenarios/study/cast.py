"""Who plays in a trial besides the robot's software: the simulated participants (plugins of kind
`participants`, made here) and the robot's targets, from the scenario and the map."""

from __future__ import annotations

from haven_scenarios.study.mission import Target
from haven_scenarios.study.participant_kind import make_walker
from haven_scenarios.study.participants import HUMAN_PLANNER, Participant, Stop, shuffled_nearest
from haven_scenarios.study.scenario import Scenario
from haven_sim.nav.planner import GridPlanner
from haven_sim.sim.occupancy import OccupancyGridData


def robot_targets(scenario: Scenario) -> list[Target]:
    w = scenario.world
    if scenario.kind == "hallway":
        return [Target(r, *w.room(r).centre, f"room {r}") for r in scenario.robot_route]
    return [Target(g.id, g.position[0], g.position[1], f"gem {g.id}") for g in w.gems if g.owner == "robot"]


def _aside(planner: GridPlanner, stop: Stop, offset_m: float = 1.2) -> Stop:
    """A free spot diagonally off a room centre, for a participant who has finished."""
    for dx, dy in ((1, 1), (-1, 1), (1, -1), (-1, -1)):
        x, y = stop.x + dx * offset_m, stop.y + dy * offset_m
        if planner.is_free(x, y):
            return Stop(x, y, 0.0, 0.2)
    return stop


def make_participants(scenario: Scenario, grid: OccupancyGridData, seed: int) -> dict[str, Participant]:
    """The simulated participants (teleoperated ones are driven by a person, not here)."""
    planner = GridPlanner(grid, HUMAN_PLANNER)
    w = scenario.world
    starts = {h.id: h.start for h in w.humans}
    out: dict[str, Participant] = {}
    for k, task in enumerate(scenario.humans):
        if task.teleoperated:
            continue
        s = seed * 101 + k
        if scenario.kind == "hallway":
            stops = [Stop(*w.room(r).centre, dwell_s=0.0, reach_m=0.3) for r in task.route]
            if stops:  # done, a person steps out of the way instead of standing on the room's centre
                stops.append(_aside(planner, stops[-1]))
        else:
            gems = [
                Stop(g.position[0], g.position[1], dwell_s=scenario.dwell_time_s + 0.5, reach_m=0.12)
                for g in w.gems
                if g.owner == "human"
            ]
            start = starts[task.id]
            stops = shuffled_nearest(gems, (start.x, start.y), s)
        out[task.id] = make_walker(task.model, task.id, stops, planner, task.speed_mps, s, task.params)
    return out
