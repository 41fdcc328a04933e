"""One recorded trial with the whole node suite, into a new session folder: what `haven run`,
`haven rerun`, `haven study run` and the Python API (`haven_scenarios.api`) call.

The suite takes its ROS domain (run/domains.py), the nodes run as supervised processes, the
trial ends when the scenario node exits (or a node dies, or the time limit passes), and the result
comes back typed: the session folder, how the run ended, the metrics and whether the recording is
valid. session.json gets the run's outcome however it ends.
"""

from __future__ import annotations

import contextlib
import math
import os
import select
import shutil
import signal
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from haven_scenarios.conduct import after_trial, outcomes
from haven_scenarios.conduct.after_trial import Asked
from haven_scenarios.conduct.outcomes import (
    NO_OUTCOME,
    Ended,
    exit_text,
    outcome,
    repair_bag,
    repair_record,
    write_outcome,
)
from haven_scenarios.conduct.session_plan import SESSION_PARAMS_HEADER, SessionPlan, WebOptions, specs_of, web_spec
from haven_scenarios.conduct.suite_processes import claim_ros_domain, port_free
from haven_scenarios.record import recorder_stop
from haven_scenarios.record.bag import not_recorded
from haven_scenarios.record.outsiders import allowable
from haven_scenarios.record.session import (
    END_FD_ENV,
    EVENTS_FILE,
    METRICS_FILE,
    PARAMS_FILE,
    SCENARIO_FILE,
    SESSION_FILE,
    WORLD_FILE,
    analyse,
    new_session_dir,
    trajectory_picture,
    trial_record,
    trial_wall_clock,
    write_inputs,
    write_json,
)
from haven_scenarios.run.domains import DomainBusy, DomainRange
from haven_scenarios.run.grid import for_trial
from haven_scenarios.run.suite import TRIAL_SETS, load_suite_config, render
from haven_scenarios.run.supervisor import ProcessSpec, Supervisor, ros_environment
from haven_scenarios.study.conditions import check_fit, check_seed, condition_name, parse_condition
from haven_scenarios.study.names import check_name
from haven_scenarios.study.presence import DEFAULT_RECONNECT_TIMEOUT_S, OnDisconnect
from haven_scenarios.study.rules import EndReason
from haven_scenarios.study.scenario import TELEOP, ScenarioError, load_scenario
from haven_scenarios.web.tls import tls_files
from haven_sim.common import contain, nodes
from haven_sim.common.events import EventKind
from haven_sim.common.params import ParamsError
from haven_sim.runtime.lockstep import UNCAPPED_RTF
from haven_sim.runtime.process import STOP_SIGNALS

Say = Callable[[str], None]


def say_now(line: str) -> None:
    """A progress line, out at once (a pipe would hold it back until the trial ends)."""
    print(line, flush=True)


class TrialError(Exception):
    """The trial could not run or be completed, in one line; `code`: `haven run`'s exit code for it
    (2: nothing started, the input or the domain was refused; 1: the session could not be
    completed, what was written stays)."""

    def __init__(self, message: str, code: int = 2) -> None:
        super().__init__(message)
        self.code = code


@dataclass(frozen=True)
class RosOptions:
    """Where the suite runs: `domain_id` None takes the inherited domain if free, else a free one
    (inside `domains` where given); `network` lets DDS discovery go beyond this machine."""

    domain_id: int | None = None
    network: bool = False
    domains: DomainRange | None = None  # the lab's range (None: $HAVEN_DOMAINS, if set): never a domain outside it


@dataclass(frozen=True)
class RecordedTrial:
    """What a recorded trial left: its session folder and how it ended."""

    folder: Path
    outcome: str  # session.json's `outcome`, in words
    metrics: dict[str, Any] = field(repr=False)  # metrics.json
    domain_id: int
    wall_s: float
    died: str | None = None  # the node that ended the trial by dying ("planner exited with code 1")
    timed_out: bool = False  # cut at the wall-clock limit
    stopped: bool = False  # a stop signal (Ctrl-C) ended it

    @property
    def end_reason(self) -> str:
        return str(self.metrics["end_reason"])

    @property
    def valid(self) -> bool:
        return bool(self.metrics["valid"])

    @property
    def invalid_reasons(self) -> list[str]:
        return list(self.metrics.get("invalid_reasons", []))

    @property
    def finished(self) -> bool:
        """The trial ran to its end (completed, timeout, contact, battery, stopped by the researcher)."""
        return self.died is None and not self.timed_out and self.end_reason != EndReason.INTERRUPTED


@dataclass(frozen=True)
class WebRequest:
    """The trial in the browser: where the pages are served and what they ask after it."""

    host: str = "127.0.0.1"
    port: int = 8088
    researcher_start: bool = False  # the trial starts on the console's Start, not when the participants are ready
    map_inset: bool = True
    tls_cert: str = ""  # with tls_key: HTTPS, a certificate and its key in PEM (`haven cert` makes them)
    tls_key: str = ""
    on_disconnect: str = OnDisconnect.KEEP.value  # a participant's drop-out during the trial: keep | pause | abort
    reconnect_timeout_s: float = DEFAULT_RECONNECT_TIMEOUT_S  # with pause: abort after this long away
    next_url: str = ""  # the participant's browser goes here when they are done with the page (`haven serve`)


@dataclass(frozen=True)
class TrialRequest:
    """One recorded trial as a user asks for it (`haven run`'s options, the API's arguments)."""

    scenario: str = "hallway"  # a shipped scenario's name or a scenario YAML
    participant: str | None = None  # default: sim, or the teleoperated humans' ids (h1-h2)
    condition: tuple[str, ...] | None = None  # the cues shown (all, none, or names); None: the scenario's
    seed: int = 0
    world: str | None = None  # play the scenario in this world
    params_file: str | None = None
    teleop: tuple[str, ...] | None = None  # these humans are driven by a person (() for all of them)
    rtf: float | None = None  # None: 1x with a person, as fast as the machine allows on the lockstep clock
    free_running: bool = False
    without: tuple[str, ...] = ()  # our nodes left out (short names: mux, planner, controller, viz)
    allow: tuple[str, ...] = ()  # topics outside nodes may publish on (record/outsiders.py)
    web: WebRequest | None = None
    questionnaires: tuple[str, ...] = ()  # in the pages after the trial: built-in names or Likert YAML files
    extra: dict[str, Any] = field(default_factory=dict)  # more for session.json
    # simulated people as a study participant: (person seed, position in the session)
    person: tuple[int, int] | None = None
    robot: str | None = None  # a robot's name or a robot file (None: the scenario's robot: model, else turtlebot2)
    processes: str = "one"  # the suite's nodes in one process, or "separate" (one each: to debug a node)


def plan_trial(request: TrialRequest) -> SessionPlan:
    """The session plan for a request, every input checked before anything starts; TrialError in
    one line naming what is wrong."""
    r = request
    try:
        seed = check_seed(r.seed)
        if r.rtf is not None and not (isinstance(r.rtf, (int, float)) and math.isfinite(r.rtf) and r.rtf > 0):
            raise ValueError(f"rtf: must be a positive number, got {repr(r.rtf)[:40]}")
        unknown = [n for n in r.without if n not in nodes.REPLACEABLE]
        if unknown:
            raise ValueError(
                f"--without: {unknown[0]!r} is not one of our nodes "
                f"that can be left out ({', '.join(nodes.REPLACEABLE)})"
            )
        for topic in r.allow:
            why = allowable("/" + topic.lstrip("/"))
            if why is not None:
                raise ValueError(f"--allow {topic[:60]}: {why}")
        scenario = for_trial(load_scenario(r.scenario, r.world), r.robot, r.person)
        toggles = parse_condition(list(r.condition or scenario.condition))
        check_fit(toggles, scenario.robot)
        if r.teleop is not None:
            ids = list(r.teleop) or [h.id for h in scenario.humans]
            missing = [i for i in ids if i not in {h.id for h in scenario.humans}]
            if missing:
                raise ValueError(f"--teleop: no human {missing[0]!r} in scenario {scenario.name}")
            scenario = replace(
                scenario, humans=tuple(replace(h, model=TELEOP) if h.id in ids else h for h in scenario.humans)
            )
        base = load_suite_config(r.params_file, TRIAL_SETS)
        teleop = [h.id for h in scenario.humans if h.teleoperated]
        questionnaires = after_trial.specs(r.questionnaires, r.web is not None, teleop)
        web = None
        if r.web is not None:
            web = WebOptions(
                r.web.host,
                r.web.port,
                r.web.researcher_start,
                r.web.map_inset,
                questionnaires=questionnaires,
                tls=tls_files(r.web.tls_cert, r.web.tls_key),
                dropout=(OnDisconnect(r.web.on_disconnect).value, float(r.web.reconnect_timeout_s)),
                next_url=r.web.next_url,
            )
            busy = port_free(r.web.host, r.web.port)
            if busy:
                raise ValueError(busy)
        participant = r.participant if r.participant is not None else "-".join(teleop) or "sim"  # ("" is refused below)
        check_name(participant, "--participant")  # (before any path is built from them)
        check_name(scenario.name, f"{scenario.source or r.scenario}: name")
    except (ScenarioError, ParamsError, ValueError) as e:
        raise TrialError(str(e)) from None
    extra = {**r.extra, **({"questionnaires": after_trial.names(questionnaires)} if questionnaires else {})}
    if r.processes not in nodes.PROCESS_LAYOUTS:
        raise TrialError(f"processes: must be one of {', '.join(nodes.PROCESS_LAYOUTS)}, got {str(r.processes)[:40]!r}")
    return SessionPlan(
        scenario,
        toggles,
        seed,
        participant,
        base,
        r.rtf,
        r.free_running,
        extra,
        web,
        tuple(r.without),
        tuple(r.allow),
        r.processes,
    )


def record_trial(
    plan: SessionPlan, sessions: Path, ros: RosOptions = RosOptions(), say: Say = say_now
) -> RecordedTrial:
    """Run and record one trial into a new session folder under `sessions`; blocks until it has
    ended and its session is complete. TrialError (one line) when it cannot. Call it from the main
    thread: while it runs, a stop signal (Ctrl-C) ends the trial cleanly; the handlers the caller
    had are back when it returns."""
    previous = {sig: signal.getsignal(sig) for sig in STOP_SIGNALS}
    try:
        return _record(plan, sessions, ros, say)
    finally:
        for sig, handler in previous.items():
            signal.signal(sig, handler)


def _record(plan: SessionPlan, sessions: Path, ros: RosOptions, say: Say) -> RecordedTrial:
    try:
        domain = claim_ros_domain(ros.domain_id, ros.network, plan.without, say, ros.domains)
    except DomainBusy as e:
        raise TrialError(str(e)) from None
    with domain.lock:
        plan = replace(plan, extra={**plan.extra, "ros_domain_id": domain.domain_id})
        return _run_claimed(plan, sessions, RosOptions(domain.domain_id, ros.network), say)


def _run_claimed(plan: SessionPlan, sessions: Path, ros: RosOptions, say: Say) -> RecordedTrial:
    scenario, lockstep, rtf = plan.scenario, plan.lockstep, plan.real_time_factor
    folder, info = _new_session(plan, sessions)
    pace = (
        "lockstep clock" + (f", at most {rtf:g}x real time" if rtf < UNCAPPED_RTF else "")
        if lockstep
        else f"{rtf:g}x real time"
    )
    say(
        f"haven: {scenario.name} trial, robot {scenario.robot.name}, participant {plan.participant}, "
        f"condition {condition_name(plan.toggles)}, seed {plan.seed}, {pace}, ROS domain {ros.domain_id} -> {folder}"
    )
    # A person drives from the keyboard or a node of their own: say how (else the trial only times out).
    if plan.web is None:
        for human in (h.id for h in scenario.humans if h.teleoperated):
            say(f"haven: {human} is yours to drive: `haven teleop {human} --domain-id {ros.domain_id}` in a terminal")
    started = time.monotonic()
    # a lockstep trial runs at least at 1x on this machine
    limit = scenario.timeout_s / (1.0 if lockstep else rtf) + 120.0
    specs = specs_of(folder, plan)
    if plan.web is not None:
        specs.append(web_spec(plan, plan.web, folder))
    ended, metrics, repaired = None, None, None
    asked = after_trial.asked(plan.scenario, plan.web)
    end_read, end_write = os.pipe()  # the recorder says on it when it has the trial's end
    specs = [
        replace(s, env={**s.env, END_FD_ENV: str(end_write)}, pass_fds=(end_write,))
        if s.name == nodes.RECORDER.key
        else s
        for s in specs
    ]
    try:
        ended = _supervise(
            ros, specs, folder, None if plan.web is not None else limit, asked, (end_read, end_write)
        )  # the researcher decides when it starts
        died = exit_text(ended.died.name, ended.died.code) if ended.died is not None else None
        # (0: closed)
        repaired = (
            repair_bag(folder / "bag", "haven run" + (f" ({died})" if died else ""))
            if ended.recorder_code != 0
            else None
        )
        if repaired is not None:
            info["bag_repaired"] = repair_record(repaired)
        info.update({recorder_stop.KEY: stop} if (stop := ended.recorder_stop()) else {})  # (record/recorder_stop.py)
        write_json(folder / SESSION_FILE, info)  # (analyse judges the bag by its recorder_stop)
        # (stopped: no picture, out sooner)
        metrics = _finish(folder, plan, info, time.monotonic() - started, picture=not ended.stopped)
    except OSError as e:  # a full disk while the session is completed: what was written stays
        raise TrialError(f"{folder}: {e.strerror or e}", code=1) from None
    finally:
        os.close(end_read)
        info["outcome"] = outcome(ended, metrics["end_reason"] if metrics else None, repaired, limit)
        if asked is not None:  # (also when interrupted)
            info.update(after_trial.summary(folder, *asked, ended.questionnaires if ended else None))
        write_outcome(folder, info)
    # (a stop signal that ended the questionnaires' wait stops a study too: no next trial starts)
    stopped = ended.stopped or ended.questionnaires == "interrupted"
    wall = float(info["wall_time_s"])  # (as session.json has it: the trial to its metrics)
    return RecordedTrial(
        folder, info["outcome"], metrics, int(ros.domain_id or 0), wall, died, ended.timed_out, stopped
    )


def _wait_for_recorded_end(folder: Path, end_read: int, timeout_s: float) -> None:
    """Until the recorder says on its pipe that it has the `trial_end` event and the state streams
    up to it, or closes the pipe (it ended), or `timeout_s` (a stream that stopped: a node died),
    before everything stops."""
    events = folder / EVENTS_FILE
    if not (
        events.exists() and f'"{EventKind.TRIAL_START.value}"' in events.read_text(encoding="utf-8", errors="replace")
    ):
        return  # no trial started (stopped while held): no end to wait for
    with contextlib.suppress(OSError):
        if select.select([end_read], [], [], timeout_s)[0]:
            os.read(end_read, 64)


def _supervise(
    ros: RosOptions,
    specs: list[ProcessSpec],
    folder: Path,
    timeout_s: float | None,
    asked: Asked | None,
    end: tuple[int, int],
) -> Ended:
    """`asked`: the teleoperated humans and the questionnaires they answer after the trial; `end`:
    the recorder's end-of-trial pipe (read, write: the write end is the recorder's alone once it runs)."""
    started = time.monotonic()
    with Supervisor(ros_environment(network=ros.network, domain_id=ros.domain_id)) as sup:
        try:
            sup.install_signal_handlers()
            for spec in specs:
                sup.start(spec)
        finally:
            os.close(end[1])  # (the recorder's alone now: a recorder that ends closes the pipe)
        ender = next(s.name for s in specs if s.name in nodes.ENDS_TRIAL)  # (the suite process, or the scenario's own)
        exited = sup.wait(timeout_s=timeout_s, until_exit_of=ender)
        timed_out = exited is None and timeout_s is not None and time.monotonic() - started >= timeout_s
        questionnaires = None
        if asked is not None and exited is not None and exited.name == ender and exited.code == 0:
            _wait_for_recorded_end(folder, end[0], 10.0)  # (the trial's nodes still run: its end is recorded)
            questionnaires = after_trial.wait_for_answers(sup, folder, *asked)
        # the others run on (a scenario stopped mid-trial still publishes trial_end, interrupted)
        sup.stop_some((ender,))
        # (a dead recorder says no end)
        if questionnaires is None and (exited is None or exited.name != nodes.RECORDER.key):
            _wait_for_recorded_end(
                folder, end[0], 10.0 if exited is not None or timed_out else outcomes.STOPPED_END_WAIT_S
            )
        codes = sup.stop()
    return Ended(exited, timed_out, codes.get(nodes.RECORDER.key), questionnaires)


def _session_info(plan: SessionPlan) -> dict[str, Any]:
    """session.json as the run starts (its outcome is written however the run ends)."""
    scenario, rtf = plan.scenario, plan.real_time_factor
    return {
        **trial_record(plan.participant, plan.toggles, plan.seed, scenario),
        "scenario_file": SCENARIO_FILE,
        "world_file": WORLD_FILE,
        "params_file": PARAMS_FILE,
        "clock": "lockstep" if plan.lockstep else "free-running",
        "real_time_factor": None if rtf >= UNCAPPED_RTF else rtf,
        "without": list(plan.without),
        "allow": list(plan.allow),
        "suite_nodes": sorted(plan.declared.nodes),
        "open_topics": list(plan.declared.open),
        **plan.extra,
        "outcome": NO_OUTCOME,
    }


def _new_session(plan: SessionPlan, sessions: Path) -> tuple[Path, dict[str, Any]]:
    """The session folder with the run's inputs and session.json; TrialError (one line) if it
    cannot be made: a name that is not safe, --sessions under a file, not writable, a full disk."""
    try:
        folder = new_session_dir(sessions, plan.scenario.name, plan.participant)
    except OSError as e:
        raise TrialError(f"--sessions {sessions}: cannot make a session folder there: {e.strerror or e}") from None
    except ValueError as e:
        raise TrialError(str(e)) from None
    info = _session_info(plan)
    try:
        write_inputs(folder, plan.scenario, render(plan.config(folder), header=SESSION_PARAMS_HEADER))
        write_json(folder / SESSION_FILE, info)
    except OSError as e:
        shutil.rmtree(folder, ignore_errors=True)  # (only the inputs just copied: nothing is lost)
        raise TrialError(f"{folder}: cannot write the session's files: {e.strerror or e}") from None
    return folder, info


def _finish(folder: Path, plan: SessionPlan, info: dict[str, Any], wall: float, picture: bool = True) -> dict[str, Any]:
    """Metrics from the bag (metric plugins within the parameter file's deadline), the session record
    completed (valid, and why not), the trajectory picture."""
    with contain.use(plan.base.deadlines):
        metrics, world, rec = analyse(folder)
    write_json(folder / METRICS_FILE, metrics)
    info.update(
        end_reason=metrics["end_reason"],
        duration_s=metrics["duration_s"],
        wall_time_s=round(wall, 1),
        valid=metrics["valid"],
    )
    info.update(invalid_reasons=metrics.get("invalid_reasons", []))
    if recorder_stop.KEY in info:
        info[recorder_stop.KEY] = recorder_stop.judged(info[recorder_stop.KEY], folder / "bag", rec)
    info["wall_clock"] = trial_wall_clock(folder)
    info.update({"not_recorded": skipped} if (skipped := not_recorded(folder / "bag")) else {})
    write_json(folder / SESSION_FILE, info)
    if world is not None and picture:
        trajectory_picture(
            folder, world, rec, f"{plan.scenario.name}: {metrics['end_reason']} after {metrics['duration_s']} s"
        )
    return metrics


def tell(result: RecordedTrial) -> None:
    """A recorded trial's last lines, as `haven run` ends: how it went, what is wrong with the
    recording if anything, the session folder and what it holds."""
    if result.died is not None:
        print(f"haven: {result.died}; the trial was cut short", file=sys.stderr, flush=True)
    print(outcomes.summary(result.metrics, result.wall_s))
    if not result.valid:
        print(f"haven: the session is not valid: {'; '.join(result.invalid_reasons)}", file=sys.stderr)
        if any("from outside the suite" in r for r in result.invalid_reasons):
            hint = (
                "an outside input the study expects is declared with "
                "`haven run --allow TOPIC` (docs: Clocks and isolation)"
            )
            print(f"haven: {hint}", file=sys.stderr)
    made = sorted(p.name + ("/" if p.is_dir() else "") for p in result.folder.iterdir())
    print(f"haven: session in {result.folder} ({', '.join(made)})", flush=True)
    if result.timed_out:
        print("haven: the trial did not end in time; everything was stopped", file=sys.stderr)
