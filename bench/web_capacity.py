"""How many live browser trials one machine holds: N `haven run shared_room --teleop h1 --web` at
1x at once (each its own ROS domain and processes), each driven by a participant's page played by
bench/web_wire.py's WebSocket client through that trial's front door (participants' browsers run on
their own devices in a study, so the server's part of the loop is what this machine decides):
velocity sent -> moved pose back, its p95 per N; and each live trial's memory, as the proportional
set size (PSS: shared pages split among their users, from /proc/<pid>/smaps_rollup) of its
processes summed, the honest share of one trial when several run.

usage: python bench/web_capacity.py [--trials 1 2 3] [--presses 20]
"""

from __future__ import annotations

import argparse
import asyncio
import os
import re
import signal
import statistics
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from common import OUT, save
from web_wire import HAVEN, measure

GOAL_P95_MS = 100.0  # the bar for a live trial


def tree(pid: int) -> list[int]:
    """`pid` and every process below it."""
    children: dict[int, list[int]] = {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/stat") as f:
                    ppid = int(f.read().rsplit(")", 1)[1].split()[1])
            except (OSError, IndexError, ValueError):
                continue
            children.setdefault(ppid, []).append(int(entry))
    out, todo = [], [pid]
    while todo:
        p = todo.pop()
        out.append(p)
        todo += children.get(p, [])
    return out


def pss_mb(pids: list[int]) -> float:
    total = 0
    for p in pids:
        try:
            with open(f"/proc/{p}/smaps_rollup") as f:
                for line in f:
                    if line.startswith("Pss:"):
                        total += int(line.split()[1])
        except OSError:
            continue
    return total / 1024


def start(k: int) -> tuple[subprocess.Popen[str], dict[str, str]]:
    argv = [*HAVEN, "run", "shared_room", "--teleop", "h1", "--web", "--port", "0", "--researcher-start"]
    argv += ["--sessions", str(OUT / "web_sessions"), "--domain-id", str(70 + k)]
    proc = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, start_new_session=True)
    urls: dict[str, str] = {}
    while len(urls) < 2:
        line = proc.stdout.readline() if proc.stdout else ""
        if not line and proc.poll() is not None:
            raise RuntimeError(f"trial {k} ended before its pages were served")
        m = re.search(r"web: (participant h1|researcher console): (\S+)", line)
        if m:
            urls[m.group(1)] = m.group(2)
    return proc, urls


async def all_of(urls: list[dict[str, str]], presses: int) -> list[list[float]]:
    return list(await asyncio.gather(*(measure(u, presses) for u in urls)))


def run(n: int, presses: int) -> dict[str, object]:
    trials = []
    try:
        # one at a time: those started before a failure are still stopped below
        trials.extend(start(k) for k in range(n))
        lat = asyncio.run(all_of([u for _, u in trials], presses))
        memory = [pss_mb(tree(p.pid)) for p, _ in trials]
    finally:
        for p, _ in trials:
            os.killpg(p.pid, signal.SIGINT)
        for p, _ in trials:
            p.communicate(timeout=90)
    every = [x for trial in lat for x in trial]
    p95 = statistics.quantiles(every, n=20)[18]
    return {
        "trials": n,
        "median_ms": statistics.median(every),
        "p95_ms": p95,
        "pss_mb_per_trial": memory,
        "latencies_ms": lat,
    }


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--trials", type=int, nargs="+", default=[1, 2, 3])
    ap.add_argument("--presses", type=int, default=20)
    a = ap.parse_args()
    rows = []
    for n in a.trials:
        row = run(n, a.presses)
        rows.append(row)
        mem = row["pss_mb_per_trial"]
        verdict = "holds" if row["p95_ms"] <= GOAL_P95_MS else "misses"
        print(
            f"{n} live trial(s): velocity -> pose back median {row['median_ms']:.0f} ms, "
            f"p95 {row['p95_ms']:.0f} ms ({verdict} {GOAL_P95_MS:g} ms); "
            f"memory per trial (PSS) {', '.join(f'{m:.0f}' for m in mem)} MB"
        )
    save(rows, OUT / "web_capacity.json")


if __name__ == "__main__":
    main()
