"""HAVEN from a Python script or a notebook, in the spirit of nav2_simple_commander: the main jobs
as calls that block until they are done and return typed results. The `haven` command is a thin
layer over the same functions. For example::

    from haven_scenarios import api

    r = api.batch_trial("hallway", seed=3, condition=["turn_signals"])     # no ROS, in this process
    print(r.end_reason, r.metrics["min_human_centre_distance_m"])

    s = api.recorded_trial("hallway", participant="p01", seed=3)          # the whole node suite, recorded
    print(s.folder, s.outcome, s.valid, s.metrics["human_contacts"])

    rows = api.sweep(["hallway"], seeds=range(10), grid={"condition": ["all", "none"]})

    sim = api.Simulation("hallway", seed=3)                                # stepped by hand, to debug a model
    sim.step(500); print(sim.state().humans["h1"]); sim.render("now.png")

    trials = api.study_plan("haven_paper")                                 # a whole study
    api.run_participant("haven_paper", "p01", batch=True)
    api.study_status("haven_paper"); api.study_report("haven_paper")

    server = api.serve_study("haven_paper", host="0.0.0.0", capacity=2)   # online: `haven serve`
    print(server.join_url); ...; server.stop()

Bad input raises `TrialError` (or `ValueError`) with one line naming what is wrong. Recorded trials
and studies start processes and take ROS domains as `haven run` does; call them from the main
thread (a stop signal, Ctrl-C, ends the trial cleanly).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from haven_scenarios.conduct.recorded_trial import (
    RecordedTrial,
    RosOptions,
    TrialError,
    TrialRequest,
    WebRequest,
    plan_trial,
    record_trial,
)
from haven_scenarios.conduct.study_run import StudyRun, run_participant as _run_participant
from haven_scenarios.record.progress import TrialProgress, progress
from haven_scenarios.record.study_report import Report, write_report
from haven_scenarios.run.domains import DomainRange, parse_domains
from haven_scenarios.run.grid import TrialSpec, for_trial, parse_grid, plan_sweep
from haven_scenarios.run.stepped import SimState, Simulation
from haven_scenarios.run.suite import TRIAL_SETS, load_suite_config
from haven_scenarios.run.sweep import run_rows
from haven_scenarios.run.trial import TrialResult, run_trial
from haven_scenarios.study.conditions import check_fit, check_seed, parse_condition
from haven_scenarios.study.names import study_dir
from haven_scenarios.study.protocol import load_study
from haven_scenarios.study.scenario import load_scenario
from haven_scenarios.study.schedule import PlannedTrial, participant_schedule, schedule

if TYPE_CHECKING:
    from haven_scenarios.web.study_server import StudyServer

__all__ = [
    "RecordedTrial",
    "Report",
    "SimState",
    "Simulation",
    "StudyRun",
    "TrialError",
    "TrialRequest",
    "TrialResult",
    "WebRequest",
    "batch_trial",
    "recorded_trial",
    "run_participant",
    "study_plan",
    "study_report",
    "study_status",
    "sweep",
]


def batch_trial(
    scenario: str = "hallway",
    seed: int = 0,
    condition: str | Sequence[str] | None = None,
    world: str | None = None,
    params_file: str | None = None,
    robot: str | None = None,
    person: tuple[int, int] | None = None,
) -> TrialResult:
    """One trial without ROS, in this process (the components the nodes run, at their rates):
    `scenario` a shipped name or a YAML; `condition` the cues shown (None: the scenario's); `robot`
    a robot's name or a robot file (None: the scenario's); `person` the simulated people as one
    study participant, (person seed, position in the session)."""
    checked = check_seed(seed)
    s = for_trial(load_scenario(scenario, world), robot, person)
    toggles = parse_condition(list(_names(condition) or s.condition))
    check_fit(toggles, s.robot)
    return run_trial(s, checked, toggles, load_suite_config(params_file, TRIAL_SETS))


def _names(value: str | Iterable[str] | None) -> tuple[str, ...] | None:
    """One name or several: "turn_signals" is one cue, not twelve letters."""
    return None if value is None else (value,) if isinstance(value, str) else tuple(value)


def recorded_trial(
    scenario: str = "hallway",
    *,
    sessions: str | Path = "sessions",
    domain_id: int | None = None,
    domains: str | None = None,
    network: bool = False,
    quiet: bool = False,
    **options: Any,
) -> RecordedTrial:
    """One recorded trial with the whole node suite, into a new session folder under `sessions`;
    blocks until its session is complete. `options` are TrialRequest's fields (participant,
    condition, seed, world, robot, person, params_file, teleop, rtf, free_running, without, allow,
    web, questionnaires). `domains`: "A-B", the only ROS domains it may take (as `--domains`; None:
    $HAVEN_DOMAINS, if set). `quiet`: no progress lines."""
    known = [f for f in TrialRequest.__dataclass_fields__ if f not in ("scenario", "extra")]
    unknown = sorted(set(options) - set(known))
    if unknown:
        raise TrialError(f"recorded_trial: unknown option {unknown[0]!r} (options: {', '.join(known)})")
    for key in ("condition", "teleop", "without", "allow", "questionnaires"):
        if key in options:
            options[key] = _names(options[key])
    plan = plan_trial(TrialRequest(scenario, **options))
    return record_trial(
        plan,
        Path(sessions),
        RosOptions(domain_id, network, _domains(domains)),
        say=(lambda _: None) if quiet else print,
    )


def _domains(text: str | None) -> DomainRange | None:
    """`domains` as the API takes it ("30-39"), checked as `--domains` is; TrialError (one line) if it is not a
    range."""
    try:
        return parse_domains(text) if text is not None else None
    except ValueError as e:
        raise TrialError(str(e).replace("--domains", "domains", 1)) from None


def sweep(
    scenarios: str | Sequence[str],
    seeds: Iterable[int] = range(10),
    grid: Mapping[str, Any] | None = None,
    workers: int = 1,
    cluster: str | None = None,
    params_file: str | None = None,
    robot: str | None = None,
) -> list[dict[str, Any]]:
    """Batch trials over scenarios x the grid's axes (condition, model, speed_mps, robot, a
    participant parameter) x seeds, as `haven batch` runs them; one row per trial, in trial order.
    `robot`: every trial's robot (a grid's `robot` axis gives several)."""
    grid = dict(grid or {})
    if robot is not None:
        if "robot" in grid:
            raise ValueError("sweep: give the robot once: robot= or a grid's robot axis")
        grid["robot"] = robot
    axes = parse_grid([f"{k}={','.join(str(v) for v in _names(values) or ())}" for k, values in grid.items()])
    checked = tuple(check_seed(s, "seeds") for s in seeds)
    specs: list[TrialSpec] = plan_sweep(
        [load_scenario(s) for s in dict.fromkeys(_names(scenarios) or ())], axes, checked
    )
    rows = list(run_rows(specs, load_suite_config(params_file, TRIAL_SETS), workers, cluster))
    return sorted(rows, key=lambda r: r["trial"])


def study_plan(study: str, participant: str | None = None) -> list[PlannedTrial]:
    """The study's schedule (one participant's trials, or everyone's), as `haven study plan` prints it."""
    s = load_study(study)
    if participant is None:
        return schedule(s)
    if participant not in s.participants:
        raise ValueError(f"study_plan: {participant!r} is not a participant of study {s.name}")
    return participant_schedule(s, participant)


def run_participant(study: str, participant: str, **options: Any) -> int:
    """Run the participant's trials not done yet, in order (StudyRun's fields as options: batch,
    web, teleop, dir, params_file, domain_id, ...); 0 when all are done, 1 when a trial did not
    finish (the same call runs it again), 130 when stopped. TrialError (one line) when refused."""
    known = [f for f in StudyRun.__dataclass_fields__ if f not in ("study", "participant")]
    unknown = sorted(set(options) - set(known))
    if unknown:
        raise TrialError(f"run_participant: unknown option {unknown[0]!r} (options: {', '.join(known)})")
    if "teleop" in options:
        options["teleop"] = _names(options["teleop"])
    if options.get("dir") is not None:
        options["dir"] = Path(options["dir"])
    if isinstance(options.get("domains"), str):
        options["domains"] = _domains(options["domains"])
    return _run_participant(StudyRun(study, participant, **options))


def study_status(study: str, dir: str | Path | None = None) -> list[TrialProgress]:
    """Every trial of the study with its status (done, failed, to do) and its attempts."""
    s = load_study(study)
    return progress(study_dir(Path(dir) if dir is not None else None, s), schedule(s))


def study_report(study: str, dir: str | Path | None = None, out: str | Path | None = None) -> Report:
    """The study's tables and summary picture (`haven study report`): what was written where."""
    s = load_study(study)
    return write_report(s, study_dir(Path(dir) if dir is not None else None, s), Path(out) if out is not None else None)


SERVE_OPTIONS = (
    "dir",
    "host",
    "port",
    "capacity",
    "trial_ports",
    "id_param",
    "on_disconnect",
    "reconnect_timeout",
    "tls_cert",
    "tls_key",
    "params_file",
    "network",
    "domains",
)


def serve_study(study: str, **options: Any) -> StudyServer:
    """`haven serve` from a script: the study's server for remote participants, started. Its
    `join_url` is the panel's link, `console_url` the researcher's list, `sessions()` every
    session now; `stop()` ends it (each participant's trial stops cleanly, to run again). Options:
    SERVE_OPTIONS, as `haven serve`'s. ValueError (one line) for a bad study or option."""
    from haven_scenarios.conduct.online_study import open_server

    unknown = sorted(set(options) - set(SERVE_OPTIONS))
    if unknown:
        raise ValueError(f"serve_study: unknown option {unknown[0]!r} (options: {', '.join(SERVE_OPTIONS)})")
    if options.get("dir") is not None:
        options["dir"] = Path(options["dir"])
    server = open_server(study, **options)
    server.start()
    return server
