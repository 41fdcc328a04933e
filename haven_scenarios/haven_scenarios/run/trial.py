"""One trial of a scenario in one process, no DDS: batch mode.

The same core objects the ROS nodes wrap (simulation, navigator, path follower, AR cues, and the
scenario core: mission executive, rules, simulated participants) are stepped in sim time as fast as
the CPU allows, at the rates the nodes use: physics 50 Hz, controller 25 Hz, scenario / cues /
logging 10 Hz, planner checks 5 Hz.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from haven_scenarios.study.director import CoreOutput, ScenarioCore
from haven_scenarios.record.metrics import TrialLog, compute
from haven_scenarios.study.scenario import Scenario
from haven_sim.sim.battery import BatteryParams
from haven_sim.nav.follower import PathFollower, Status
from haven_sim.common.geometry import Pose2D
from haven_sim.nav.navigator import Navigator, NavOutput
from haven_sim.sim.simulation import SimConfig, Simulation
from haven_viz.cues import CUES, ArCues, Toggles


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


def cue_state(markers: Sequence[Any]) -> tuple[bool, int]:
    """(thought bubble shown, turn signal: +1 left, -1 right, 0 off) from the cue markers."""
    bubble = any(m.ns == "thought_bubble" for m in markers)
    signal = 0
    for m in markers:
        if m.ns == "turn_signals":
            signal = 1 if m.id == 0 else -1
    return bubble, signal


@dataclass
class TrialResult:
    scenario: str
    seed: int
    condition: str
    end_reason: str
    metrics: dict[str, Any]
    log: TrialLog = field(repr=False)


class Trial:
    def __init__(self, scenario: Scenario, seed: int = 0, toggles: Toggles | None = None) -> None:
        self.scenario = scenario
        self.seed = seed
        self.toggles = toggles or Toggles()
        base = scenario.world.charging_base
        battery = BatteryParams(capacity_m=scenario.battery.capacity_m, base_radius_m=base.radius if base else 0.5)
        self.sim = Simulation(scenario.world, SimConfig(battery=battery, seed=seed))
        grid = self.sim.occupancy()
        self.nav = Navigator(grid)
        self.follower = PathFollower()
        self.cues = ArCues()
        self.core = ScenarioCore(scenario, grid, seed, self.nav.planner)
        self.log = TrialLog()
        self.thought = ""
        self.path: list[Pose2D] = []
        self.goal: Pose2D | None = None

    def _record(self, events: Sequence[dict[str, Any]], source: str | None = None) -> None:
        for e in events:
            event = {"stamp": round(self.sim.time, 4), **({"source": source} if source else {}), **e}
            self.log.events.append(event)
            self._apply(self.core.on_event(event, self.sim.robot_pose()))

    def _apply_nav(self, out: NavOutput) -> None:
        if out.path is not None:
            self.path = out.path
            self.follower.set_path(out.path)
            self.cues.set_path(out.path)
        if out.waiting is not None:
            self.follower.waiting = out.waiting
        self._record(out.events, "planner")

    def _apply(self, out: CoreOutput) -> None:
        for hid, cmd in out.human_cmds.items():
            self.sim.command_human(hid, cmd)
        if out.thought is not None:
            self.thought = out.thought
        self._record(out.events)
        for oid in out.clear_obstructions:
            self.sim.remove_obstruction(oid)
            self.nav.set_map(self.sim.occupancy())
            self.core.set_map(self.sim.occupancy())
            self._record([e.as_dict() for e in self.sim.pop_events()])
        if out.goal is not None:
            self.goal = out.goal
            self._apply_nav(self.nav.set_goal(self.sim.robot_pose(), out.goal))

    def run(self) -> TrialResult:
        sim, core = self.sim, self.core
        self._apply(core.start(sim.time, sim.robot_pose(), sim.battery.level))
        k = 0
        while core.ended is None:
            robot = sim.robot_pose()
            if k % 2 == 0:
                was = self.follower.status
                sim.command_robot(self.follower.command(robot))
                if self.follower.status is Status.ARRIVED and was is not Status.ARRIVED and self.goal is not None:
                    self._record([{"type": "goal_reached", "goal": [round(self.goal.x, 3), round(self.goal.y, 3)]}], "controller")
            if k % 5 == 0:
                self._record([e.as_dict() for e in sim.pop_events()])
                humans = sim.human_poses()
                self._apply(core.tick(sim.time, robot, humans, sim.battery.level, self.path))
                markers = self.cues.markers(robot, [(h.x, h.y) for h in humans.values()], sim.battery.level, self.thought, self.toggles)
                bubble, signal = cue_state(markers)
                tw = sim.robot_twist()
                self.log.sample(sim.time, (robot.x, robot.y, robot.yaw, tw.wz), {h: (p.x, p.y) for h, p in humans.items()}, sim.battery.level, bubble, signal)
            if k % 10 == 0:
                self._apply_nav(self.nav.update(robot, [(p.x, p.y) for p in sim.human_poses().values()]))
            sim.step()
            k += 1
        reason = core.ended
        metrics = compute(self.log, self.scenario.name, reason)
        metrics.update(seed=self.seed, condition=condition_name(self.toggles))
        return TrialResult(self.scenario.name, self.seed, condition_name(self.toggles), reason, metrics, self.log)


def run_trial(scenario: Scenario, seed: int = 0, toggles: Toggles | None = None) -> TrialResult:
    return Trial(scenario, seed, toggles).run()
