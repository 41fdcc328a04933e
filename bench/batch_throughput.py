"""Batch throughput (issue 15): shared_room trials per minute through `haven batch`'s runner with one
worker (in this process) and with every core (spawned worker processes), optionally on a Dask
LocalCluster too; the same seeds, and the CSVs checked byte-identical. Wall times include starting
the workers (imports), so short sweeps understate the steady rate.

Other jobs on a shared VM take cores from the workers, so the two sweeps run alternately --repeat times
and the table gives the best and the median of each (the load average is recorded with every run).

usage: python bench/batch_throughput.py [--trials 60] [--repeat 3] [--workers N] [--dask]
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))
from common import OUT, save

from haven_scenarios.run.batch import run_batch
from haven_scenarios.run.grid import plan_sweep
from haven_scenarios.run.sweep import LOCAL, cores
from haven_scenarios.study.scenario import load_scenario


def sweep(trials: int, workers: int, cluster: str | None, folder: Path) -> dict[str, Any]:
    specs = plan_sweep([load_scenario("shared_room")], {}, tuple(range(trials)))
    out = folder / f"w{workers}_{cluster or 'procs'}.csv"
    load0 = os.getloadavg()[0]
    cpu0, w0 = time.process_time(), time.perf_counter()
    run_batch(specs, out, workers=workers, cluster=cluster)
    wall, cpu = time.perf_counter() - w0, time.process_time() - cpu0
    return {
        "workers": workers,
        "where": "Dask LocalCluster" if cluster else ("this process" if workers == 1 else "spawned processes"),
        "trials": trials,
        "wall_s": round(wall, 2),
        "trials_per_min": round(60.0 * trials / wall, 1),
        "s_per_trial": round(wall / trials, 3),
        "parent_cpu_s": round(cpu, 2),
        "load_before": round(load0, 2),
        "load_after": round(os.getloadavg()[0], 2),
        "csv": out.read_bytes(),
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--trials", type=int, default=60)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--workers", type=int, default=cores())
    ap.add_argument("--dask", action="store_true", help="also on a Dask LocalCluster of --workers processes")
    ap.add_argument("--json", default=str(OUT / "batch_throughput.json"))
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        runs = []
        for _ in range(args.repeat):
            runs += [sweep(args.trials, 1, None, Path(tmp)), sweep(args.trials, args.workers, None, Path(tmp))]
        if args.dask:
            runs.append(sweep(args.trials, args.workers, LOCAL, Path(tmp)))
    reference = runs[0]["csv"]
    for r in runs:
        r["rows_identical_to_1_worker"] = r.pop("csv") == reference
        print(
            f"{r['workers']} worker(s), {r['where']:18} {r['trials']} trials in {r['wall_s']:6.1f} s "
            f"= {r['trials_per_min']:6.1f} trials/min ({r['s_per_trial']:.3f} s each), rows identical: "
            f"{r['rows_identical_to_1_worker']}, load {r['load_before']} -> {r['load_after']}"
        )
    rates = {
        w: sorted(r["trials_per_min"] for r in runs if r["where"] == w) for w in dict.fromkeys(r["where"] for r in runs)
    }
    one = rates["this process"]
    for where, rs in rates.items():
        best, median = rs[-1], rs[len(rs) // 2]
        up = f"speed-up best/best {best / one[-1]:.2f}x, median/median {median / one[len(one) // 2]:.2f}x"
        print(f"{where:18} best {best:6.1f} trials/min, median {median:6.1f}; {up}")
    save(runs, args.json)


if __name__ == "__main__":
    main()
