"""The scenario side of a trial, shared by batch mode and the ROS scenario node.

`ScenarioCore` holds the mission executive, the scenario rules and the simulated participants. It is
fed what a node would receive (poses, battery level, the robot's path, other nodes' events) and
returns what a node would publish (a goal, the thought text, participants' velocity commands,
events, obstructions to clear, the end of the trial). Batch mode wires it to in-process simulator
and navigation objects; the scenario node wires it to topics. Neither adds behaviour of its own.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

from haven_scenarios.study.mission import Mission, MissionOutput, Phase, Target
from haven_scenarios.study.participants import Blocker, Stop, Walker, Yielder
from haven_scenarios.study.rules import EndRule, GemRules, ObstructionRules, RouteRules
from haven_scenarios.study.scenario import Scenario
from haven_sim.common.geometry import Point, Pose2D, Twist2D
from haven_sim.sim.occupancy import OccupancyGridData
from haven_sim.nav.planner import GridPlanner, PlannerParams, PlanningError

HUMAN_PLANNER = PlannerParams(robot_radius_m=0.25, safety_margin_m=0.05, snap_radius_m=0.5)


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


def make_participants(scenario: Scenario, grid: OccupancyGridData, seed: int) -> dict[str, Walker]:
    """The simulated participants (teleoperated ones are driven by a person, not here)."""
    planner = GridPlanner(grid, HUMAN_PLANNER)
    w = scenario.world
    starts = {h.id: h.start for h in w.humans}
    out: dict[str, Walker] = {}
    for k, task in enumerate(scenario.humans):
        if task.model == "teleop":
            continue
        s = seed * 101 + k
        if scenario.kind == "hallway":
            stops = [Stop(*w.room(r).centre, dwell_s=0.0, reach_m=0.3) for r in task.route]
            if stops:  # done, a person steps out of the way instead of standing on the room's centre
                stops.append(_aside(planner, stops[-1]))
        else:
            gems = [Stop(g.position[0], g.position[1], dwell_s=scenario.dwell_time_s + 0.5, reach_m=0.12) for g in w.gems if g.owner == "human"]
            start = starts[task.id]
            stops = Walker.shuffled_nearest(gems, (start.x, start.y), s)
        cls = {"walker": Walker, "blocker": Blocker, "yielder": Yielder}[task.model]
        out[task.id] = cls(task.id, stops, planner, task.speed_mps, s)
    return out


@dataclass
class CoreOutput:
    goal: Pose2D | None = None
    thought: str | None = None
    human_cmds: dict[str, Twist2D] = field(default_factory=dict)
    events: list[dict[str, Any]] = field(default_factory=list)
    clear_obstructions: list[str] = field(default_factory=list)
    end: str | None = None

    def merge(self, m: MissionOutput) -> None:
        if m.goal is not None:
            self.goal = m.goal
        if m.thought is not None:
            self.thought = m.thought
        self.events += [{"source": "mission", **e} for e in m.events]


class ScenarioCore:
    def __init__(self, scenario: Scenario, grid: OccupancyGridData, seed: int = 0, robot_planner: GridPlanner | None = None) -> None:
        self.scenario = scenario
        w = scenario.world
        self.planner = robot_planner or GridPlanner(grid)
        self.participants = make_participants(scenario, grid, seed)
        base = w.charging_base
        self.mission = Mission(
            robot_targets(scenario),
            self.path_length,
            "fixed" if scenario.kind == "hallway" else scenario.robot_order,
            scenario.battery,
            base.position if base else None,
            seed,
        )
        self.gems = GemRules(w.gems, scenario.dwell_time_s)
        routes: dict[str, Sequence[str]] = {}
        if scenario.kind == "hallway":
            routes = {"robot": scenario.robot_route, **{h.id: h.route for h in scenario.humans}}
        self.routes = RouteRules(w, routes)
        self.obstructions = ObstructionRules(w)
        self.end_rule = EndRule(scenario.timeout_s, scenario.end_on_contact)
        self.humans_done: set[str] = set()
        self.contact = False
        self.empty_since: float | None = None  # when the battery ran out (the robot cannot drive)
        self.waiting = False
        self.arrived = False  # the controller reached the last goal sent
        self.start_time: float | None = None
        self.ended: str | None = None

    def path_length(self, a: Point, b: Point) -> float:
        try:
            return self.planner.plan(a, b).length_m
        except PlanningError:
            return math.inf

    def set_map(self, grid: OccupancyGridData) -> None:
        self.planner = GridPlanner(grid, self.planner.params)

    def _merge(self, out: CoreOutput, m: MissionOutput) -> None:
        out.merge(m)
        if m.goal is not None:
            self.arrived = False
            if self.mission.current is not None and self.mission.phase is Phase.GOING and self.scenario.kind == "retrieval":
                self.gems.robot_target = self.mission.current.id

    def start(self, now: float, robot: Pose2D, level: float) -> CoreOutput:
        self.start_time = now
        out = CoreOutput()
        out.events.append({"source": "scenario", "type": "trial_start", "scenario": self.scenario.name})
        self._merge(out, self.mission.start(robot, level))
        return out

    def on_event(self, event: Mapping[str, Any], robot: Pose2D) -> CoreOutput:
        """Events of the other nodes: planner waits, controller arrivals, contacts, map changes."""
        out = CoreOutput()
        kind = event.get("type")
        if kind == "waiting":
            self.waiting = True
        elif kind in ("resumed", "plan_made", "replanned"):
            self.waiting = False
        elif kind == "goal_reached":
            self.arrived = True
        elif kind == "contact_begin" and str(event.get("other", "")).startswith("human"):
            self.contact = True
        elif kind == "battery_empty":
            self.empty_since = float(event.get("stamp", 0.0))
        elif kind == "obstruction_removed":
            self._merge(out, self.mission.resend())
        return out

    def tick(self, now: float, robot: Pose2D, humans: Mapping[str, Pose2D], level: float, robot_path: Sequence[Pose2D]) -> CoreOutput:
        """The 10 Hz step: participants move, rules fire, the mission decides, the end is checked."""
        out = CoreOutput()
        if self.ended is not None:
            return out
        for hid, walker in self.participants.items():
            if hid in humans:
                out.human_cmds[hid] = walker.command(now, humans[hid], robot, robot_path)
        events = self.gems.update(now, robot, humans) + self.routes.update({"robot": robot, **humans})
        events += self.obstructions.update(humans)
        out.events += [{"source": "scenario", **e} for e in events]
        for e in events:
            if e["type"] == "obstruction_cleared":
                out.clear_obstructions.append(e["id"])
            elif e["type"] == "gem_collected" and e["by"] == "robot":
                self._merge(out, self.mission.target_done(e["gem"], robot, level))
            elif e["type"] == "room_reached" and e["by"] == "robot" and self.mission.current is not None and e["room"] == self.mission.current.id:
                self._merge(out, self.mission.target_done(e["room"], robot, level))
        for hid in self.participants:
            if hid not in self.humans_done and self._human_finished(hid):
                self.humans_done.add(hid)
                out.events.append({"source": "scenario", "type": "task_done", "by": hid})
        base = self.scenario.world.charging_base
        at_base = base is not None and self.arrived and robot.distance_to(base.position) <= base.radius
        if base is not None and self.arrived and not at_base and self.mission.phase is Phase.TO_BASE:
            self._merge(out, self.mission.resend())  # stopped short of (or past) the base: once more
        self._merge(out, self.mission.tick(robot, level, at_base, self.waiting))
        all_done = self.mission.phase is Phase.DONE and self.humans_done >= set(self.participants)
        elapsed = now - (self.start_time if self.start_time is not None else now)
        if level > 0.0:
            self.empty_since = None
        # Empty and not charging for a while (a robot that made it onto the base recharges).
        stranded = self.empty_since is not None and now - self.empty_since > 5.0
        self.ended = out.end = "battery_empty" if stranded and not all_done else self.end_rule.reason(elapsed, all_done, self.contact)
        if out.end is not None:
            out.events.append({"source": "scenario", "type": "trial_end", "reason": out.end})
        return out

    def _human_finished(self, hid: str) -> bool:
        if self.scenario.kind == "hallway":
            return self.routes.done(hid)
        return not self.gems.remaining("human")
