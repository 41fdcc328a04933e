"""A lockstep trial under a /goal_pose flood (issue 21): its wall time and its metrics against the
same trial alone. The flood is another process sending geometry_msgs/PoseStamped goals at `--hz`
for `--seconds`, from the moment the suite's planner reads /goal_pose (a hostile neighbour, or RViz's
"2D Goal Pose" held down). Each trial is `haven run SCENARIO --seed 0` on a domain of its own.

usage: python bench/flood.py [--scenario hallway] [--hz 1000] [--seconds 10] [--runs 3]
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))
from common import OUT, save

FLOOD = Path(__file__).resolve().parents[1] / "haven_scenarios" / "test" / "flood.py"
SAME = (
    "robot_time_to_finish_s",
    "min_human_centre_distance_m",
    "robot_path_length_m",
    "replans",
    "waits",
    "duration_s",
)


def trial(scenario: str, domain: int, flood: tuple[float, float] | None) -> dict[str, Any]:
    env = {**os.environ, "ROS_DOMAIN_ID": str(domain), "ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST"}
    with tempfile.TemporaryDirectory() as tmp:
        flooder = None
        if flood is not None:
            flooder = subprocess.Popen(
                [sys.executable, str(FLOOD), str(flood[0]), str(flood[1])], env=env, stdout=subprocess.PIPE, text=True
            )
        start = time.monotonic()
        r = subprocess.run([sys.executable, "-m", "haven_scenarios", "run", scenario,
                            "--domain-id", str(domain), "--sessions", tmp],
                           env=env, capture_output=True, text=True, timeout=1800)  # fmt: skip
        wall = time.monotonic() - start
        sent = flooder.communicate(timeout=120)[0].strip() if flooder is not None else ""
        (folder,) = [p for p in Path(tmp).iterdir() if p.is_dir()]
        m = json.loads((folder / "metrics.json").read_text())
        events = [json.loads(line) for line in (folder / "events.jsonl").read_text().splitlines()]
    ignored = sum(e.get("ignored", 0) for e in events if e["type"] == "outside_input")
    return {
        "exit": r.returncode,
        "wall_s": wall,
        "valid": m["valid"],
        "ignored": ignored,
        "sent": sent,
        **{k: m.get(k) for k in SAME},
    }


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--scenario", default="hallway")
    ap.add_argument("--hz", type=float, default=1000.0)
    ap.add_argument("--seconds", type=float, default=10.0)
    ap.add_argument("--runs", type=int, default=3)
    args = ap.parse_args()
    rows = []
    for k in range(args.runs):
        for flood in (None, (args.hz, args.seconds)):
            row = {
                "run": k,
                "flood": "alone" if flood is None else f"{args.hz:g} Hz x {args.seconds:g} s",
                **trial(args.scenario, 150 + k, flood),
            }
            rows.append(row)
            print(json.dumps(row), flush=True)
    alone = [r for r in rows if r["flood"] == "alone"]
    flooded = [r for r in rows if r["flood"] != "alone"]
    same = all(all(f[key] == alone[0][key] for key in SAME) for f in flooded + alone)
    print(f"\n{args.scenario}, {args.runs} runs each: "
          f"alone median {statistics.median(r['wall_s'] for r in alone):.1f} s wall, "
          f"flooded median {statistics.median(r['wall_s'] for r in flooded):.1f} s "
          f"(max {max(r['wall_s'] for r in flooded):.1f} s); "
          f"every trial the same: {same}; all valid: {all(r['valid'] for r in rows)}; "
          f"goals ignored per flooded trial: {[r['ignored'] for r in flooded]}")  # fmt: skip
    save(rows, OUT / "flood.json")


if __name__ == "__main__":
    main()
