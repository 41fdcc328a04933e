"""One trial of a scenario in one process, no DDS: batch mode.

The very components the ROS nodes wrap (simulator, velocity mux, planner, controller, AR cues and
the trial director with its mission executive, rules and simulated participants) run in the
in-process loop (`haven_sim.runtime.loop`) at the rates their configs give, built from the same
parameter source as the nodes. The trial's messages are collected as a recording holds them (with
their stamps), so the metrics come out of the same code for both modes.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field, fields, replace
from typing import Any

from haven_scenarios.record.metric_kind import compute
from haven_scenarios.record.timeline import RECORDED, Recording
from haven_scenarios.run.suite import SuiteConfig
from haven_scenarios.study.conditions import condition_name, parse_condition
from haven_scenarios.study.director import TrialDirector
from haven_scenarios.study.rules import EndReason
from haven_scenarios.study.scenario import Scenario
from haven_sim.common import contain
from haven_sim.common.component import Component
from haven_sim.nav.controller import ControllerComponent
from haven_sim.nav.mux import MuxComponent
from haven_sim.nav.planning import PlannerComponent, world_lanes
from haven_sim.robots.fields import with_robot
from haven_sim.runtime.loop import DelayFn, InProcessLoop, Observer
from haven_sim.sim.simulator import SimulatorComponent
from haven_viz.cues import CueParams, CueToggles
from haven_viz.viz import VizComponent

GRACE_S = 60.0  # the loop stops this long after the scenario's timeout even if nothing ended it


def scenario_suite(scenario: Scenario, seed: int, toggles: CueToggles, suite: SuiteConfig | None = None) -> SuiteConfig:
    """The suite configured for one trial: what the scenario and the run fix on top of the
    parameter file (robot, world, battery size, seeds, condition) — what `haven run` passes as -p."""
    s = with_robot(suite or SuiteConfig(), scenario.robot, scenario.robot_model)
    battery = replace(s.sim.sim.battery, pack_m=scenario.battery.capacity_m)
    sim = replace(s.sim, world=scenario.world_path, sim=replace(s.sim.sim, battery=battery, seed=seed))
    director = replace(s.scenario.director, scenario=scenario.source or scenario.name, seed=seed)
    # The scenario's cue parameters, except where the run's parameter file set one.
    default, run = CueParams(), s.viz.cues
    cues = replace(
        scenario.cues,
        **{f.name: getattr(run, f.name) for f in fields(CueParams) if getattr(run, f.name) != getattr(default, f.name)},
    )
    viz = replace(s.viz, world=scenario.world_path, toggles=toggles, cues=cues)
    return replace(
        s,
        sim=sim,
        planner=replace(s.planner, world=scenario.world_path),
        viz=viz,
        scenario=replace(s.scenario, director=director),
    )


@dataclass
class TrialResult:
    scenario: str
    seed: int
    condition: str
    end_reason: str
    metrics: dict[str, Any]
    recording: Recording = field(repr=False)


class Trial:
    """The trial's components in the in-process loop. `watch`: more observers of more topics (a
    stepped simulation's view of the AR markers), beside the recording."""

    def __init__(
        self,
        scenario: Scenario,
        seed: int = 0,
        toggles: CueToggles | None = None,
        suite: SuiteConfig | None = None,
        delay: DelayFn | None = None,
        watch: tuple[Sequence[Observer], Sequence[str]] = ((), ()),
    ) -> None:
        self.scenario = scenario
        self.seed = seed
        self.toggles = toggles if toggles is not None else parse_condition(scenario.condition)
        c = scenario_suite(scenario, seed, self.toggles, suite)
        self.sim = SimulatorComponent(scenario.world, c.sim)
        self.director = TrialDirector(scenario, seed, c.scenario.director.rate_hz)
        self.viz = VizComponent(c.viz, scenario.world)
        components: list[Component] = [
            MuxComponent(c.mux),
            PlannerComponent(c.planner, world_lanes(scenario.world)),
            ControllerComponent(c.controller),
            self.viz,
            self.director,
        ]
        self.recording = Recording()
        observers, watched = watch
        self.loop = InProcessLoop(self.sim, components, [self.recording.add, *observers], {*RECORDED, *watched}, delay)
        self.limit = math.ceil((scenario.timeout_s + GRACE_S) / self.sim.config.sim.step_s)  # steps at most

    def run(self) -> TrialResult:
        self.loop.run_until(lambda: self.director.ended is not None, self.limit - self.sim.sim.steps)
        return self.result()

    def result(self) -> TrialResult:
        """The metrics of the trial so far (end reason `interrupted` while it has not ended)."""
        reason = self.director.ended or EndReason.INTERRUPTED
        metrics = compute(self.recording, self.scenario.name, reason, self.scenario.world, robot=self.scenario.robot)
        metrics.update(seed=self.seed, condition=condition_name(self.toggles), robot=self.scenario.robot.name)
        return TrialResult(self.scenario.name, self.seed, condition_name(self.toggles), reason, metrics, self.recording)


def run_trial(
    scenario: Scenario, seed: int = 0, toggles: CueToggles | None = None, suite: SuiteConfig | None = None
) -> TrialResult:
    """The trial with the suite's plugin deadlines (common/contain.py): a plugin that fails ends it not valid."""
    with contain.use(suite.deadlines if suite is not None else None):
        return Trial(scenario, seed, toggles, suite).run()
