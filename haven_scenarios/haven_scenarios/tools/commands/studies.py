"""`haven batch` (simulated trials without ROS) and `haven report` (metrics from recordings)."""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from haven_scenarios.record.report import report_csv, session_folders
from haven_scenarios.run.batch import progress_bar, run_batch, summary
from haven_scenarios.run.suite import load_suite_config
from haven_scenarios.run.trial import condition_name, parse_condition
from haven_scenarios.study.scenario import ScenarioError, load_scenario, scenario_names
from haven_scenarios.tools.commands.common import SEED, bounded_int, existing_file, fail

CONDITION_HELP = "cues shown: all, none, or any of path_projection turn_signals thought_bubble battery_indicator (default: the scenario's condition)"


def add(sub: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    report = sub.add_parser("report", help="recompute metrics from session folders or bags into one CSV")
    report.add_argument("paths", nargs="+", type=Path)
    report.add_argument("--out", type=Path, default=Path("report.csv"))
    report.set_defaults(func=report_cmd)
    batch = sub.add_parser("batch", help="run many simulated trials without ROS, one CSV row per trial")
    batch.add_argument("scenario", help=f"a shipped scenario ({', '.join(scenario_names())}) or a scenario YAML")
    batch.add_argument("--trials", type=bounded_int(1), default=10)
    batch.add_argument("--seed", type=SEED, default=0)
    batch.add_argument("--condition", nargs="+", default=None, metavar="CUE", help=CONDITION_HELP)
    batch.add_argument("--out", default=None, help="CSV path (default: sessions/batch_<scenario>_<time>.csv)")
    batch.add_argument("--params-file", type=existing_file, default=None, help="ROS parameter YAML (the same file `haven run` takes)")
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
    print(f"haven: {len(rows)} session(s) -> {args.out}" + (f" ({flagged} flagged not valid: see invalid_reasons)" if flagged else ""))
    return 1 if missing else 0


def batch_cmd(args: argparse.Namespace) -> int:
    try:
        scenario = load_scenario(args.scenario)
        toggles = parse_condition(args.condition or scenario.condition)
        if args.trials < 1:
            raise ValueError(f"--trials must be at least 1, got {args.trials}")
        if any(h.model == "teleop" for h in scenario.humans):
            raise ValueError(f"scenario {scenario.name} has a teleoperated participant: run it with `haven run`")
        suite = load_suite_config(args.params_file)
    except (ScenarioError, ValueError) as e:
        return fail(str(e))
    out = Path(args.out) if args.out else Path("sessions") / f"batch_{scenario.name}_{time.strftime('%Y%m%d_%H%M%S')}.csv"
    started = time.monotonic()
    progress_bar(0, args.trials, started)
    rows = run_batch(scenario, args.trials, args.seed, toggles, out, lambda i, _: progress_bar(i + 1, args.trials, started), suite)
    print(f"haven: {scenario.name}, condition {condition_name(toggles)}: {summary(rows)}")
    print(f"haven: wrote {out}")
    return 0
