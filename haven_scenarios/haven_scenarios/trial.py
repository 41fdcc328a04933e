"""One trial of a scenario in one process, no DDS: batch mode.

The same core objects the ROS nodes wrap (simulation, navigator, path follower, AR cues, mission
executive, scenario rules, simulated participants) are stepped in sim time as fast as the CPU
allows, at the rates the nodes use: physics 50 Hz, controller 25 Hz, participants / rules / cues /
logging 10 Hz, planner checks and mission 5 Hz.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from haven_scenarios.metrics import TrialLog, compute
from haven_scenarios.mission import Mission, Target
from haven_scenarios.participants import Blocker, Stop, Walker, Yielder
from haven_scenarios.rules import EndRule, GemRules, ObstructionRules, RouteRules
from haven_scenarios.scenario import Scenario
from haven_sim.battery import BatteryParams
from haven_sim.controller import PathFollower, Status
from haven_sim.geometry import Point, Pose2D
from haven_sim.navigator import Navigator, NavOutput
from haven_sim.occupancy import OccupancyGridData
from haven_sim.planner import GridPlanner, PlannerParams, PlanningError
from haven_sim.simulation import SimConfig, Simulation
from haven_viz.cues import CUES, ArCues, Toggles

HUMAN_PLANNER = PlannerParams(robot_radius_m=0.25, safety_margin_m=0.05, snap_radius_m=0.5)


def parse_condition(names: Sequence[str]) -> Toggles:
    """`all`, `none`, or the cues to show (the others are off)."""
    if not names or list(names) == ["all"]:
        return Toggles()
    if list(names) == ["none"]:
        return Toggles(False, False, False, False)
    unknown = [n for n in names if n not in CUES]
    if unknown:
        raise ValueError(f"unknown cue {unknown[0]!r} in the condition (cues: {', '.join(CUES)}, or all / none)")
    return Toggles(**{c: c in names for c in CUES})


def condition_name(t: Toggles) -> str:
    on = [c for c in CUES if getattr(t, c)]
    return "all" if len(on) == len(CUES) else ("none" if not on else "+".join(on))


def robot_targets(scenario: Scenario) -> list[Target]:
    w = scenario.world
    if scenario.kind == "hallway":
        return [Target(r, *w.room(r).centre, f"room {r}") for r in scenario.robot_route]
    return [Target(g.id, g.position[0], g.position[1], f"gem {g.id}") for g in w.gems if g.owner == "robot"]


def make_participants(scenario: Scenario, grid: OccupancyGridData, seed: int) -> dict[str, Walker]:
    planner = GridPlanner(grid, HUMAN_PLANNER)
    w = scenario.world
    starts = {h.id: h.start for h in w.humans}
    out: dict[str, Walker] = {}
    for k, task in enumerate(scenario.humans):
        if task.model == "teleop":
            continue  # a person drives this one
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


def _aside(planner: GridPlanner, stop: Stop, offset_m: float = 1.2) -> Stop:
    """A free spot diagonally off a room centre, for a participant who has finished."""
    for dx, dy in ((1, 1), (-1, 1), (1, -1), (-1, -1)):
        x, y = stop.x + dx * offset_m, stop.y + dy * offset_m
        if planner.is_free(x, y):
            return Stop(x, y, 0.0, 0.2)
    return stop


@dataclass
class TrialResult:
    scenario: str
    seed: int
    condition: str
    end_reason: str
    metrics: dict[str, Any]
    log: TrialLog = field(repr=False)


class Trial:
    """The state of one running trial; `run()` steps it to the end."""

    def __init__(self, scenario: Scenario, seed: int = 0, toggles: Toggles | None = None) -> None:
        self.scenario = scenario
        self.seed = seed
        self.toggles = toggles or Toggles()
        w = scenario.world
        base = w.charging_base
        battery = BatteryParams(capacity_m=scenario.battery.capacity_m, base_radius_m=base.radius if base else 0.5)
        self.sim = Simulation(w, SimConfig(battery=battery, seed=seed))
        grid = self.sim.occupancy()
        self.nav = Navigator(grid)
        self.follower = PathFollower()
        self.cues = ArCues()
        self.participants = make_participants(scenario, grid, seed)
        self.mission = Mission(
            robot_targets(scenario),
            self._path_length,
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
        self.end = EndRule(scenario.timeout_s, scenario.end_on_contact)
        self.log = TrialLog()
        self.thought = ""
        self.path: list[Pose2D] = []
        self.waiting = False
        self.goal: Pose2D | None = None
        self.humans_done: set[str] = set()
        self.contact = False

    # -- helpers -----------------------------------------------------------------------------------
    def _path_length(self, a: Point, b: Point) -> float:
        try:
            return self.nav.planner.plan(a, b).length_m
        except PlanningError:
            return math.inf

    def _emit(self, source: str, events: Sequence[dict[str, Any]]) -> None:
        for e in events:
            self.log.events.append({"stamp": round(self.sim.time, 4), "source": source, **e})

    def _apply_nav(self, out: NavOutput) -> None:
        if out.path is not None:
            self.path = out.path
            self.follower.set_path(out.path)
            self.cues.set_path(out.path)
        if out.waiting is not None:
            self.waiting = out.waiting
            self.follower.waiting = out.waiting
        self._emit("planner", out.events)

    def _apply_mission(self, out: Any) -> None:
        if out.thought is not None:
            self.thought = out.thought
        self._emit("mission", out.events)
        if out.goal is not None:
            self.goal = out.goal
            self._apply_nav(self.nav.set_goal(self.sim.robot_pose(), out.goal))
            if self.mission.current is not None and self.scenario.kind == "retrieval":
                self.gems.robot_target = self.mission.current.id

    def _robot_done_target(self, target_id: str) -> None:
        self._apply_mission(self.mission.target_done(target_id, self.sim.robot_pose(), self.sim.battery.level))

    # -- the loop ----------------------------------------------------------------------------------
    def run(self) -> TrialResult:
        sim = self.sim
        self._apply_mission(self.mission.start(sim.robot_pose(), sim.battery.level))
        k = 0
        reason = None
        while reason is None:
            robot = sim.robot_pose()
            if k % 2 == 0:
                was = self.follower.status
                sim.command_robot(self.follower.command(robot))
                if self.follower.status is Status.ARRIVED and was is not Status.ARRIVED and self.goal is not None:
                    self._emit("controller", [{"type": "goal_reached", "goal": [round(self.goal.x, 3), round(self.goal.y, 3)]}])
            if k % 5 == 0:
                reason = self._tick10(robot)
            if k % 10 == 0:
                self._apply_nav(self.nav.update(robot, [(p.x, p.y) for p in sim.human_poses().values()]))
                base = self.scenario.world.charging_base
                at_base = base is not None and self.follower.status is Status.ARRIVED and robot.distance_to(base.position) <= base.radius
                self._apply_mission(self.mission.tick(robot, sim.battery.level, at_base, self.waiting))
            sim.step()
            k += 1
        self._emit("scenario", [{"type": "trial_end", "reason": reason}])
        metrics = compute(self.log, self.scenario.name, reason)
        metrics.update(seed=self.seed, condition=condition_name(self.toggles))
        return TrialResult(self.scenario.name, self.seed, condition_name(self.toggles), reason, metrics, self.log)

    def _tick10(self, robot: Pose2D) -> str | None:
        sim = self.sim
        humans = sim.human_poses()
        for hid, walker in self.participants.items():
            sim.command_human(hid, walker.command(sim.time, humans[hid], robot, self.path))
        for sim_event in sim.pop_events():
            if sim_event.type == "contact_begin" and str(sim_event.data.get("other", "")).startswith("human"):
                self.contact = True
            self.log.events.append(sim_event.as_dict())
        events = self.gems.update(sim.time, robot, humans) + self.routes.update({"robot": robot, **humans})
        events += self.obstructions.update(humans)
        self._emit("scenario", events)
        for e in events:
            if e["type"] == "obstruction_cleared":
                sim.remove_obstruction(e["id"])
                self.log.events += [ev.as_dict() for ev in sim.pop_events()]
                self.nav.set_map(sim.occupancy())
                self._apply_mission(self.mission.resend())
            elif e["type"] == "gem_collected" and e["by"] == "robot":
                self._robot_done_target(e["gem"])
            elif e["type"] == "room_reached" and e["by"] == "robot" and self.mission.current is not None and e["room"] == self.mission.current.id:
                self._robot_done_target(e["room"])
        self._check_humans_done()
        markers = self.cues.markers(robot, [(h.x, h.y) for h in humans.values()], sim.battery.level, self.thought, self.toggles)
        bubble = self.toggles.thought_bubble and any(m.ns == "thought_bubble" for m in markers)
        signal = 0
        for m in markers:
            if m.ns == "turn_signals":
                signal = 1 if m.id == 0 else -1
        tw = sim.robot_twist()
        self.log.sample(sim.time, (robot.x, robot.y, robot.yaw, tw.wz), {h: (p.x, p.y) for h, p in humans.items()}, sim.battery.level, bubble, signal)
        all_done = self.mission.phase.value == "done" and self.humans_done >= set(self.participants)
        return self.end.reason(sim.time, all_done, self.contact)

    def _check_humans_done(self) -> None:
        for hid, walker in self.participants.items():
            if hid in self.humans_done:
                continue
            finished = self.routes.done(hid) if self.scenario.kind == "hallway" else not self.gems.remaining("human")
            if finished:
                self.humans_done.add(hid)
                self._emit("scenario", [{"type": "task_done", "by": hid}])


def run_trial(scenario: Scenario, seed: int = 0, toggles: Toggles | None = None) -> TrialResult:
    return Trial(scenario, seed, toggles).run()
