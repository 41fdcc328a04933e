"""`haven run`: one recorded trial of a scenario with the whole node suite, into a session folder."""

from __future__ import annotations

import argparse
import sys
from dataclasses import replace
from pathlib import Path

from haven_scenarios.conduct.recorded_trial import (
    RecordedTrial,
    RosOptions,
    TrialError,
    TrialRequest,
    WebRequest,
    plan_trial,
    record_trial,
    tell,
)
from haven_scenarios.conduct.session_plan import SessionPlan
from haven_scenarios.record.session import PARAMS_FILE, SCENARIO_FILE, SESSION_FILE, session_info, session_scenario
from haven_scenarios.run.suite import SuiteConfig, checked_suite_config, load_suite_config
from haven_scenarios.study.conditions import check_seed
from haven_scenarios.study.names import check_name
from haven_scenarios.study.rules import EndReason
from haven_scenarios.study.scenario import scenario_names
from haven_scenarios.tools.commands.batch_report import CONDITION_HELP
from haven_scenarios.tools.commands.common import (
    PORT,
    SEED,
    add_dropout_options,
    add_questionnaire_option,
    add_robot_option,
    add_ros_options,
    add_suite_options,
    add_tls_options,
    allowed_topic,
    fail,
    positive,
)
from haven_sim.common.params import load_params_file
from haven_sim.common.yaml_file import file_label
from haven_sim.robots.robot_kind import is_file_spec
from haven_viz.cues import CUES, Toggles


def add(sub: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    run = sub.add_parser("run", help="run one recorded trial of a scenario (default: hallway, simulated participant)")
    run.add_argument(
        "scenario", nargs="?", default="hallway", help=f"a shipped scenario ({', '.join(scenario_names())}) or a YAML"
    )
    run.add_argument(
        "--participant",
        default=None,
        help="participant id for the session (default: sim, or the teleoperated humans' ids, e.g. h1-h2)",
    )
    run.add_argument("--condition", nargs="+", default=None, metavar="CUE", help=CONDITION_HELP)
    run.add_argument(
        "--rtf",
        type=positive,
        default=None,
        help="real-time factor (default: 1 with a person; simulated participants run on the lockstep clock as fast as "
        "the machine allows, or at most this fast)",
    )
    run.add_argument(
        "--free-running",
        action="store_true",
        help="simulated participants on the free-running clock too (machine load then changes what happens)",
    )
    run.add_argument("--seed", type=SEED, default=0)
    run.add_argument(
        "--teleop",
        nargs="*",
        default=None,
        metavar="HUMAN",
        help=(
            "these humans (default: all) are driven by a person through /humans/<id>/cmd_vel, e.g. with `haven teleop`"
        ),
    )
    run.add_argument("--sessions", default="sessions", help="folder for session folders (default: ./sessions)")
    run.add_argument(
        "--world",
        default=None,
        help=(
            "play the scenario in this world (a packaged world name or a YAML with the rooms, gems and humans it names)"
        ),
    )
    add_suite_options(run)
    add_robot_option(run)
    web = run.add_argument_group("in the browser")
    web.add_argument(
        "--web",
        action="store_true",
        help="serve the participants' first-person pages and the researcher console (the URLs are printed)",
    )
    run.add_argument(
        "--allow",
        nargs="+",
        default=[],
        type=allowed_topic,
        metavar="TOPIC",
        help=(
            "topics nodes outside the suite may publish on during the trial "
            "(e.g. /cmd_vel_teleop for a teleop node, /goal_pose for RViz goals); "
            "another outside publisher on a topic the trial rests on makes the session not valid"
        ),
    )
    web.add_argument(
        "--host",
        default="127.0.0.1",
        help="address the pages are served on (0.0.0.0: the lab network; default: this machine)",
    )
    web.add_argument("--port", type=PORT, default=8088, help="port of the pages (default 8088)")
    add_tls_options(web)
    add_dropout_options(web)
    web.add_argument(
        "--researcher-start",
        action="store_true",
        help="the trial starts on the console's Start, not when the participants are ready",
    )
    web.add_argument("--no-map-inset", action="store_true", help="no map inset on the participants' pages")
    add_questionnaire_option(web)
    add_ros_options(run, suite=True)
    run.set_defaults(func=run_cmd)
    rerun = sub.add_parser(
        "rerun", help="run a recorded session again from its folder (same scenario, world, parameters, seed, condition)"
    )
    rerun.add_argument("session", type=Path, help="a session folder")
    rerun.add_argument("--sessions", default=None, help="folder for the new session (default: beside the old one)")
    rerun.add_argument("--rtf", type=positive, default=None, help="real-time factor (default: as recorded)")
    add_ros_options(rerun, suite=True)
    rerun.set_defaults(func=rerun_cmd)


def run_session(args: argparse.Namespace, plan: SessionPlan, sessions: Path) -> int:
    """Run and record one trial into a new session folder under `sessions` (conduct/recorded_trial.py);
    the exit code."""
    try:
        result = record_trial(plan, sessions, RosOptions(args.domain_id, args.network, args.domains))
    except TrialError as e:
        if e.code == 2:
            return fail(str(e))
        print(f"haven: error: {e}", file=sys.stderr)
        return e.code
    return _said(result)


def _said(result: RecordedTrial) -> int:
    """The run's last lines, and its exit code."""
    tell(result)
    if result.died is not None:
        return 1
    return 0 if result.end_reason != EndReason.INTERRUPTED else 1


def request_of(args: argparse.Namespace) -> TrialRequest:
    """`haven run`'s options as a trial request."""
    web = None
    if args.web:
        tls = (args.tls_cert or "", args.tls_key or "")
        web = WebRequest(
            args.host,
            args.port,
            args.researcher_start,
            not args.no_map_inset,
            *tls,
            args.on_disconnect,
            args.reconnect_timeout,
        )
    return TrialRequest(
        args.scenario,
        args.participant,
        tuple(args.condition) if args.condition else None,
        args.seed,
        args.world,
        args.params_file,
        tuple(args.teleop) if args.teleop is not None else None,
        args.rtf,
        args.free_running,
        tuple(args.without),
        tuple(args.allow),
        web,
        tuple(args.questionnaire or ()),
        robot=args.robot,
        processes=args.processes,
    )


def run_cmd(args: argparse.Namespace) -> int:
    if not args.web and (args.tls_cert or args.tls_key):
        return fail("--tls-cert and --tls-key serve the pages: they need --web")
    try:
        plan = plan_trial(request_of(args))
    except TrialError as e:
        return fail(str(e))
    return run_session(args, plan, Path(args.sessions))


def session_params(folder: Path) -> SuiteConfig:
    """The session's params.yaml as a configuration, read from anywhere: its robot file (robot.yaml)
    is named relative to the folder, where the nodes ran."""
    path = folder / PARAMS_FILE
    if not path.exists():
        return load_suite_config(None)
    params = load_params_file(path)
    for section, values in params.items():
        robot = values.get("robot")
        if isinstance(robot, str) and is_file_spec(str(folder / robot)) and not Path(robot).is_absolute():
            params[section] = {**values, "robot": str(folder.resolve() / robot)}
    return checked_suite_config(params, file_label(path))


def rerun_cmd(args: argparse.Namespace) -> int:
    """The session again, from its own files: scenario, world, parameters, seed, condition."""
    folder: Path = args.session
    info = session_info(folder)
    scenario, problem = session_scenario(folder)
    if scenario is None or not info:
        return fail(f"{folder}: cannot run it again: {problem or 'no readable session.json'}")
    free = info.get("clock") == "free-running"
    try:
        base = session_params(folder)
        toggles = Toggles(**{c: bool(v) for c, v in dict(info.get("cues", {})).items() if c in CUES})
        seed = check_seed(info.get("seed", 0))
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
    # (robot.yaml is the robot: the name as first given)
    scenario = replace(scenario, robot_model=str(info.get("robot") or scenario.robot_model))
    plan = SessionPlan(
        scenario, toggles, seed, participant, base, rtf, free, {"rerun_of": folder.name}, without=without, allow=allow
    )
    return run_session(args, plan, Path(args.sessions) if args.sessions else folder.parent)
