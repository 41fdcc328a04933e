"""`haven batch` (simulated trials without ROS) and `haven report` (metrics from recordings)."""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from haven_scenarios.record.report import report_csv, session_folders
from haven_scenarios.run.batch import Progress, group_summaries, journal_path, run_batch
from haven_scenarios.run.grid import TrialSpec, param_keys, parse_grid, parse_seeds, plan_sweep, robot_spec
from haven_scenarios.run.suite import TRIAL_SETS, load_suite_config
from haven_scenarios.run.sweep import LOCAL, cores
from haven_scenarios.study.conditions import condition_name, parse_condition
from haven_scenarios.study.scenario import ScenarioError, load_scenario, scenario_names
from haven_scenarios.tools.commands.common import SEED, add_robot_option, bounded_int, existing_file, fail
from haven_sim.runtime.process import interrupted, on_stop_signals
from haven_viz.cues import CUES

MAX_WORKERS = 1024
GRID_HELP = (
    "an axis of the sweep (repeat for more): condition=all,none,path_projection (cues joined by +), "
    "model=walker,yielder,blocker, robot=turtlebot2,my_bot.yaml (names or robot files), "
    f"speed_mps=0.8,1.2 or a participant parameter{' (' + ', '.join(param_keys()) + ')' if param_keys() else ''}"
)
CLUSTER_HELP = (
    "run on Dask: local (a LocalCluster of --workers processes) or a running scheduler's address (tcp://host:8786)"
)
CONDITION_HELP = (
    "cues shown: all (each cue the robot has that is on by default), none, "
    f"or any of the installed cues: {' '.join(CUES)} (default: the scenario's condition)"
)


def add(sub: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    report = sub.add_parser("report", help="recompute metrics from session folders or bags into one CSV")
    report.add_argument("paths", nargs="+", type=Path)
    report.add_argument("--out", type=Path, default=Path("report.csv"))
    report.set_defaults(func=report_cmd)
    batch = sub.add_parser(
        "batch", help="run many simulated trials without ROS, one CSV row per trial, on every core or a Dask cluster"
    )
    batch.add_argument(
        "scenarios",
        nargs="+",
        metavar="scenario",
        help=f"shipped scenarios ({', '.join(scenario_names())}) or scenario YAMLs",
    )
    batch.add_argument("--trials", type=bounded_int(1), default=None, help="seeds --seed, --seed + 1, ... (default 10)")
    batch.add_argument("--seed", type=SEED, default=None, help="the first seed (default 0)")
    batch.add_argument("--seeds", default=None, help="the seeds, e.g. 0-9 or 1,4,7 (instead of --trials/--seed)")
    batch.add_argument("--condition", nargs="+", default=None, metavar="CUE", help=CONDITION_HELP)
    batch.add_argument("--grid", action="append", default=[], metavar="KEY=V1,V2", help=GRID_HELP)
    add_robot_option(batch)
    batch.add_argument(
        "--workers",
        type=bounded_int(1, MAX_WORKERS),
        default=None,
        help=f"worker processes (default: every core, {cores()} here)",
    )
    batch.add_argument("--cluster", default=None, metavar="local|ADDRESS", help=CLUSTER_HELP)
    batch.add_argument("--out", default=None, help="CSV path (default: sessions/batch_<scenario>_<time>.csv)")
    batch.add_argument(
        "--params-file", type=existing_file, default=None, help="ROS parameter YAML (the same file `haven run` takes)"
    )
    batch.set_defaults(func=batch_cmd)


def report_cmd(args: argparse.Namespace) -> int:
    """Every readable session's row; a path that is not there is named and left out (exit 1), and
    a report of no session at all is an error, not an empty file."""
    missing = [p for p in args.paths if not p.exists()]
    for p in missing:
        print(f"haven: {p}: no such session folder or bag; left out", file=sys.stderr)
    if not session_folders([p for p in args.paths if p.exists()]):
        return fail(f"no session folders in {', '.join(map(str, args.paths))}")
    rows = report_csv([p for p in args.paths if p.exists()], args.out)
    flagged = sum(1 for r in rows if not r.get("valid"))
    print(
        f"haven: {len(rows)} session(s) -> {args.out}"
        + (f" ({flagged} flagged not valid: see invalid_reasons)" if flagged else "")
    )
    return 1 if missing else 0


def _seeds(args: argparse.Namespace) -> tuple[int, ...]:
    if args.seeds is not None:
        if args.trials is not None or args.seed is not None:
            raise ValueError("give either --seeds or --trials/--seed, not both")
        return parse_seeds(args.seeds)
    first = args.seed or 0
    return tuple(range(first, first + (args.trials or 10)))


def _sweep(args: argparse.Namespace) -> list[TrialSpec]:
    """The trials the arguments ask for; ValueError (one line) for anything wrong."""
    scenarios = [load_scenario(s) for s in dict.fromkeys(args.scenarios)]
    for scenario in scenarios:
        if any(h.teleoperated for h in scenario.humans):
            raise ValueError(f"scenario {scenario.name} has a teleoperated participant: run it with `haven run`")
    axes = parse_grid(args.grid)
    if args.condition is not None:
        if "condition" in axes:
            raise ValueError("give either --condition or --grid condition=..., not both")
        axes = {"condition": (condition_name(parse_condition(args.condition)),), **axes}
    if args.robot is not None:
        if "robot" in axes:
            raise ValueError("give either --robot or --grid robot=..., not both")
        axes = {**axes, "robot": (robot_spec(args.robot),)}
    if args.cluster is not None and args.cluster != LOCAL and "://" not in args.cluster:
        raise ValueError(f"--cluster: expected local or a scheduler address like tcp://host:8786, got {args.cluster!r}")
    return plan_sweep(scenarios, axes, _seeds(args))


def batch_cmd(args: argparse.Namespace) -> int:
    try:
        specs = _sweep(args)
        suite = load_suite_config(args.params_file, TRIAL_SETS)
    except (ScenarioError, ValueError) as e:
        return fail(str(e))
    names = "+".join(dict.fromkeys(s.scenario.name for s in specs))
    out = Path(args.out) if args.out else Path("sessions") / f"batch_{names}_{time.strftime('%Y%m%d_%H%M%S')}.csv"
    workers = args.workers or cores()
    progress = Progress(len(specs))
    try:
        # (SIGTERM, SIGHUP, ... as Ctrl-C: the workers stopped, the finished rows kept)
        with on_stop_signals(interrupted):
            rows = run_batch(specs, out, suite, workers, args.cluster, progress)
    except OSError as e:  # a cluster that cannot be reached, a CSV that cannot be written
        progress.close(finished=False)
        return fail(f"{args.cluster or out}: {e}")
    except KeyboardInterrupt:
        progress.close(finished=False)
        kept = journal_path(out)
        print(
            f"haven: interrupted; the {progress.done} finished trial(s) are in {kept}"
            if kept.exists()
            else "haven: interrupted",
            file=sys.stderr,
        )
        return 130
    progress.close()
    for line in group_summaries(specs, rows):
        print(f"haven: {line}")
    print(f"haven: wrote {out}")
    return 0
