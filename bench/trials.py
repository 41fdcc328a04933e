"""Scenario trials: batch-mode trials per second (CPU per trial) for each scenario, and the real-time
factor a ROS-mode trial (`haven run`, every node its own process) actually holds.

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

sys.path.insert(0, str(Path(__file__).resolve().parent))
from common import OUT, save  # noqa: E402

from haven_scenarios.run.trial import run_trial  # noqa: E402
from haven_scenarios.study.scenario import load_scenario, scenario_names  # noqa: E402
from haven_sim.common.events import Event, EventKind  # noqa: E402


def batch(name: str, trials: int) -> dict[str, float]:
    scenario = load_scenario(name)
    cpu, wall, sim = [], [], []
    for seed in range(trials):
        c0, w0 = time.process_time(), time.perf_counter()
        m = run_trial(scenario, seed).metrics
        cpu.append(time.process_time() - c0)
        wall.append(time.perf_counter() - w0)
        sim.append(m["duration_s"])
    cpu.sort()
    return {"scenario": name, "trials": trials, "trials_per_s": trials / sum(wall), "cpu_s_median": cpu[len(cpu) // 2],
            "cpu_s_max": cpu[-1], "sim_s_mean": sum(sim) / trials, "speedup_vs_real_time": sum(sim) / sum(wall)}


def ros(name: str, rtf: float) -> dict[str, object]:
    """One `haven run`; the achieved factor is the sim time between the trial_start and trial_end
    events over the wall time between their appearance in the session's events.jsonl."""
    with tempfile.TemporaryDirectory() as tmp:
        proc = subprocess.Popen([sys.executable, "-m", "haven_scenarios.tools.cli", "run", name, "--rtf", str(rtf), "--sessions", tmp],
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        seen: dict[str, tuple[float, float]] = {}  # event -> (sim stamp, wall time first seen)
        while proc.poll() is None:
            for events in Path(tmp).glob("*/events.jsonl"):
                for line in events.read_text().splitlines():
                    e = Event.from_json(line)
                    if e.kind in (EventKind.TRIAL_START, EventKind.TRIAL_END) and e.kind not in seen:
                        seen[e.kind] = (e.stamp, time.perf_counter())
            time.sleep(0.02)
        metrics = json.loads(next(Path(tmp).glob("*/metrics.json")).read_text())
    (s0, w0), (s1, w1) = seen[EventKind.TRIAL_START], seen[EventKind.TRIAL_END]
    return {"scenario": name, "rtf_requested": rtf, "end_reason": metrics["end_reason"], "sim_s": round(s1 - s0, 1),
            "wall_s": round(w1 - w0, 2), "rtf_achieved": round((s1 - s0) / (w1 - w0), 2)}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--trials", type=int, default=20)
    ap.add_argument("--ros-rtf", type=float, default=10.0)
    ap.add_argument("--skip-ros", action="store_true")
    ap.add_argument("--json", default=str(OUT / "trials.json"))
    args = ap.parse_args()
    rows = []
    for name in scenario_names():
        row = batch(name, args.trials)
        rows.append(row)
        print(f"batch {name:13} {row['trials_per_s']:5.2f} trials/s  CPU per trial median {row['cpu_s_median']:.2f} s "
              f"(max {row['cpu_s_max']:.2f})  {row['sim_s_mean']:.0f} s simulated each, {row['speedup_vs_real_time']:.0f}x real time")
    if not args.skip_ros:
        for name in ("hallway", "shared_room"):
            row = ros(name, args.ros_rtf)
            rows.append(row)
            print(f"ros   {name:13} requested {args.ros_rtf:g}x: trial of {row['sim_s']} s simulated in {row['wall_s']} s of wall time "
                  f"= {row['rtf_achieved']}x, {row['end_reason']}")
    save(rows, args.json)


if __name__ == "__main__":
    main()
