"""A world from a ROS map at scale: the peers' W1 map (bench/w1_map.py, 20 m x 20 m) drawn into a
400 x 400-cell map_server PGM at 0.05 m/cell, clean and with SLAM-like ragged wall edges (seeded
single cells stuck to the walls' faces, as a scan-built map has), then read as a HAVEN world
(`map_image.read_image` + `wall_boxes`, the world file's `map:`). Reports the wall boxes the merge
makes, the time to read and merge, and the simulator (physics + 10 Hz scan, 1 human) and the
planner on that world against W1 drawn from its own 13 wall rectangles.

usage: python bench/map_walls.py [--steps 3000] [--repeats 3] [--n 200]
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import yaml
from PIL import Image

sys.path.insert(0, str(Path(__file__).resolve().parent))
from common import OUT, save
from planner_latency import run as plan_run
from sim_speed import run_case
from w1_map import ROOMS, human_rooms, w1_world

from haven_sim.sim.map_image import read_image, wall_boxes
from haven_sim.sim.occupancy import rasterise
from haven_sim.sim.world import World
from haven_sim.sim.world_file import load_world

RESOLUTION = 0.05  # m/cell: map_saver's usual (slam_toolbox's default `resolution`)
RAGGED_FRACTION = 0.05  # of the free cells along a wall's face made occupied


def map_pixels(ragged: bool, seed: int = 0) -> np.ndarray:
    """W1 as a map_saver PGM (0 occupied, 254 free), row 0 the top; 400 x 400 cells."""
    grid = rasterise(w1_world(0), RESOLUTION, padding_m=0.0)
    occupied = grid.data[::-1] > 0  # /map rows are bottom-up, an image's top-down
    if ragged:
        rng = np.random.default_rng(seed)
        near = np.zeros_like(occupied)
        near[1:] |= occupied[:-1]
        near[:-1] |= occupied[1:]
        near[:, 1:] |= occupied[:, :-1]
        near[:, :-1] |= occupied[:, 1:]
        face = near & ~occupied
        occupied = occupied | (face & (rng.random(occupied.shape) < RAGGED_FRACTION))
    return np.where(occupied, 0, 254).astype(np.uint8)


def map_world(folder: Path, pixels: np.ndarray) -> World:
    """The PGM, its map_server YAML and an overlay (W1's rooms, robot and one human) in `folder`."""
    Image.fromarray(pixels).save(folder / "w1.pgm")
    settings = {"image": "w1.pgm", "mode": "trinary", "resolution": RESOLUTION, "origin": [0.0, 0.0, 0.0], "negate": 0}
    (folder / "w1.yaml").write_text(yaml.safe_dump(settings | {"occupied_thresh": 0.65, "free_thresh": 0.25}))
    overlay = {
        "name": "w1_from_map",
        "map": "w1.yaml",
        "rooms": [{"name": n, "centre": [(r[0] + r[2]) / 2, (r[1] + r[3]) / 2]} for n, r in ROOMS.items()],
        "robot": {"start": [5.0, 2.5, 0.0]},
        "humans": [{"id": h.id, "start": [h.start.x, h.start.y, h.start.yaw]} for h in w1_world(1).humans],
    }
    (folder / "world.yaml").write_text(yaml.safe_dump(overlay))
    return load_world(folder / "world.yaml")


def measure(name: str, pixels: np.ndarray, folder: Path, steps: int, repeats: int, n: int) -> dict[str, object]:
    Image.fromarray(pixels).save(folder / "probe.pgm")
    t0 = time.perf_counter()
    image = read_image(folder / "probe.pgm", RESOLUTION)
    t1 = time.perf_counter()
    boxes = wall_boxes(image)
    t2 = time.perf_counter()
    world = map_world(folder, pixels)
    t3 = time.perf_counter()
    return {
        "map": name,
        "cells": int(pixels.size),
        "blocked_cells": int(image.blocked.sum()),
        "boxes": len(boxes),
        "read_ms": 1e3 * (t1 - t0),
        "merge_ms": 1e3 * (t2 - t1),
        "load_world_ms": 1e3 * (t3 - t2),
        **sim_speed(world, steps, repeats),
        "planner": plan_run(name, world, n, 0, None),
    }


def sim_speed(world: World, steps: int, repeats: int) -> dict[str, float]:
    """Physics + a 10 Hz scan with one human walking (bench/sim_speed.py's case), best and median of `repeats`."""
    runs = sorted((run_case(world, human_rooms(1), 5, steps) for _ in range(repeats)), key=lambda r: float(r["rtf"]))  # type: ignore[arg-type]
    return {"sim_rtf_best": float(runs[-1]["rtf"]), "sim_rtf_median": float(runs[len(runs) // 2]["rtf"])}  # type: ignore[arg-type]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--steps", type=int, default=3000)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--n", type=int, default=200, help="planner start/goal pairs")
    ap.add_argument("--json", default=str(OUT / "map_walls.json"))
    args = ap.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, ragged in (("W1 map, clean", False), ("W1 map, ragged", True)):
            rows.append(measure(name, map_pixels(ragged), Path(tmp), args.steps, args.repeats, args.n))
    rows.append({"map": "W1 walls (13 rectangles)", **sim_speed(w1_world(1), args.steps, args.repeats)})
    rows[-1]["planner"] = plan_run("W1 walls", w1_world(0), args.n, 0, None)
    for r in rows:
        p = r["planner"]
        if "boxes" in r:
            print(f"{r['map']}: {r['boxes']} boxes of {r['blocked_cells']} blocked cells", end="; ")
            print(f"read {r['read_ms']:.0f} ms, merge {r['merge_ms']:.0f} ms, load {r['load_world_ms']:.0f} ms")
        print(f"{r['map']}: sim RTF best {r['sim_rtf_best']:.0f} median {r['sim_rtf_median']:.0f}")
        print(
            f"{r['map']}: planner preprocess {p['preprocess_ms']:.0f} ms "  # type: ignore[index]
            f"({p['corner_nodes']} nodes), plan median {p['median_ms']:.2f} ms "  # type: ignore[index]
            f"p99 {p['p99_ms']:.2f} ms, refused {p['refused']}, min clearance {p['min_wall_clearance_m']:.3f} m"  # type: ignore[index]
        )
    save(rows, args.json)


if __name__ == "__main__":
    main()
