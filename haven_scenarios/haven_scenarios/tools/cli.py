"""The `haven` command: starts HAVEN's nodes as plain Python processes and supervises them.

    haven sim  [--world W] [--rtf X] [--duration S]   simulator, mux, planner, controller, viz until Ctrl-C
    haven goto X Y [YAW]                              send a goal to a running suite, wait for arrival
    haven snapshot [OUT.png]                          save what the viewers show as a picture
    haven run [SCENARIO] [--participant ID] [--condition CUE...] [--rtf X] [--seed S] [--teleop [HUMAN...]]
                                                      one recorded trial -> a session folder
    haven teleop [HUMAN]                              drive a participant's avatar from the keyboard
    haven report SESSION... [--out CSV]               metrics recomputed from recordings
    haven topics | echo TOPIC | hz TOPIC              graph inspection without the ros2 command
    haven bridge [--host H] [--port P]                live Foxglove WebSocket view of a running suite
    haven batch SCENARIO --trials N --seed S          simulated trials without ROS, one CSV row each
    haven demo [--world W] [--rtf X]                  the same plus a node that drives a square

Discovery stays on this machine unless --network is given (study data stays local).
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import time
from collections.abc import Sequence
from dataclasses import replace
from pathlib import Path

import yaml

from haven_scenarios.run.batch import progress_bar, run_batch, summary
from haven_scenarios.run.suite import load_suite_config
from haven_scenarios.study.scenario import Scenario, ScenarioError, load_scenario, scenario_names
from haven_scenarios.record.session import analyse, new_session_dir, report_csv, trajectory_picture, versions, write_json
from haven_scenarios.tools.supervisor import ProcessSpec, Supervisor, node_argv, ros_environment
from haven_scenarios.run.trial import condition_name, parse_condition
from haven_viz.cues import CUES
from haven_sim.sim.world import WorldError, load_world, resolve_world_path


SUITE = ("sim", "mux", "planner", "controller", "viz")


def _positive(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number, got {text!r}") from None
    if not value > 0:
        raise argparse.ArgumentTypeError(f"must be positive, got {text}")
    return value


def _common(p: argparse.ArgumentParser) -> None:
    p.add_argument("--world", default="small_test", help="packaged world name or world YAML path (default: small_test)")
    p.add_argument("--rtf", type=_positive, default=1.0, help="real-time factor of the simulation (default: 1)")
    p.add_argument("--domain-id", type=int, default=None, help="ROS_DOMAIN_ID for the nodes (default: inherited)")
    p.add_argument("--network", action="store_true", help="allow DDS discovery beyond localhost")
    p.add_argument("--params-file", default=None, help="ROS parameter YAML passed to every node")
    p.add_argument("--without", nargs="+", default=[], choices=SUITE[1:], metavar="NODE",
                   help="leave out our mux, planner, controller or viz (to run your own in their place)")


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="haven", description="HAVEN for ROS 2: AR-cue HRI studies with a simulated TurtleBot2.")
    sub = parser.add_subparsers(dest="command", required=True)
    sim = sub.add_parser("sim", help="run the simulator, velocity mux, planner, controller and viz until Ctrl-C")
    _common(sim)
    sim.add_argument("--duration", type=_positive, default=None, help="stop after this many wall seconds")
    goto = sub.add_parser("goto", help="send a goal to a running suite (like RViz's 2D Goal Pose) and wait for it")
    goto.add_argument("x", type=float)
    goto.add_argument("y", type=float)
    goto.add_argument("yaw", type=float, nargs="?", default=0.0, help="radians (default 0)")
    goto.add_argument("--timeout", type=_positive, default=120.0, help="sim seconds to wait for arrival")
    goto.add_argument("--domain-id", type=int, default=None)
    goto.add_argument("--network", action="store_true")
    snap = sub.add_parser("snapshot", help="save what a running suite's viewers show as a top-down PNG")
    snap.add_argument("output", nargs="?", default="haven_snapshot.png")
    snap.add_argument("--world", default="small_test", help="the world the suite runs (for the walls)")
    snap.add_argument("--domain-id", type=int, default=None)
    snap.add_argument("--network", action="store_true")
    run = sub.add_parser("run", help="run one recorded trial of a scenario (default: hallway, simulated participant)")
    run.add_argument("scenario", nargs="?", default="hallway", help=f"a shipped scenario ({', '.join(scenario_names())}) or a YAML")
    run.add_argument("--participant", default="sim", help="participant id for the session (default: sim)")
    run.add_argument("--condition", nargs="+", default=["all"], metavar="CUE",
                     help="cues shown: all, none, or any of path_projection turn_signals thought_bubble battery_indicator")
    run.add_argument("--rtf", type=_positive, default=None, help="real-time factor (default: 5 with simulated participants, 1 with a person)")
    run.add_argument("--seed", type=int, default=0)
    run.add_argument("--teleop", nargs="*", default=None, metavar="HUMAN",
                     help="these humans (default: all) are driven by a person through /humans/<id>/cmd_vel, e.g. with `haven teleop`")
    run.add_argument("--sessions", default="sessions", help="folder for session folders (default: ./sessions)")
    run.add_argument("--params-file", default=None, help="ROS parameter YAML for every node (e.g. an edited copy of haven.yaml)")
    run.add_argument("--domain-id", type=int, default=None)
    run.add_argument("--network", action="store_true")
    teleop = sub.add_parser("teleop", help="drive a human avatar of a running trial from this terminal")
    teleop.add_argument("human", nargs="?", default="h1")
    teleop.add_argument("--speed", type=_positive, default=1.0, help="walking speed, m/s (default 1)")
    teleop.add_argument("--domain-id", type=int, default=None)
    teleop.add_argument("--network", action="store_true")
    for name, text in (("topics", "list the graph's topics with types and publisher/subscriber counts"),
                       ("echo", "print the messages on a topic"), ("hz", "measure a topic's message rate")):
        g = sub.add_parser(name, help=text + " (for installs without the ros2 command)")
        if name != "topics":
            g.add_argument("topic")
        g.add_argument("--count", type=int, default=0, help=argparse.SUPPRESS if name != "echo" else "stop after N messages")
        g.add_argument("--domain-id", type=int, default=None)
        g.add_argument("--network", action="store_true")
    bridge = sub.add_parser("bridge", help="relay the running suite's topics to a Foxglove WebSocket server")
    bridge.add_argument("--host", default="127.0.0.1", help="address to bind (default 127.0.0.1: this machine only)")
    bridge.add_argument("--port", type=int, default=8765)
    bridge.add_argument("--topics", nargs="+", default=None, help="only these topics (default: every topic)")
    bridge.add_argument("--domain-id", type=int, default=None)
    bridge.add_argument("--network", action="store_true")
    report = sub.add_parser("report", help="recompute metrics from session folders or bags into one CSV")
    report.add_argument("paths", nargs="+", type=Path)
    report.add_argument("--out", type=Path, default=Path("report.csv"))
    batch = sub.add_parser("batch", help="run many simulated trials without ROS, one CSV row per trial")
    batch.add_argument("scenario", help=f"a shipped scenario ({', '.join(scenario_names())}) or a scenario YAML")
    batch.add_argument("--trials", type=int, default=10)
    batch.add_argument("--seed", type=int, default=0)
    batch.add_argument("--condition", nargs="+", default=["all"], metavar="CUE",
                       help="cues shown: all, none, or any of path_projection turn_signals thought_bubble battery_indicator")
    batch.add_argument("--out", default=None, help="CSV path (default: sessions/batch_<scenario>_<time>.csv)")
    batch.add_argument("--params-file", default=None, help="ROS parameter YAML (the same file `haven run` takes)")
    demo = sub.add_parser("demo", help="simulator + mux + a node that drives a square through /cmd_vel_teleop")
    _common(demo)
    demo.set_defaults(rtf=4.0)
    demo.add_argument("--laps", type=int, default=1)
    return parser


def _suite(args: argparse.Namespace) -> list[ProcessSpec]:
    world = str(resolve_world_path(args.world))
    pfile = str(Path(args.params_file).resolve()) if args.params_file else None
    sim_time = {"use_sim_time": True}
    nodes = {
        "sim": node_argv("haven_sim.nodes.sim_node", {"world": world, "real_time_factor": args.rtf}, params_file=pfile),
        "mux": node_argv("haven_sim.nodes.mux_node", sim_time, params_file=pfile),
        "planner": node_argv("haven_sim.nodes.planner_node", sim_time, params_file=pfile),
        "controller": node_argv("haven_sim.nodes.controller_node", sim_time, params_file=pfile),
        "viz": node_argv("haven_viz.nodes.viz_node", {**sim_time, "world": world}, params_file=pfile),
    }
    return [ProcessSpec(name, argv) for name, argv in nodes.items() if name not in args.without]


def _client(args: argparse.Namespace, name: str, module: str, params: dict[str, object], extra: Sequence[str] = ()) -> int:
    """Run one client node against a running suite until it exits (or Ctrl-C); its exit code is ours."""
    env = ros_environment(network=args.network, domain_id=args.domain_id)
    with Supervisor(env) as sup:
        sup.install_signal_handlers()
        sup.start(ProcessSpec(name, node_argv(module, params, extra)))
        exited = sup.wait()
        sup.stop()
    return 1 if exited is None else exited.code


def _run(args: argparse.Namespace) -> int:
    try:
        scenario = load_scenario(args.scenario)
        toggles = parse_condition(args.condition)
        if args.teleop is not None:
            ids = args.teleop or [h.id for h in scenario.humans]
            unknown = [i for i in ids if i not in {h.id for h in scenario.humans}]
            if unknown:
                raise ValueError(f"--teleop: no human {unknown[0]!r} in scenario {scenario.name}")
            scenario = replace(scenario, humans=tuple(replace(h, model="teleop") if h.id in ids else h for h in scenario.humans))
        load_suite_config(args.params_file)  # a bad parameter file is refused before anything starts
    except (ScenarioError, ValueError) as e:
        print(f"haven: error: {e}", file=sys.stderr)
        return 2
    people = any(h.model == "teleop" for h in scenario.humans)
    rtf = args.rtf if args.rtf is not None else (1.0 if people else 5.0)
    folder = new_session_dir(Path(args.sessions), scenario.name, args.participant)
    scenario_file = folder / "scenario.yaml"
    scenario_file.write_text(_scenario_yaml(scenario))
    info = {
        "participant": args.participant, "condition": condition_name(toggles), "cues": {c: getattr(toggles, c) for c in CUES},
        "seed": args.seed, "scenario": scenario.name, "scenario_file": str(scenario_file.resolve()),
        "world_file": scenario.world_path, "real_time_factor": rtf, "teleoperated": [h.id for h in scenario.humans if h.model == "teleop"],
        "started": time.strftime("%Y-%m-%dT%H:%M:%S%z"), "versions": versions(), "command": sys.argv,
    }
    write_json(folder / "session.json", info)
    sim_time = {"use_sim_time": True}
    pfile = str(Path(args.params_file).resolve()) if args.params_file else None
    specs = [
        ProcessSpec("recorder", node_argv("haven_scenarios.nodes.recorder", {**sim_time, "session_dir": str(folder.resolve())})),
        ProcessSpec("sim", node_argv("haven_sim.nodes.sim_node", {"world": scenario.world_path, "real_time_factor": rtf,
                                                                   "battery_capacity_m": scenario.battery.capacity_m, "seed": args.seed},
                                     params_file=pfile)),
        ProcessSpec("mux", node_argv("haven_sim.nodes.mux_node", sim_time, params_file=pfile)),
        ProcessSpec("planner", node_argv("haven_sim.nodes.planner_node", sim_time, params_file=pfile)),
        ProcessSpec("controller", node_argv("haven_sim.nodes.controller_node", sim_time, params_file=pfile)),
        ProcessSpec("viz", node_argv("haven_viz.nodes.viz_node", {**sim_time, "world": scenario.world_path,
                                                                 **{c: getattr(toggles, c) for c in CUES}}, params_file=pfile)),
        ProcessSpec("scenario", node_argv("haven_scenarios.nodes.scenario_node", {**sim_time, "scenario": str(scenario_file.resolve()),
                                                                                "seed": args.seed}, ["-p", "wait_for:=[planner,recorder]"],
                                          params_file=pfile)),
    ]
    env = ros_environment(network=args.network, domain_id=args.domain_id)
    print(f"haven: {scenario.name} trial, participant {args.participant}, condition {condition_name(toggles)}, "
          f"seed {args.seed}, {rtf:g}x real time -> {folder}", flush=True)
    started = time.monotonic()
    with Supervisor(env) as sup:
        sup.install_signal_handlers()
        for spec in specs:
            sup.start(spec)
        exited = sup.wait(timeout_s=scenario.timeout_s / rtf + 120.0, until_exit_of="scenario")
        _wait_for_recorded_end(folder / "events.jsonl", 5.0)
        sup.stop()
    wall = time.monotonic() - started
    try:
        metrics, world = analyse(folder)
    except Exception as e:  # noqa: BLE001 - a damaged recording must not hide the session folder
        print(f"haven: could not read the session's bag: {e}", file=sys.stderr)
        return 1
    write_json(folder / "metrics.json", metrics)
    info.update(end_reason=metrics["end_reason"], duration_s=metrics["duration_s"], wall_time_s=round(wall, 1))
    write_json(folder / "session.json", info)
    if world is not None:
        trajectory_picture(folder, world, f"{scenario.name}: {metrics['end_reason']} after {metrics['duration_s']} s")
    print(f"haven: {metrics['end_reason']} in {metrics['duration_s']} s of sim time ({wall:.0f} s wall): "
          f"robot finished at {metrics['robot_time_to_finish_s']} s, closest approach {metrics['min_human_distance_m']} m, "
          f"{metrics['waits']} wait(s), {metrics['replans']} re-plan(s), {metrics['human_contacts']} contact(s)")
    print(f"haven: session in {folder} (bag/, events.jsonl, metrics.json, session.json, trajectory.png)")
    if exited is not None and exited.name != "scenario":
        print(f"haven: {exited.name} exited with code {exited.code}; the trial was cut short", file=sys.stderr)
        return 1
    return 0 if metrics["end_reason"] != "interrupted" else 1


def _wait_for_recorded_end(events: Path, timeout_s: float) -> None:
    """Give the recorder a moment to receive the `trial_end` event before everything stops."""
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        if events.exists() and '"trial_end"' in events.read_text():
            return
        time.sleep(0.05)


def _scenario_yaml(scenario: Scenario) -> str:
    """The scenario as run (teleop overrides included), for the session folder."""
    data = yaml.safe_load(Path(scenario.source).read_text())
    data["world"] = scenario.world_path
    data["humans"] = [{"id": h.id, "model": h.model, "route": list(h.route), "speed_mps": h.speed_mps} for h in scenario.humans]
    return yaml.safe_dump(data, sort_keys=False)


def _report(args: argparse.Namespace) -> int:
    missing = [p for p in args.paths if not p.exists()]
    if missing:
        print(f"haven: error: {missing[0]}: no such session folder or bag", file=sys.stderr)
        return 2
    rows = report_csv(args.paths, args.out)
    print(f"haven: {len(rows)} session(s) -> {args.out}")
    return 0


def _batch(args: argparse.Namespace) -> int:
    try:
        scenario = load_scenario(args.scenario)
        toggles = parse_condition(args.condition)
        if args.trials < 1:
            raise ValueError(f"--trials must be at least 1, got {args.trials}")
        if any(h.model == "teleop" for h in scenario.humans):
            raise ValueError(f"scenario {scenario.name} has a teleoperated participant: run it with `haven run`")
        suite = load_suite_config(args.params_file)
    except (ScenarioError, ValueError) as e:
        print(f"haven: error: {e}", file=sys.stderr)
        return 2
    out = Path(args.out) if args.out else Path("sessions") / f"batch_{scenario.name}_{time.strftime('%Y%m%d_%H%M%S')}.csv"
    started = time.monotonic()
    progress_bar(0, args.trials, started)
    rows = run_batch(scenario, args.trials, args.seed, toggles, out, lambda i, _: progress_bar(i + 1, args.trials, started), suite)
    print(f"haven: {scenario.name}, condition {condition_name(toggles)}: {summary(rows)}")
    print(f"haven: wrote {out}")
    return 0


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    if args.command == "batch":
        return _batch(args)
    if args.command == "run":
        return _run(args)
    if args.command == "report":
        return _report(args)
    if args.command == "goto":
        goal = {"x": args.x, "y": args.y, "yaw": args.yaw, "timeout_s": args.timeout, "use_sim_time": True}
        return _client(args, "goal_client", "haven_scenarios.nodes.goal_client", goal)
    if args.command in ("topics", "echo", "hz"):
        argv = [sys.executable, "-m", "haven_scenarios.nodes.graph_tools", args.command]
        argv += [args.topic] if args.command != "topics" else []
        argv += ["--count", str(args.count)] if args.count else []
        try:
            return subprocess.call(argv, env=ros_environment(network=args.network, domain_id=args.domain_id))
        except KeyboardInterrupt:
            return 0
    if args.command == "teleop":
        # In this terminal's process group, so that it reads the keyboard; Ctrl-C or x ends it.
        argv = node_argv("haven_scenarios.nodes.keyboard_teleop", {"human": args.human, "speed_mps": args.speed})
        env = ros_environment(network=args.network, domain_id=args.domain_id)
        try:
            return subprocess.call(argv, env=env)
        except KeyboardInterrupt:
            return 0
    if args.command == "bridge":
        extra = ["-p", f"topics:=[{','.join(args.topics)}]"] if args.topics else []
        return _client(args, "bridge", "haven_scenarios.nodes.bridge", {"host": args.host, "port": args.port}, extra)
    if args.command == "snapshot":
        try:
            world = str(resolve_world_path(args.world))
            load_world(world)
        except WorldError as e:
            print(f"haven: error: {e}", file=sys.stderr)
            return 2
        out = str(Path(args.output).resolve())
        return _client(args, "snapshot", "haven_viz.nodes.snapshot", {"world": world, "output": out})
    try:
        load_world(resolve_world_path(args.world))  # fail before starting anything
    except WorldError as e:
        print(f"haven: error: {e}", file=sys.stderr)
        return 2
    specs = _suite(args)
    until = None
    timeout = getattr(args, "duration", None)
    if args.command == "demo":
        specs.append(ProcessSpec("demo_driver", node_argv("haven_scenarios.nodes.demo_driver", {"use_sim_time": True, "laps": args.laps})))
        until = "demo_driver"
        timeout = 300.0
    env = ros_environment(network=args.network, domain_id=args.domain_id)
    with Supervisor(env) as sup:
        sup.install_signal_handlers()
        for spec in specs:
            sup.start(spec)
        print(f"haven: started {', '.join(f'{n} (pid {p})' for n, p in sup.pids().items())}; Ctrl-C stops all", flush=True)
        exited = sup.wait(timeout_s=timeout, until_exit_of=until)
        codes = sup.stop()
    if exited is not None and not (exited.name == until and exited.code == 0):
        print(f"haven: {exited.name} exited with code {exited.code}; stopped the others", file=sys.stderr)
        return exited.code or 1
    if until is not None and exited is None:
        print(f"haven: {until} did not finish; stopped everything", file=sys.stderr)
        return 1
    bad = {n: c for n, c in codes.items() if c not in (0, -2)}
    if bad and until is None:
        print(f"haven: unclean exit codes: {bad}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
