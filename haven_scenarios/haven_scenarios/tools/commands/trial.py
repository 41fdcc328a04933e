"""`haven run`: one recorded trial of a scenario with the whole node suite, into a session folder."""

from __future__ import annotations

import argparse
import shutil
import sys
import time
from dataclasses import replace
from pathlib import Path
from typing import Any

from haven_scenarios.record.session import (
    END_MARK,
    EVENTS_FILE,
    METRICS_FILE,
    PARAMS_FILE,
    SCENARIO_FILE,
    SESSION_FILE,
    WORLD_FILE,
    analyse,
    check_name,
    new_session_dir,
    session_info,
    session_scenario,
    trajectory_picture,
    trial_record,
    trial_wall_clock,
    write_inputs,
    write_json,
)
from haven_scenarios.run.suite import TRIAL_SETS, SuiteConfig, load_suite_config, render
from haven_scenarios.run.trial import SEED_MAX, condition_name, parse_condition
from haven_scenarios.study.rules import EndReason
from haven_scenarios.study.scenario import TELEOP, Scenario, ScenarioError, load_scenario, scenario_names
from haven_scenarios.tools.commands import after_trial
from haven_scenarios.tools.commands.after_trial import Asked
from haven_scenarios.tools.commands.batch_report import CONDITION_HELP
from haven_scenarios.tools.commands.common import (
    PORT,
    SEED,
    add_ros_options,
    add_suite_options,
    allowed_topic,
    claim,
    environment,
    fail,
    port_free,
    positive,
)
from haven_scenarios.tools.commands.recordings import NO_OUTCOME, Ended, exit_text, outcome, repair_bag, repair_record, write_outcome
from haven_scenarios.tools.commands.session_plan import SESSION_PARAMS_HEADER, SessionPlan, WebOptions, specs_of, web_spec
from haven_scenarios.tools.domains import DomainBusy
from haven_scenarios.tools.supervisor import ProcessSpec, Supervisor
from haven_sim.common import nodes
from haven_sim.common.events import EventKind
from haven_sim.runtime.lockstep import UNCAPPED_RTF
from haven_viz.cues import CUES, Toggles


def add(sub: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    run = sub.add_parser("run", help="run one recorded trial of a scenario (default: hallway, simulated participant)")
    run.add_argument("scenario", nargs="?", default="hallway", help=f"a shipped scenario ({', '.join(scenario_names())}) or a YAML")
    run.add_argument("--participant", default=None, help="participant id for the session (default: sim, or the teleoperated humans' ids, e.g. h1-h2)")
    run.add_argument("--condition", nargs="+", default=None, metavar="CUE", help=CONDITION_HELP)
    run.add_argument(
        "--rtf",
        type=positive,
        default=None,
        help="real-time factor (default: 1 with a person; simulated participants run on the lockstep clock as fast as "
        "the machine allows, or at most this fast)",
    )
    run.add_argument(
        "--free-running", action="store_true", help="simulated participants on the free-running clock too (machine load then changes what happens)"
    )
    run.add_argument("--seed", type=SEED, default=0)
    run.add_argument(
        "--teleop",
        nargs="*",
        default=None,
        metavar="HUMAN",
        help="these humans (default: all) are driven by a person through /humans/<id>/cmd_vel, e.g. with `haven teleop`",
    )
    run.add_argument("--sessions", default="sessions", help="folder for session folders (default: ./sessions)")
    run.add_argument(
        "--world", default=None, help="play the scenario in this world (a packaged world name or a YAML with the rooms, gems and humans it names)"
    )
    add_suite_options(run)
    web = run.add_argument_group("in the browser")
    web.add_argument(
        "--web", action="store_true", help="serve the participants' first-person pages and the researcher console (the URLs are printed)"
    )
    run.add_argument(
        "--allow",
        nargs="+",
        default=[],
        type=allowed_topic,
        metavar="TOPIC",
        help="topics nodes outside the suite may publish on during the trial (e.g. /cmd_vel_teleop for a teleop node, /goal_pose "
        "for RViz goals); another outside publisher on a topic the trial rests on makes the session not valid",
    )
    web.add_argument("--host", default="127.0.0.1", help="address the pages are served on (0.0.0.0: the lab network; default: this machine)")
    web.add_argument("--port", type=PORT, default=8088, help="port of the pages (default 8088)")
    web.add_argument("--researcher-start", action="store_true", help="the trial starts on the console's Start, not when the participants are ready")
    web.add_argument("--no-map-inset", action="store_true", help="no map inset on the participants' pages")
    after_trial.add_option(web)
    add_ros_options(run, suite=True)
    run.set_defaults(func=run_cmd)
    rerun = sub.add_parser("rerun", help="run a recorded session again from its folder (same scenario, world, parameters, seed, condition)")
    rerun.add_argument("session", type=Path, help="a session folder")
    rerun.add_argument("--sessions", default=None, help="folder for the new session (default: beside the old one)")
    rerun.add_argument("--rtf", type=positive, default=None, help="real-time factor (default: as recorded)")
    add_ros_options(rerun, suite=True)
    rerun.set_defaults(func=rerun_cmd)


def _prepare(args: argparse.Namespace) -> tuple[Scenario, Toggles, SuiteConfig]:
    """The scenario as this run plays it (teleoperated humans marked), the condition and the
    parameter file's configuration; raises ScenarioError or ValueError (including for a bad
    parameter file) before anything starts."""
    scenario = load_scenario(args.scenario, args.world)
    toggles = parse_condition(args.condition or scenario.condition)
    if args.teleop is not None:
        ids = args.teleop or [h.id for h in scenario.humans]
        unknown = [i for i in ids if i not in {h.id for h in scenario.humans}]
        if unknown:
            raise ValueError(f"--teleop: no human {unknown[0]!r} in scenario {scenario.name}")
        scenario = replace(scenario, humans=tuple(replace(h, model=TELEOP) if h.id in ids else h for h in scenario.humans))
    return scenario, toggles, load_suite_config(args.params_file, TRIAL_SETS)


def _wait_for_recorded_end(folder: Path, timeout_s: float) -> None:
    """Until the recorder has the `trial_end` event and the state streams up to it (it writes
    END_MARK), or `timeout_s` (a stream that stopped: a node died), before everything stops."""
    mark = folder / END_MARK
    events = folder / EVENTS_FILE
    if not (events.exists() and f'"{EventKind.TRIAL_START.value}"' in events.read_text(encoding="utf-8", errors="replace")):
        return  # no trial started (stopped while held): no end to wait for
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline and not mark.exists():
        time.sleep(0.05)
    mark.unlink(missing_ok=True)


def _supervise(args: argparse.Namespace, specs: list[ProcessSpec], folder: Path, timeout_s: float | None, asked: Asked | None = None) -> Ended:
    """`asked`: the teleoperated humans and the questionnaires they answer after the trial."""
    started = time.monotonic()
    with Supervisor(environment(args)) as sup:
        sup.install_signal_handlers()
        for spec in specs:
            sup.start(spec)
        exited = sup.wait(timeout_s=timeout_s, until_exit_of=nodes.SCENARIO.key)
        timed_out = exited is None and timeout_s is not None and time.monotonic() - started >= timeout_s
        questionnaires = None
        if asked is not None and exited is not None and exited.name == nodes.SCENARIO.key and exited.code == 0:
            _wait_for_recorded_end(folder, 10.0)  # (the trial's nodes still run: its end is recorded)
            questionnaires = after_trial.wait_for_answers(sup, folder, *asked)
        sup.stop_some((nodes.SCENARIO.key,))  # the others run on (a scenario stopped mid-trial still publishes trial_end, interrupted)
        if questionnaires is None and (exited is None or exited.name != nodes.RECORDER.key):  # (a dead recorder marks no end)
            _wait_for_recorded_end(folder, 10.0)
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
    """The session folder with the run's inputs and session.json; ValueError (one line) if it
    cannot be made: a name that is not safe, --sessions under a file, not writable, a full disk."""
    try:
        folder = new_session_dir(sessions, plan.scenario.name, plan.participant)
    except OSError as e:
        raise ValueError(f"--sessions {sessions}: cannot make a session folder there: {e.strerror or e}") from None
    info = _session_info(plan)
    try:
        write_inputs(folder, plan.scenario, render(plan.config(folder), header=SESSION_PARAMS_HEADER))
        write_json(folder / SESSION_FILE, info)
    except OSError as e:
        shutil.rmtree(folder, ignore_errors=True)  # (only the inputs just copied: nothing is lost)
        raise ValueError(f"{folder}: cannot write the session's files: {e.strerror or e}") from None
    return folder, info


def _finish(folder: Path, scenario: Scenario, info: dict[str, Any], wall: float) -> dict[str, Any]:
    """Metrics from the bag, the session record completed, the trajectory picture."""
    metrics, world, rec = analyse(folder)
    write_json(folder / METRICS_FILE, metrics)
    info.update(end_reason=metrics["end_reason"], duration_s=metrics["duration_s"], wall_time_s=round(wall, 1), valid=metrics["valid"])
    info["wall_clock"] = trial_wall_clock(folder)
    write_json(folder / SESSION_FILE, info)
    if world is not None:
        trajectory_picture(folder, world, rec, f"{scenario.name}: {metrics['end_reason']} after {metrics['duration_s']} s")
    return metrics


def run_session(args: argparse.Namespace, plan: SessionPlan, sessions: Path) -> int:
    """Run and record one trial into a new session folder under `sessions`; the exit code.
    session.json gets the run's outcome however it ends."""
    try:
        domain = claim(args, plan.without)
    except DomainBusy as e:
        return fail(str(e))
    with domain.lock:
        return _run_claimed(args, replace(plan, extra={**plan.extra, "ros_domain_id": domain.domain_id}), sessions)


def _run_claimed(args: argparse.Namespace, plan: SessionPlan, sessions: Path) -> int:
    scenario, lockstep, rtf = plan.scenario, plan.lockstep, plan.real_time_factor
    try:
        folder, info = _new_session(plan, sessions)
    except ValueError as e:
        return fail(str(e))
    pace = "lockstep clock" + (f", at most {rtf:g}x real time" if rtf < UNCAPPED_RTF else "") if lockstep else f"{rtf:g}x real time"
    print(
        f"haven: {scenario.name} trial, participant {plan.participant}, condition {condition_name(plan.toggles)}, "
        f"seed {plan.seed}, {pace}, ROS domain {args.domain_id} -> {folder}",
        flush=True,
    )
    started = time.monotonic()
    limit = scenario.timeout_s / (1.0 if lockstep else rtf) + 120.0  # a lockstep trial runs at least at 1x on this machine
    specs = specs_of(folder, plan)
    if plan.web is not None:
        specs.append(web_spec(plan, plan.web, folder))
    ended, metrics, repaired = None, None, None
    try:
        asked = after_trial.asked(plan.scenario, plan.web)
        ended = _supervise(args, specs, folder, None if plan.web is not None else limit, asked)  # the researcher decides when it starts
        if ended.died is not None:
            print(f"haven: {exit_text(ended.died.name, ended.died.code)}; the trial was cut short", file=sys.stderr, flush=True)
        repaired = repair_bag(folder / "bag", "haven run" + (f" ({exit_text(ended.died.name, ended.died.code)})" if ended.died else ""))
        if repaired is not None:
            info["bag_repaired"] = repair_record(repaired)
        metrics = _finish(folder, scenario, info, time.monotonic() - started)
    except OSError as e:  # a full disk while the session is completed: what was written stays
        print(f"haven: error: {folder}: {e.strerror or e}", file=sys.stderr)
        return 1
    finally:
        info["outcome"] = outcome(ended, metrics["end_reason"] if metrics else None, repaired, limit)
        if (asked := after_trial.asked(plan.scenario, plan.web)) is not None:  # (also when interrupted)
            info.update(after_trial.summary(folder, *asked, ended.questionnaires if ended else None))
        write_outcome(folder, info)
    return _said(folder, ended, metrics, time.monotonic() - started)


def _said(folder: Path, ended: Ended, metrics: dict[str, Any], wall: float) -> int:
    """The run's last lines, and its exit code."""
    print(summary(metrics, wall))
    if not metrics["valid"]:
        print(f"haven: the recording is not complete: {'; '.join(metrics['invalid_reasons'])}", file=sys.stderr)
        if any("from outside the suite" in r for r in metrics["invalid_reasons"]):
            hint = "an outside input the study expects is declared with `haven run --allow TOPIC` (README: One trial, one world)"
            print(f"haven: {hint}", file=sys.stderr)
    made = sorted(p.name + ("/" if p.is_dir() else "") for p in folder.iterdir())
    print(f"haven: session in {folder} ({', '.join(made)})")
    if ended.died is not None:
        return 1
    if ended.timed_out:
        print("haven: the trial did not end in time; everything was stopped", file=sys.stderr)
    return 0 if metrics["end_reason"] != EndReason.INTERRUPTED else 1


def summary(metrics: dict[str, Any], wall_s: float) -> str:
    """The one line `haven run` prints about a trial's outcome."""
    if metrics["duration_s"] is None:
        return f"haven: {metrics['end_reason']} before the trial started ({wall_s:.0f} s wall)"
    finished = metrics.get("robot_time_to_finish_s")
    robot = f"robot finished at {finished} s" if finished is not None else "robot did not finish"
    return (
        f"haven: {metrics['end_reason']} in {metrics['duration_s']} s of sim time ({wall_s:.0f} s wall): {robot}, "
        f"closest approach {metrics.get('min_human_distance_m')} m, {metrics.get('waits')} wait(s), "
        f"{metrics.get('replans')} re-plan(s), {metrics.get('human_contacts')} contact(s)"
    )


def run_cmd(args: argparse.Namespace) -> int:
    try:
        scenario, toggles, base = _prepare(args)
    except (ScenarioError, ValueError) as e:
        return fail(str(e))
    web, teleop = None, [h.id for h in scenario.humans if h.teleoperated]
    try:
        questionnaires = after_trial.specs(args, teleop)
    except ValueError as e:
        return fail(str(e))
    if args.web:
        web = WebOptions(args.host, args.port, args.researcher_start, not args.no_map_inset, questionnaires=questionnaires)
        busy = port_free(args.host, args.port)
        if busy:
            return fail(busy)
    participant = args.participant if args.participant is not None else "-".join(teleop) or "sim"  # ("" is refused below)
    try:  # before any path is built from them
        check_name(participant, "--participant")
        check_name(scenario.name, f"{scenario.source or args.scenario}: name")
    except ValueError as e:
        return fail(str(e))
    extra = {"questionnaires": after_trial.names(questionnaires)} if questionnaires else {}
    plan = SessionPlan(
        scenario, toggles, args.seed, participant, base, args.rtf, args.free_running, extra, web, tuple(args.without), tuple(args.allow)
    )
    return run_session(args, plan, Path(args.sessions))


def rerun_cmd(args: argparse.Namespace) -> int:
    """The session again, from its own files: scenario, world, parameters, seed, condition."""
    folder: Path = args.session
    info = session_info(folder)
    scenario, problem = session_scenario(folder)
    if scenario is None or not info:
        return fail(f"{folder}: cannot run it again: {problem or 'no readable session.json'}")
    free = info.get("clock") == "free-running"
    try:
        base = load_suite_config(folder / PARAMS_FILE if (folder / PARAMS_FILE).exists() else None)
        toggles = Toggles(**{c: bool(v) for c, v in dict(info.get("cues", {})).items() if c in CUES})
        seed = info.get("seed", 0)
        if isinstance(seed, bool) or not isinstance(seed, int) or not 0 <= seed <= SEED_MAX:
            raise ValueError(f"seed: must be an integer 0..{SEED_MAX}, got {str(seed)[:40]}")
        rtf = args.rtf if args.rtf is not None else (float(info.get("real_time_factor") or 1.0) if free else None)
    except (TypeError, ValueError) as e:
        return fail(f"{folder / SESSION_FILE}: {e}")
    without = tuple(str(n) for n in info.get("without") or ())  # (their own nodes must run again too)
    allow = tuple(str(t) for t in info.get("allow") or ())
    try:  # session.json and scenario.yaml are data: their names are checked before a path is built
        participant = check_name(info.get("participant", "sim"), f"{folder / SESSION_FILE}: participant")
        check_name(scenario.name, f"{folder / SCENARIO_FILE}: name")
    except ValueError as e:
        return fail(str(e))
    plan = SessionPlan(scenario, toggles, seed, participant, base, rtf, free, {"rerun_of": folder.name}, without=without, allow=allow)
    return run_session(args, plan, Path(args.sessions) if args.sessions else folder.parent)
