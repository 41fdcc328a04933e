"""Planner latency on scenario-size maps: median and p99 over many random start/goal pairs.

Maps: the peers' W1/W2 20 m x 20 m rooms-and-hallway map (bench/w1_map.py; doors 1 m) rasterised
at 5 cm, and the small test world. Pairs are sampled uniformly in free space (seeded), or read from
--pairs (a JSON list of [[sx, sy], [gx, gy]], e.g. the peers' `common.sample_pairs(200, seed=0)`).
The robot is a disc of 0.18 m with a 0.05 m margin (the peers' 0.23 m inflation). Each query is
timed alone; the map preprocessing (inflation, corner graph, all-pairs paths) once. Every path is
checked against the world's true geometry: no point of it closer than the robot radius to a wall.
Also timed: the full goal handling of the planner node's core (plan + HAVEN path style).

usage: python bench/planner_latency.py [--n 200] [--seed 0] [--pairs pairs.json]
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import itertools

from common import OUT, save
from w1_map import w1_world

from haven_sim.common.geometry import Pose2D, distance_point_to_edges
from haven_sim.nav.navigator import Navigator
from haven_sim.nav.planner import GridPlanner, PlannerParams, PlanningError
from haven_sim.sim.occupancy import rasterise
from haven_sim.sim.world import World, packaged_world
from haven_sim.sim.world_file import load_world

PARAMS = PlannerParams(safety_margin_m=0.05, body_radius_m=0.18)  # the peers' robot: 0.23 m inflation


def sample_pairs(
    world: World, planner: GridPlanner, n: int, seed: int
) -> list[tuple[tuple[float, float], tuple[float, float]]]:
    """Uniform over the free space inside the world's walls (the grid also has free padding outside)."""
    rng = np.random.default_rng(seed)
    x0, y0, x1, y1 = world.bounds()
    pts: list[tuple[float, float]] = []
    while len(pts) < 2 * n:
        x, y = float(rng.uniform(x0, x1)), float(rng.uniform(y0, y1))
        if planner.is_free(x, y):
            pts.append((x, y))
    return [(pts[2 * i], pts[2 * i + 1]) for i in range(n)]


def clearance(world: World, path: list[tuple[float, float]]) -> float:
    edges = world.edges()
    worst = np.inf
    for a, b in itertools.pairwise(path):
        n = max(2, int(np.hypot(b[0] - a[0], b[1] - a[1]) / 0.02) + 1)
        for t in np.linspace(0.0, 1.0, n):
            worst = min(worst, distance_point_to_edges(a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, edges))
    return float(worst)


def stats(ms: list[float]) -> dict[str, float]:
    a = np.asarray(ms)
    return {
        "median_ms": float(np.median(a)),
        "p90_ms": float(np.percentile(a, 90)),
        "p99_ms": float(np.percentile(a, 99)),
        "max_ms": float(a.max()),
    }


def run(name: str, world: World, n: int, seed: int, pairs_file: str | None) -> dict[str, object]:
    grid = rasterise(world, 0.05)
    t0 = time.perf_counter()
    planner = GridPlanner(grid, PARAMS)
    _ = planner.dist  # the graph (else built at the first plan that needs it)
    pre = time.perf_counter() - t0
    pairs = sample_pairs(world, planner, n, seed)
    if pairs_file:
        pairs = [(tuple(s), tuple(g)) for s, g in json.loads(Path(pairs_file).read_text())]  # type: ignore[misc]
    lat, lengths, refused, worst = [], [], 0, np.inf
    for s, g in pairs:
        t = time.perf_counter()
        try:
            plan = planner.plan(s, g)
        except PlanningError:
            refused += 1
            continue
        lat.append(1e3 * (time.perf_counter() - t))
        lengths.append(plan.length_m)
        worst = min(worst, clearance(world, plan.points))
    nav = Navigator(grid, PARAMS)
    full = []
    for s, g in pairs[:100]:
        t = time.perf_counter()
        nav.set_goal(Pose2D(s[0], s[1], 0.0), Pose2D(g[0], g[1], 0.0), 0.0)
        full.append(1e3 * (time.perf_counter() - t))
    return {
        "map": name,
        "pairs": len(pairs),
        "refused": refused,
        "preprocess_ms": 1e3 * pre,
        "corner_nodes": len(planner.nodes),
        **stats(lat),
        "mean_length_m": float(np.mean(lengths)),
        "min_wall_clearance_m": worst,
        "with_path_style": stats(full),
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--n", type=int, default=200)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--pairs", default=None, help="JSON pairs for the W1 map (e.g. the peers' sample)")
    ap.add_argument("--json", default=str(OUT / "planner_latency.json"))
    args = ap.parse_args()
    rows = [
        run("W1 map 20x20", w1_world(0), args.n, args.seed, args.pairs),
        run("small test world", load_world(packaged_world("small_test")), args.n, args.seed, None),
    ]
    for r in rows:
        st = r["with_path_style"]
        print(
            f"{r['map']:18} pairs {r['pairs']} refused {r['refused']}  "
            f"preprocess {r['preprocess_ms']:.1f} ms ({r['corner_nodes']} nodes)  "
            f"plan median {r['median_ms']:.2f} ms p90 {r['p90_ms']:.2f} p99 {r['p99_ms']:.2f} max {r['max_ms']:.2f}  "
            f"mean length {r['mean_length_m']:.2f} m  min clearance {r['min_wall_clearance_m']:.3f} m  "
            f"| plan+style median {st['median_ms']:.2f} p99 {st['p99_ms']:.2f} ms"
        )  # type: ignore[index]
    save(rows, args.json)


if __name__ == "__main__":
    main()
