"""A batch trial stepped by hand, to debug a participant model, a cue or a mission in: in the spirit
of IR-SIM's `env.step()` / `env.render()`, over the very components `haven batch` runs (the same
loop, rates and results; `run()` to its end gives the batch row's metrics).

    sim = Simulation("hallway", seed=3)
    while not sim.state().ended and sim.state().time < 20.0:
        sim.step(50)                      # one second of the 50 Hz physics
    sim.render("now.png")                 # the world, the tracks so far and the AR cues shown now
    print(sim.result().metrics["min_human_centre_distance_m"])
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from haven_scenarios.run.grid import for_trial
from haven_scenarios.run.suite import TRIAL_SETS, load_suite_config
from haven_scenarios.run.trial import Trial, TrialResult
from haven_scenarios.study.conditions import check_fit, check_seed, parse_condition
from haven_scenarios.study.scenario import Scenario, load_scenario
from haven_sim.common import topics
from haven_sim.common.component import Message
from haven_sim.common.geometry import Pose2D
from haven_viz.markers import MarkerSpec
from haven_viz.render import PERSON_TRAILS, render_scene


@dataclass(frozen=True)
class SimState:
    """The trial at one instant: sim time (s), the robot's and the people's poses (frame `map`),
    the battery's level (0..1), and why the trial ended (None while it runs)."""

    time: float
    robot: Pose2D
    humans: dict[str, Pose2D]
    battery: float
    ended: str | None


class Simulation:
    """One trial of `scenario` (a shipped name, a scenario YAML or a Scenario), stepped by hand:
    `step(n)` advances n physics steps (`step_s` each), `state()` says where everyone is, `render()`
    draws it, `result()` scores it so far. `condition`: the cues shown (None: the scenario's);
    `params_file`: a parameter file as `haven batch --params-file` takes; `robot` and `person` as
    `api.batch_trial` takes them."""

    def __init__(
        self,
        scenario: str | Path | Scenario = "hallway",
        seed: int = 0,
        condition: Sequence[str] | None = None,
        world: str | None = None,
        params_file: str | None = None,
        robot: str | None = None,
        person: tuple[int, int] | None = None,
    ) -> None:
        s = for_trial(scenario if isinstance(scenario, Scenario) else load_scenario(scenario, world), robot, person)
        self.markers: dict[tuple[str, int], MarkerSpec] = {}  # the AR markers shown now
        toggles = parse_condition(list(condition if condition is not None else s.condition))
        check_fit(toggles, s.robot)
        self.trial = Trial(
            s,
            check_seed(seed),
            toggles,
            load_suite_config(params_file, TRIAL_SETS),
            watch=([self._marker], [topics.AR_MARKERS]),
        )
        self.step_s = self.trial.sim.config.sim.step_s

    def _marker(self, m: Message) -> None:
        if m.topic == topics.AR_MARKERS:
            for key in m.data.delete:
                self.markers.pop(key, None)
            self.markers.update({spec.key: spec for spec in m.data.upsert})

    def step(self, steps: int = 1) -> SimState:
        """Advance `steps` physics steps (fewer once the trial has ended or run past its timeout);
        ValueError (one line) for a count that is not a whole number of at least 0."""
        if isinstance(steps, bool) or not isinstance(steps, int) or steps < 0:
            raise ValueError(f"step: steps must be a whole number of at least 0, got {steps!r}")
        for _ in range(steps):
            if self.trial.director.ended is not None or self.trial.sim.sim.steps >= self.trial.limit:
                break
            self.trial.loop.step()
        return self.state()

    def state(self) -> SimState:
        sim = self.trial.sim.sim
        ended = self.trial.director.ended
        return SimState(
            sim.time,
            sim.robot_pose(),
            sim.human_poses(),
            sim.battery_reading().level,
            ended.value if ended is not None else None,
        )

    def run(self) -> TrialResult:
        """On to the trial's end (as `haven batch` runs it), then its result."""
        return self.trial.run()

    def result(self) -> TrialResult:
        """The metrics of the trial so far (end reason `interrupted` while it has not ended)."""
        return self.trial.result()

    def render(self, out: str | Path) -> Path:
        """A top-down PNG: the world, everyone's track so far and the AR cues shown now."""
        rec, trails = self.trial.recording, {}
        if rec.odom:
            trails["robot"] = (np.array([(s.pose.x, s.pose.y) for _, s in rec.odom]), "black")
        for i, hid in enumerate(sorted({h for _, poses in rec.humans for h in poses})):
            xy = np.array([(poses[hid].x, poses[hid].y) for _, poses in rec.humans if hid in poses])
            trails[hid] = (xy, PERSON_TRAILS[i % len(PERSON_TRAILS)])
        world = self.trial.scenario.world
        title = f"{self.trial.scenario.name}, seed {self.trial.seed}, t = {self.state().time:.1f} s"
        return render_scene(world, list(self.markers.values()), out, title=title, trails=trails)
