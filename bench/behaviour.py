"""Behaviour sweep: seeded batch trials of every shipped scenario with each simulated participant
model (and, for the shared room, each battery mode x gem order), summarised the way an HRI
researcher would look at them: completion, end reasons, re-plans and waits, contacts by who caused
them, the passes (Figure 3) whose turn signal showed before the curve and by how long, and the
closest approach.

usage: python bench/behaviour.py [--seeds 30] [--workers 2] [--only hallway ...]
"""

from __future__ import annotations

import argparse
import statistics
import sys
from collections import Counter
from concurrent.futures import ProcessPoolExecutor
from dataclasses import replace
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))
from common import OUT, save

from haven_scenarios.run.trial import run_trial
from haven_scenarios.study.scenario import Scenario, load_scenario, scenario_names

MODELS = ("walker", "blocker", "yielder")
BATTERY = [(mode, order) for mode in ("on_arrival", "continuous") for order in ("nearest", "random")]


def variants() -> list[tuple[str, dict[str, str]]]:
    """(scenario, changes): each scenario with each model; the shared room also per battery mode x order."""
    out: list[tuple[str, dict[str, str]]] = []
    for name in scenario_names():
        out += [(name, {"model": m}) for m in MODELS]
        if name == "shared_room":
            out += [(name, {"model": "walker", "battery": mode, "order": order}) for mode, order in BATTERY]
    return out


def scenario_of(name: str, changes: dict[str, str]) -> Scenario:
    s = load_scenario(name)
    s = replace(s, humans=tuple(replace(h, model=changes["model"]) for h in s.humans))
    if "battery" in changes:
        s = replace(s, battery=replace(s.battery, mode=changes["battery"]), robot_order=changes["order"])
    return s


def one(job: tuple[str, dict[str, str], int]) -> dict[str, Any]:
    name, changes, seed = job
    m = run_trial(scenario_of(name, changes), seed).metrics
    keys = (
        "end_reason",
        "replans",
        "waits",
        "human_contacts",
        "human_contacts_robot_on_person",
        "human_contacts_person_on_robot",
        "turn_signal_lead_s_mean",
        "passes",
        "passes_signalled",
        "pass_signal_lead_s_median",
        "turns",
        "turns_signalled",
        "min_human_centre_distance_m",
        "charge_trips",
        "duration_s",
    )
    return {"scenario": name, "variant": " ".join(changes.values()), "seed": seed, **{k: m.get(k) for k in keys}}


def summary(rows: list[dict[str, Any]]) -> str:
    n = len(rows)
    ends = Counter(r["end_reason"] for r in rows)
    leads = [r["pass_signal_lead_s_median"] for r in rows if r["pass_signal_lead_s_median"] is not None]
    dmin = [r["min_human_centre_distance_m"] for r in rows if r["min_human_centre_distance_m"] is not None]
    return (
        f"completed {ends['completed']}/{n} "
        f"({', '.join(f'{k} {v}' for k, v in ends.items() if k != 'completed') or 'no other end'}); "
        f"re-plans {sum(r['replans'] for r in rows)}, waits {sum(r['waits'] for r in rows)}; "
        f"contacts {sum(r['human_contacts'] for r in rows)} (robot on person "
        f"{sum(r['human_contacts_robot_on_person'] for r in rows)}, "
        f"person on robot {sum(r['human_contacts_person_on_robot'] for r in rows)}); "
        f"passes {sum(r['passes'] for r in rows)}, signalled first {sum(r['passes_signalled'] for r in rows)} "
        f"(lead median {statistics.median(leads) if leads else float('nan'):.2f} s); "
        f"min distance {min(dmin) if dmin else float('nan'):.2f} m (median "
        f"{statistics.median(dmin) if dmin else float('nan'):.2f})"
    )


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--seeds", type=int, default=30)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--only", nargs="*", default=None, help="scenario names")
    ap.add_argument("--json", default=str(OUT / "behaviour.json"))
    args = ap.parse_args()
    groups = [(n, c) for n, c in variants() if not args.only or n in args.only]
    jobs = [(n, c, seed) for n, c in groups for seed in range(args.seeds)]
    with ProcessPoolExecutor(args.workers) as pool:
        rows = list(pool.map(one, jobs, chunksize=2))
    for name, changes in groups:
        label = " ".join(changes.values())
        mine = [r for r in rows if r["scenario"] == name and r["variant"] == label]
        print(f"{name:13} {label:28} {summary(mine)}")
    save(rows, args.json)


if __name__ == "__main__":
    main()
