"""ROS simulator node: achieved /odom rate and real-time factor at real_time_factor 1 and 10.

Starts `haven_sim.nodes.sim_node` as its own process (small_test world, 50 Hz physics), subscribes to
/odom from this process, and after a warm-up counts messages for `--seconds` of wall time:
  * wall rate = messages / wall seconds (target 50 x rtf),
  * sim rate  = messages / sim seconds spanned by their stamps (target 50: no step skipped),
  * achieved rtf = sim seconds spanned / wall seconds.
The node's CPU use over the window is read from /proc.

usage: python bench/odom_rate.py [--seconds 20] [--rtf 1 10]
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "haven_sim" / "test"))
import itertools

from common import OUT, save
from ros_harness import RosHarness


def cpu_seconds(pid: int) -> float:
    fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def measure(rtf: float, seconds: float) -> dict[str, float]:
    ros = RosHarness()
    try:
        received = ros.stamps("/odom", "nav_msgs/msg/Odometry")  # (arrival, header stamp) per message
        proc = ros.start("haven_sim.nodes.sim_node", {"real_time_factor": rtf})
        ros.spin_until(lambda: len(received) > 50, 30)
        ros.spin_for(2.0)  # warm-up
        n0, cpu0, t0 = len(received), cpu_seconds(proc.pid), time.monotonic()
        ros.spin_for(seconds)
        n1, cpu1, t1 = len(received), cpu_seconds(proc.pid), time.monotonic()
        arrivals = [a for a, _ in received[n0:n1]]
        window = [s for _, s in received[n0:n1]]
        wall = arrivals[-1] - arrivals[0]
        sim = window[-1] - window[0]
        gaps = [b - a for a, b in itertools.pairwise(window)]
        arrived = sorted(b - a for a, b in itertools.pairwise(arrivals))
        return {
            "rtf_requested": rtf,
            "messages": len(window),
            "wall_s": round(t1 - t0, 3),
            "wall_rate_hz": round((len(window) - 1) / wall, 2),
            "sim_rate_hz": round((len(window) - 1) / sim, 3),
            "rtf_achieved": round(sim / wall, 3),
            "max_sim_gap_s": round(max(gaps), 4),
            "arrival_gap_p50_ms": round(1e3 * arrived[len(arrived) // 2], 2),
            "arrival_gap_p99_ms": round(1e3 * arrived[int(0.99 * (len(arrived) - 1))], 2),
            "node_cpu_percent": round(100 * (cpu1 - cpu0) / (t1 - t0), 1),
        }
    finally:
        ros.close()


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--seconds", type=float, default=20.0)
    ap.add_argument("--rtf", type=float, nargs="+", default=[1.0, 10.0])
    ap.add_argument("--json", default=str(OUT / "odom_rate.json"))
    args = ap.parse_args()
    rows = []
    for rtf in args.rtf:
        row = measure(rtf, args.seconds)
        rows.append(row)
        target = 50.0 * rtf
        print(
            f"rtf {rtf:>4g}: /odom {row['wall_rate_hz']:8.2f} Hz wall (target {target:g}, "
            f"{100 * (row['wall_rate_hz'] / target - 1):+.2f} %), {row['sim_rate_hz']:.2f} Hz sim, "
            f"achieved rtf {row['rtf_achieved']:.3f}, largest stamp gap {row['max_sim_gap_s']} s, "
            f"arrival gaps p50 {row['arrival_gap_p50_ms']} ms p99 {row['arrival_gap_p99_ms']} ms, "
            f"node CPU {row['node_cpu_percent']} %"
        )
    save(rows, args.json)


if __name__ == "__main__":
    main()
