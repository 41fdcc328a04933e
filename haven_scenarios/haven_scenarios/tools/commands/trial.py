"""`haven run`: one recorded trial of a scenario with the whole node suite, into a session folder."""

from __future__ import annotations

import argparse
import sys
import time
from dataclasses import replace
from pathlib import Path
from typing import Any

import yaml

from haven_scenarios.record.session import analyse, new_session_dir, trajectory_picture, versions, write_json
from haven_scenarios.run.suite import load_suite_config
from haven_scenarios.run.trial import condition_name, parse_condition
from haven_scenarios.study.rules import EndReason
from haven_scenarios.study.scenario import Scenario, ScenarioError, load_scenario, scenario_names
from haven_scenarios.tools.commands.common import add_ros_options, environment, fail, params_file, positive, suite_specs
from haven_scenarios.tools.commands.studies import CONDITION_HELP
from haven_scenarios.tools.supervisor import Exited, ProcessSpec, Supervisor, node_argv
from haven_sim.common.events import EventKind
from haven_viz.cues import CUES, Toggles

LOCKSTEP_UNCAPPED = 1e6  # the lockstep clock's real-time factor cap when --rtf is not given


def add(sub: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    run = sub.add_parser("run", help="run one recorded trial of a scenario (default: hallway, simulated participant)")
    run.add_argument("scenario", nargs="?", default="hallway", help=f"a shipped scenario ({', '.join(scenario_names())}) or a YAML")
    run.add_argument("--participant", default="sim", help="participant id for the session (default: sim)")
    run.add_argument("--condition", nargs="+", default=["all"], metavar="CUE", help=CONDITION_HELP)
    run.add_argument("--rtf", type=positive, default=None,
                     help="real-time factor (default: 1 with a person; simulated participants run on the lockstep clock as fast as "
                          "the machine allows, or at most this fast)")
    run.add_argument("--seed", type=int, default=0)
    run.add_argument("--teleop", nargs="*", default=None, metavar="HUMAN",
                     help="these humans (default: all) are driven by a person through /humans/<id>/cmd_vel, e.g. with `haven teleop`")
    run.add_argument("--sessions", default="sessions", help="folder for session folders (default: ./sessions)")
    run.add_argument("--params-file", default=None, help="ROS parameter YAML for every node (e.g. an edited copy of haven.yaml)")
    add_ros_options(run)
    run.set_defaults(func=run_cmd)


def _prepare(args: argparse.Namespace) -> tuple[Scenario, Toggles]:
    """The scenario as this run plays it (teleoperated humans marked), and the condition; raises
    ScenarioError or ValueError (including for a bad parameter file) before anything starts."""
    scenario = load_scenario(args.scenario)
    toggles = parse_condition(args.condition)
    if args.teleop is not None:
        ids = args.teleop or [h.id for h in scenario.humans]
        unknown = [i for i in ids if i not in {h.id for h in scenario.humans}]
        if unknown:
            raise ValueError(f"--teleop: no human {unknown[0]!r} in scenario {scenario.name}")
        scenario = replace(scenario, humans=tuple(replace(h, model="teleop") if h.id in ids else h for h in scenario.humans))
    load_suite_config(args.params_file)
    return scenario, toggles


def _scenario_yaml(scenario: Scenario) -> str:
    """The scenario as run (teleop overrides included), for the session folder."""
    data = yaml.safe_load(Path(scenario.source).read_text())
    data["world"] = scenario.world_path
    data["humans"] = [{"id": h.id, "model": h.model, "route": list(h.route), "speed_mps": h.speed_mps} for h in scenario.humans]
    return yaml.safe_dump(data, sort_keys=False)


PARTICIPANTS = ("velocity_mux", "planner", "controller", "viz", "scenario")  # the nodes' names


def _specs(args: argparse.Namespace, scenario: Scenario, toggles: Toggles, folder: Path, rtf: float, lockstep: bool) -> list[ProcessSpec]:
    pfile = params_file(args)
    world = scenario.world_path
    sim: dict[str, object] = {"world": world, "real_time_factor": rtf, "battery_capacity_m": scenario.battery.capacity_m, "seed": args.seed}
    if lockstep:
        sim.update(lockstep=True, lockstep_participants=f"[{','.join(PARTICIPANTS)}]", lockstep_observers="[viz]", lockstep_wait_for="[recorder]")
    # On the lockstep clock the ticks carry the time: the participants need no /clock.
    stepped: dict[str, object] = {"lockstep": True, "use_sim_time": False} if lockstep else {}
    suite = suite_specs({
        "sim": sim, "mux": stepped, "planner": stepped, "controller": stepped,
        "viz": {"world": world, **{c: getattr(toggles, c) for c in CUES}, **stepped},
    }, pfile)
    recorder = node_argv("haven_scenarios.nodes.recorder", {"use_sim_time": True, "session_dir": str(folder.resolve())})
    scenario_node = node_argv("haven_scenarios.nodes.scenario_node",
                              {"use_sim_time": True, "scenario": str((folder / "scenario.yaml").resolve()), "seed": args.seed, **stepped},
                              ["-p", "wait_for:=[planner,recorder]"], params_file=pfile)
    return [ProcessSpec("recorder", recorder), *suite, ProcessSpec("scenario", scenario_node)]


def _wait_for_recorded_end(events: Path, timeout_s: float) -> None:
    """Give the recorder a moment to receive the `trial_end` event before everything stops."""
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        if events.exists() and any(f'"type": "{EventKind.TRIAL_END}"' in line for line in events.read_text().splitlines()):
            return
        time.sleep(0.05)


def _supervise(args: argparse.Namespace, specs: list[ProcessSpec], folder: Path, timeout_s: float) -> Exited | None:
    with Supervisor(environment(args)) as sup:
        sup.install_signal_handlers()
        for spec in specs:
            sup.start(spec)
        exited = sup.wait(timeout_s=timeout_s, until_exit_of="scenario")
        _wait_for_recorded_end(folder / "events.jsonl", 5.0)
        sup.stop()
    return exited


def _finish(folder: Path, scenario: Scenario, info: dict[str, Any], wall: float) -> dict[str, Any] | None:
    """Metrics from the bag, the session record completed, the trajectory picture."""
    try:
        metrics, world = analyse(folder)
    except Exception as e:  # noqa: BLE001 - a damaged recording must not hide the session folder
        print(f"haven: could not read the session's bag: {e}", file=sys.stderr)
        return None
    write_json(folder / "metrics.json", metrics)
    info.update(end_reason=metrics["end_reason"], duration_s=metrics["duration_s"], wall_time_s=round(wall, 1))
    write_json(folder / "session.json", info)
    if world is not None:
        trajectory_picture(folder, world, f"{scenario.name}: {metrics['end_reason']} after {metrics['duration_s']} s")
    return metrics


def run_cmd(args: argparse.Namespace) -> int:
    try:
        scenario, toggles = _prepare(args)
    except (ScenarioError, ValueError) as e:
        return fail(str(e))
    # A person plays in real time on the free-running clock; simulated participants run on the
    # lockstep clock, as fast as the machine allows unless --rtf caps it.
    lockstep = not any(h.model == "teleop" for h in scenario.humans)
    rtf = args.rtf if args.rtf is not None else (LOCKSTEP_UNCAPPED if lockstep else 1.0)
    folder = new_session_dir(Path(args.sessions), scenario.name, args.participant)
    (folder / "scenario.yaml").write_text(_scenario_yaml(scenario))
    info = {
        "participant": args.participant, "condition": condition_name(toggles), "cues": {c: getattr(toggles, c) for c in CUES},
        "seed": args.seed, "scenario": scenario.name, "scenario_file": str((folder / "scenario.yaml").resolve()),
        "world_file": scenario.world_path, "real_time_factor": rtf, "teleoperated": [h.id for h in scenario.humans if h.model == "teleop"],
        "started": time.strftime("%Y-%m-%dT%H:%M:%S%z"), "versions": versions(), "command": sys.argv,
    }
    write_json(folder / "session.json", info)
    pace = "lockstep clock" + (f", at most {rtf:g}x real time" if rtf != LOCKSTEP_UNCAPPED else "") if lockstep else f"{rtf:g}x real time"
    print(f"haven: {scenario.name} trial, participant {args.participant}, condition {condition_name(toggles)}, "
          f"seed {args.seed}, {pace} -> {folder}", flush=True)
    started = time.monotonic()
    limit = scenario.timeout_s / (1.0 if lockstep else rtf) + 120.0  # a lockstep trial runs at least at 1x on this machine
    exited = _supervise(args, _specs(args, scenario, toggles, folder, rtf, lockstep), folder, limit)
    wall = time.monotonic() - started
    metrics = _finish(folder, scenario, info, wall)
    if metrics is None:
        return 1
    print(f"haven: {metrics['end_reason']} in {metrics['duration_s']} s of sim time ({wall:.0f} s wall): "
          f"robot finished at {metrics['robot_time_to_finish_s']} s, closest approach {metrics['min_human_distance_m']} m, "
          f"{metrics['waits']} wait(s), {metrics['replans']} re-plan(s), {metrics['human_contacts']} contact(s)")
    print(f"haven: session in {folder} (bag/, events.jsonl, metrics.json, session.json, trajectory.png)")
    if exited is not None and exited.name != "scenario":
        print(f"haven: {exited.name} exited with code {exited.code}; the trial was cut short", file=sys.stderr)
        return 1
    return 0 if metrics["end_reason"] != EndReason.INTERRUPTED else 1
