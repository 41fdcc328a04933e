"""Scenario trials: batch-mode trials per second (CPU per trial) for each scenario, and how fast a
ROS-mode trial (`haven run`, every node its own process) runs: on the lockstep clock (as fast as
the machine allows; is it the same trial as batch mode's?) and free-running at a requested factor.

usage: python bench/trials.py [--trials 20] [--ros-rtf 10] [--skip-ros]
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))
from common import OUT, save

from haven_scenarios.run.trial import run_trial
from haven_scenarios.study.scenario import load_scenario, scenario_names
from haven_sim.common.events import Event, EventKind


def batch(name: str, trials: int) -> dict[str, Any]:
    scenario = load_scenario(name)
    cpu, wall, sim = [], [], []
    for seed in range(trials):
        c0, w0 = time.process_time(), time.perf_counter()
        m = run_trial(scenario, seed).metrics
        cpu.append(time.process_time() - c0)
        wall.append(time.perf_counter() - w0)
        sim.append(m["duration_s"])
    cpu.sort()
    return {
        "scenario": name,
        "trials": trials,
        "trials_per_s": trials / sum(wall),
        "cpu_s_median": cpu[len(cpu) // 2],
        "cpu_s_max": cpu[-1],
        "sim_s_mean": sum(sim) / trials,
        "speedup_vs_real_time": sum(sim) / sum(wall),
    }


def ros(name: str, rtf: float | None) -> dict[str, Any]:
    """One `haven run` of seed 0: lockstep and uncapped when `rtf` is None, else free-running at
    `rtf`. The achieved factor is the sim time between the trial_start and trial_end events over the
    wall time between their appearance in the session's events.jsonl."""
    pace = ["--free-running", "--rtf", str(rtf)] if rtf is not None else []
    with tempfile.TemporaryDirectory() as tmp:
        proc = subprocess.Popen(
            [sys.executable, "-m", "haven_scenarios.tools.cli", "run", name, *pace, "--sessions", tmp],
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
        )
        seen: dict[str, tuple[float, float]] = {}  # event -> (sim stamp, wall time first seen)
        running = True
        while running:
            running = proc.poll() is None  # (one more look after it ended)
            for events in Path(tmp).glob("*/events.jsonl"):
                for line in events.read_text().splitlines():
                    e = Event.from_json(line)
                    if e.kind in (EventKind.TRIAL_START, EventKind.TRIAL_END) and e.kind not in seen:
                        seen[e.kind] = (e.stamp, time.perf_counter())
            time.sleep(0.02)
        metrics = json.loads(next(Path(tmp).glob("*/metrics.json")).read_text())
    (s0, w0), (s1, w1) = seen[EventKind.TRIAL_START], seen[EventKind.TRIAL_END]
    batch_metrics = run_trial(load_scenario(name), 0).metrics
    differ = sorted(k for k, v in batch_metrics.items() if metrics.get(k) != v)
    return {
        "scenario": name,
        "clock": "lockstep" if rtf is None else "free-running",
        "rtf_requested": rtf,
        "metrics": len(batch_metrics),
        "end_reason": metrics["end_reason"],
        "valid": metrics["valid"],
        "metrics_unlike_batch": differ,
        "sim_s": round(s1 - s0, 1),
        "wall_s": round(w1 - w0, 2),
        "rtf_achieved": round((s1 - s0) / (w1 - w0), 2),
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--trials", type=int, default=20)
    ap.add_argument("--ros-rtf", type=float, default=10.0)
    ap.add_argument("--skip-ros", action="store_true")
    ap.add_argument("--json", default=str(OUT / "trials.json"))
    args = ap.parse_args()
    rows: list[dict[str, Any]] = []
    for name in scenario_names():
        row = batch(name, args.trials)
        rows.append(row)
        print(
            f"batch {name:13} {row['trials_per_s']:5.2f} trials/s  CPU per trial "
            f"median {row['cpu_s_median']:.2f} s (max {row['cpu_s_max']:.2f})  "
            f"{row['sim_s_mean']:.0f} s simulated each, {row['speedup_vs_real_time']:.0f}x real time"
        )
    if not args.skip_ros:
        for name in ("hallway", "shared_room"):
            for rtf in (None, args.ros_rtf):
                row = ros(name, rtf)
                rows.append(row)
                pace = "lockstep, uncapped" if rtf is None else f"free-running, requested {rtf:g}x"
                unlike = f"{len(row['metrics_unlike_batch'])} of {row['metrics']}"
                print(
                    f"ros   {name:13} {pace}: trial of {row['sim_s']} s simulated in "
                    f"{row['wall_s']} s of wall time = {row['rtf_achieved']}x, {row['end_reason']}, "
                    f"valid {row['valid']}, metrics unlike batch mode's: {unlike}"
                )
    save(rows, args.json)


if __name__ == "__main__":
    main()
