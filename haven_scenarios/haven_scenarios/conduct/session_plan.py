"""What one recorded trial runs: `SessionPlan` (the scenario, condition, seed, participant,
parameters, clock and who is in the suite) and the node processes it starts; `haven run` and
`haven rerun` both make one."""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from haven_scenarios.conduct import after_trial
from haven_scenarios.conduct.suite_processes import suite_specs
from haven_scenarios.record.outsiders import Declared, open_topics, suite_nodes
from haven_scenarios.record.session import PARAMS_FILE, ROBOT_FILE, SCENARIO_FILE, WORLD_FILE
from haven_scenarios.run.suite import SuiteConfig
from haven_scenarios.run.supervisor import ProcessSpec, node_argv
from haven_scenarios.run.trial import scenario_suite
from haven_scenarios.study.director import any_reader
from haven_scenarios.study.presence import DEFAULT_RECONNECT_TIMEOUT_S, OnDisconnect
from haven_scenarios.study.scenario import Scenario
from haven_scenarios.web.access import TOKEN_ENV, new_token
from haven_sim.common import nodes, topics
from haven_sim.runtime.lockstep import UNCAPPED_RTF, LockstepParams
from haven_viz.cues import CueToggles

SESSION_PARAMS_HEADER = """Every node's parameters as run in this session: each node was started with this file, in this
folder (file names are relative to it, so the folder can move). `haven rerun` on this folder runs
the session again with them. Parameters are documented in haven_sim/config/haven.yaml."""


@dataclass(frozen=True)
class SessionPlan:
    """One recorded trial to run: what `haven run` and `haven rerun` both start."""

    scenario: Scenario
    toggles: CueToggles
    seed: int
    participant: str
    base: SuiteConfig  # the parameter file's configuration (defaults where it is silent)
    rtf: float | None  # None: 1x with a person, uncapped on the lockstep clock
    free_running: bool = False  # simulated participants on the free-running clock
    extra: dict[str, Any] = field(default_factory=dict)  # more for session.json
    web: WebOptions | None = None  # the pages, with `haven run --web`
    without: tuple[str, ...] = ()  # our nodes left out: the user runs their own in their place
    allow: tuple[str, ...] = ()  # topics outside nodes may publish on during the trial (record/outsiders.py)
    processes: str = "one"  # the suite's nodes in one process, or "separate" (nodes.PROCESS_LAYOUTS)

    @property
    def lockstep(self) -> bool:
        """Simulated participants run on the lockstep clock; a person plays on the free-running
        one, and so does a suite with a node of the user's (it does not take the clock's ticks)."""
        return not self.free_running and not self.without and not any(h.teleoperated for h in self.scenario.humans)

    @property
    def declared(self) -> Declared:
        """The nodes this run starts and the topics it opens to outside publishers."""
        without = [nodes.BY_KEY[n].name for n in self.without]
        teleop = [h.id for h in self.scenario.humans if h.teleoperated]
        return Declared(
            frozenset(suite_nodes(without, self.web is not None)),
            open_topics(without, teleop, self.allow),
            self.lockstep,
        )

    @property
    def real_time_factor(self) -> float:
        return self.rtf if self.rtf is not None else (UNCAPPED_RTF if self.lockstep else 1.0)

    def config(self, folder: Path) -> SuiteConfig:
        """Every node's parameters as run in a session folder (its own copies of the world, the
        scenario and the robot, named relative to it): the file's, then what the scenario and the run fix."""
        # (robot.yaml: the session's copy)
        model = ROBOT_FILE if self.scenario.robot.source_file else self.scenario.robot_model
        own = replace(self.scenario, world_path=WORLD_FILE, source=SCENARIO_FILE, robot_model=model)
        c = scenario_suite(own, self.seed, self.toggles, self.base)
        # (a recorded trial is not reset from outside)
        sim = replace(c.sim, real_time_factor=self.real_time_factor, reset_allowed=False)
        if self.web is not None:  # a first-person camera moves with every physics step, not at 20 Hz
            sim = replace(sim, humans_rate_hz=max(sim.humans_rate_hz, 1.0 / sim.sim.step_s))
        if self.lockstep:
            # The viz is waited for like any participant: the scenario reads what it shows (/haven/cue_state).
            participants = tuple(n.name for n in nodes.LOCKSTEP_PARTICIPANTS)
            sim = replace(
                sim, lockstep_participants=participants, lockstep_observers=(), lockstep_wait_for=(nodes.RECORDER.name,)
            )
        else:
            sim = replace(sim, lockstep_participants=(), lockstep_observers=(), lockstep_wait_for=())
        # The trial starts once the planner listens (somebody's own: whichever node reads /goal_pose).
        planner = nodes.PLANNER.name if nodes.PLANNER.key not in self.without else any_reader(topics.GOAL)
        scenario = replace(c.scenario, wait_for=(planner, nodes.RECORDER.name), hold_start=self.web is not None)
        return replace(c, sim=sim, scenario=scenario, lockstep=LockstepParams(self.lockstep, self.allow))


def specs_of(folder: Path, plan: SessionPlan) -> list[ProcessSpec]:
    """The recorder and the suite's nodes (in one process unless `plan.processes` says separate), run
    in the session folder, each reading its params.yaml (node sections there win over `-p`, so the
    file holds everything); on the command line only which clock they read."""
    # On the lockstep clock the ticks carry the time: the participants need no /clock.
    stepped: dict[str, object] = {"use_sim_time": False} if plan.lockstep else {}
    own = {n.key: stepped for n in nodes.COMPONENTS if n is not nodes.SIM} | {nodes.SCENARIO.key: stepped}
    members = (*nodes.COMPONENTS, nodes.SCENARIO)
    suite = suite_specs(own, PARAMS_FILE, plan.without, plan.processes, members)
    declared = plan.declared
    recorder_params = {
        "use_sim_time": True,
        "session_dir": ".",
        "suite_nodes": sorted(declared.nodes),
        "open_topics": list(declared.open),
        "suite_lockstep": plan.lockstep,
    }
    specs = [ProcessSpec(nodes.RECORDER.key, node_argv(nodes.RECORDER.module, recorder_params)), *suite]
    return [replace(spec, cwd=str(folder.resolve())) for spec in specs]


@dataclass(frozen=True)
class WebOptions:
    host: str
    port: int
    researcher_start: bool = False
    map_inset: bool = True
    secret: str = field(default_factory=new_token)  # each page role's token derives from it
    questionnaires: tuple[str | dict[str, Any], ...] = ()  # asked after the trial: built-in names, Likert mappings
    tls: tuple[str, str] | None = None  # HTTPS: the certificate's and its key's absolute paths (checked: web/tls.py)
    # on_disconnect, reconnect_timeout_s
    dropout: tuple[str, float] = (OnDisconnect.KEEP.value, DEFAULT_RECONNECT_TIMEOUT_S)
    next_url: str = ""  # where a participant's page goes when the trial and its questionnaires are over


def web_spec(plan: SessionPlan, web: WebOptions, folder: Path) -> ProcessSpec:
    params = {
        "use_sim_time": True,
        "scenario": SCENARIO_FILE,
        "humans": "[" + ",".join(h.id for h in plan.scenario.humans if h.teleoperated) + "]",
        "host": web.host,
        "port": web.port,
        "participant": plan.participant,
        "session": folder.name,
        "researcher_start": web.researcher_start,
        "map_inset": web.map_inset,
        **({"questionnaires": after_trial.as_parameter(web.questionnaires)} if web.questionnaires else {}),
        **({"tls_cert": web.tls[0], "tls_key": web.tls[1]} if web.tls else {}),
        "on_disconnect": web.dropout[0],
        "reconnect_timeout_s": web.dropout[1],
        **({"next_url": web.next_url} if web.next_url else {}),
    }
    return ProcessSpec(
        nodes.WEB.key, node_argv(nodes.WEB.module, params), env={TOKEN_ENV: web.secret}, cwd=str(folder.resolve())
    )
