"""`haven sim` (the node suite until Ctrl-C) and `haven demo` (the suite plus a node driving a square)."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from haven_scenarios.conduct.outcomes import repair_bag
from haven_scenarios.conduct.suite_processes import nav2_specs, suite_specs
from haven_scenarios.record.bag import not_recorded
from haven_scenarios.record.session import SESSION_FILE, WORLD_FILE, new_session_dir, provenance, write_json
from haven_scenarios.run.domains import DomainBusy
from haven_scenarios.run.grid import robot_spec
from haven_scenarios.run.suite import SIM_SETS, load_suite_config
from haven_scenarios.run.supervisor import ProcessSpec, Supervisor, node_argv
from haven_scenarios.study.names import check_name
from haven_scenarios.tools.commands.common import (
    add_robot_option,
    add_ros_options,
    add_suite_options,
    bounded_int,
    claim,
    environment,
    fail,
    params_file,
    positive,
)
from haven_sim.common import atomic, nodes
from haven_sim.common.params import ParamsError
from haven_sim.common.yaml_file import file_label
from haven_sim.nav.planner import check_plannable
from haven_sim.sim.world import WorldError, resolve_world_path
from haven_sim.sim.world_file import load_world


def add(sub: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    sim = sub.add_parser("sim", help="run the simulator, velocity mux, planner, controller and viz until Ctrl-C")
    _suite_arguments(sim, rtf=1.0)
    sim.add_argument("--duration", type=positive, default=None, help="stop after this many wall seconds")
    sim.add_argument(
        "--record", action="store_true", help="record every topic into a session folder (bag, world.yaml, session.json)"
    )
    sim.add_argument(
        "--sessions", default="sessions", help="folder for the session folder with --record (default: ./sessions)"
    )
    sim.set_defaults(func=run_suite)
    demo = sub.add_parser("demo", help="simulator + mux + a node that drives a square through /cmd_vel_teleop")
    _suite_arguments(demo, rtf=4.0)
    demo.add_argument("--laps", type=bounded_int(1), default=1)
    demo.set_defaults(func=run_suite)


def _suite_arguments(p: argparse.ArgumentParser, rtf: float) -> None:
    p.add_argument("--world", default="small_test", help="packaged world name or world YAML path (default: small_test)")
    p.add_argument("--rtf", type=positive, default=rtf, help=f"real-time factor of the simulation (default: {rtf:g})")
    add_suite_options(p, sim=True)
    add_robot_option(p)
    add_ros_options(p, suite=True)


def _ad_hoc_session(root: Path, world: str, args: argparse.Namespace) -> Path:
    """A session folder for `haven sim --record`: no scenario, no trial; the bag, the world and a
    record of how it was run."""
    name = check_name(load_world(world).name, f"{world}: name")
    folder = new_session_dir(root, "sim", name)
    atomic.write_text(folder / WORLD_FILE, Path(world).read_text(encoding="utf-8"))
    info = {
        "kind": "ad hoc (haven sim --record)",
        "world": name,
        "world_file": WORLD_FILE,
        "real_time_factor": args.rtf,
        "robot": args.robot,
        "without": list(args.without),
        "ros_domain_id": args.domain_id,
        **provenance(),
    }
    write_json(folder / SESSION_FILE, info)
    return folder


def run_suite(args: argparse.Namespace) -> int:
    try:  # fail before starting anything
        world = str(resolve_world_path(args.world))
        check_plannable(load_world(world), file_label(world))
        load_suite_config(args.params_file, SIM_SETS)
        args.robot = robot_spec(args.robot) if args.robot is not None else None
    except (WorldError, ParamsError, ValueError) as e:
        return fail(str(e))
    try:
        domain = claim(args, args.without)
    except DomainBusy as e:
        return fail(str(e))
    with domain.lock:
        return _run_claimed(args, world)


def _run_claimed(args: argparse.Namespace, world: str) -> int:
    own: dict[str, dict[str, object]] = {
        nodes.SIM.key: {"world": world, "real_time_factor": args.rtf},
        nodes.PLANNER.key: {"world": world},
        nodes.VIZ.key: {"world": world},
    }
    if args.robot is not None:  # (every node that has the `robot` parameter; the others ignore it)
        own = {n.key: {**own.get(n.key, {}), "robot": args.robot} for n in nodes.COMPONENTS}
    specs = suite_specs(own, params_file(args), args.without, args.processes)
    if nodes.NAV2.key not in args.without:
        specs += nav2_specs(own, params_file(args))
    until, timeout = None, getattr(args, "duration", None)
    folder = None
    if getattr(args, "record", False):
        try:
            folder = _ad_hoc_session(Path(args.sessions), world, args)
        except (ValueError, OSError) as e:
            return fail(f"--sessions {args.sessions}: {getattr(e, 'strerror', None) or e}")
        recorder = node_argv(
            nodes.RECORDER.module, {"use_sim_time": True, "session_dir": "."}, params_file=params_file(args)
        )
        specs.insert(0, ProcessSpec(nodes.RECORDER.key, recorder, cwd=str(folder.resolve())))
    if args.command == "demo":
        specs.append(
            ProcessSpec(
                "demo_driver", node_argv("haven_scenarios.nodes.demo_driver", {"use_sim_time": True, "laps": args.laps})
            )
        )
        until, timeout = "demo_driver", 300.0
    with Supervisor(environment(args)) as sup:
        sup.install_signal_handlers()
        for spec in specs:
            sup.start(spec)
        started = ", ".join(f"{n} (pid {p})" for n, p in sup.pids().items())
        print(f"haven: started {started} on ROS domain {args.domain_id}; Ctrl-C stops all", flush=True)
        exited = sup.wait(timeout_s=timeout, until_exit_of=until)
        # the recorder last: it gets everything
        codes = sup.stop(first=tuple(n for n in sup.pids() if n != nodes.RECORDER.key))
    if folder is not None:
        repair_bag(folder / "bag", how="haven sim --record")  # (a recorder that died leaves a bag to mend)
        if skipped := not_recorded(folder / "bag"):  # (said by the recorder as it saw them; kept with the session)
            write_json(
                folder / SESSION_FILE, {**json.loads((folder / SESSION_FILE).read_text()), "not_recorded": skipped}
            )
        print(f"haven: recorded in {folder}")
    if exited is not None and not (exited.name == until and exited.code == 0):
        print(f"haven: {exited.name} exited with code {exited.code}; stopped the others", file=sys.stderr)
        return exited.code or 1
    if until is not None and exited is None:
        print(f"haven: {until} did not finish; stopped everything", file=sys.stderr)
        return 1
    # (-15: stopped by our SIGTERM before it could say so)
    bad = {n: c for n, c in codes.items() if c not in (0, -2, -15)}
    if bad and until is None:
        print(f"haven: unclean exit codes: {bad}", file=sys.stderr)
    return 0
