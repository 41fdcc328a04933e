"""Robot sweep: every catalogue robot x hallway and shared_room x each simulated participant model x
seeds, in batch mode: completion, end reasons, contacts (footprint-based, by who closed in), passes
(Figure 3) and waits, the closest approach between bodies, and what a batch trial costs per robot
(CPU seconds in the worker, the trial alone).

usage: python bench/robots.py [--seeds 30] [--workers 2] [--robots turtlebot2 quadrotor ...]
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from collections import Counter
from concurrent.futures import ProcessPoolExecutor
from dataclasses import replace
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))
from common import OUT, save

from haven_scenarios.run.trial import run_trial
from haven_scenarios.study.scenario import load_scenario
from haven_sim.robots.robot_kind import resolve_robot, robot_names

SCENARIOS = ("hallway", "shared_room")
MODELS = ("walker", "blocker", "yielder")


def one(job: tuple[str, str, str, int]) -> dict[str, Any]:
    robot, name, model, seed = job
    s = load_scenario(name).for_robot(resolve_robot(robot))
    s = replace(s, humans=tuple(replace(h, model=model) for h in s.humans))
    cpu = time.process_time()
    m = run_trial(s, seed).metrics
    keys = (
        "end_reason",
        "waits",
        "passes",
        "human_contacts",
        "human_contacts_robot_on_person",
        "human_contacts_person_on_robot",
        "min_human_surface_distance_m",
        "robot_time_to_finish_s",
        "charge_trips",
    )
    return {
        "robot": robot,
        "scenario": name,
        "model": model,
        "seed": seed,
        "cpu_s": time.process_time() - cpu,
        **{k: m.get(k) for k in keys},
    }


def line(rows: list[dict[str, Any]]) -> str:
    n = len(rows)
    ends = Counter(r["end_reason"] for r in rows)
    gaps = [r["min_human_surface_distance_m"] for r in rows if r["min_human_surface_distance_m"] is not None]
    times = [r["robot_time_to_finish_s"] for r in rows if r["robot_time_to_finish_s"] is not None]
    other = ", ".join(f"{k} {v}" for k, v in ends.items() if k != "completed")
    return (
        f"| {ends['completed']}/{n}{f' ({other})' if other else ''} "
        f"| {sum(r['human_contacts'] or 0 for r in rows)} "
        f"({sum(r['human_contacts_robot_on_person'] or 0 for r in rows)}/"
        f"{sum(r['human_contacts_person_on_robot'] or 0 for r in rows)}) "
        f"| {sum(r['passes'] or 0 for r in rows)} | {sum(r['waits'] or 0 for r in rows)} "
        f"| {min(gaps):.2f} m | {statistics.median(times) if times else float('nan'):.1f} s "
        f"| {sum(r['charge_trips'] or 0 for r in rows)} | {statistics.median(r['cpu_s'] for r in rows):.2f} s |"
    )


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--seeds", type=int, default=30)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--robots", nargs="*", default=None, help="robot names (default: every registered robot)")
    ap.add_argument("--json", default=str(OUT / "robots.json"))
    args = ap.parse_args()
    robots = args.robots or robot_names()
    jobs = [(r, s, m, seed) for r in robots for s in SCENARIOS for m in MODELS for seed in range(args.seeds)]
    with ProcessPoolExecutor(args.workers) as pool:
        rows = list(pool.map(one, jobs, chunksize=3))
    print(
        "| robot | scenario | model | completed | contacts (robot on person / person on robot) | passes | waits "
        "| closest gap | robot finishes (median) | charge trips | CPU per trial |"
    )
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in robots:
        for s in SCENARIOS:
            for m in MODELS:
                print(
                    f"| {r} | {s} | {m} "
                    + line([x for x in rows if (x["robot"], x["scenario"], x["model"]) == (r, s, m)])
                )
    save(rows, args.json)


if __name__ == "__main__":
    main()
