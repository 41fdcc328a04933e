"""A world from a ROS map against the same world written by hand: HAVEN's hallway world rasterised
into a map_server PGM (0.05 m cells, as map_saver would save a map of it) and made a world again
with an overlay of the same rooms, hallways and starts (`map:`). How many wall boxes the map
becomes, how long loading it takes, and batch trials on both (CPU per trial and the outcome).

usage: python bench/map_world.py [--trials 10]
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

import numpy as np
import yaml
from PIL import Image

sys.path.insert(0, str(Path(__file__).resolve().parent))
from common import OUT, save

from haven_scenarios.run.trial import run_trial
from haven_scenarios.study.scenario import load_scenario
from haven_sim.sim.occupancy import rasterise
from haven_sim.sim.world_file import load_world


def map_version(folder: Path) -> Path:
    """The hallway scenario on a map of its world: PGM + map YAML + overlay + scenario."""
    scenario = load_scenario("hallway")
    grid = rasterise(scenario.world)
    pixels = np.where(grid.data[::-1] >= 50, 0, 254).astype(np.uint8)  # image row 0 is the top
    Image.fromarray(pixels).save(folder / "hallway_map.pgm")
    meta = {
        "image": "hallway_map.pgm",
        "mode": "trinary",
        "resolution": grid.resolution_m,
        "origin": [grid.origin_x, grid.origin_y, 0.0],
    }
    meta |= {"negate": 0, "occupied_thresh": 0.65, "free_thresh": 0.25}
    (folder / "hallway_map.yaml").write_text(yaml.safe_dump(meta))
    world = yaml.safe_load(Path(scenario.world_path).read_text())
    world.pop("walls")
    world["map"] = "hallway_map.yaml"
    (folder / "world.yaml").write_text(yaml.safe_dump(world, sort_keys=False))
    data = yaml.safe_load(Path(scenario.source).read_text())
    data["world"] = "world.yaml"
    (folder / "scenario.yaml").write_text(yaml.safe_dump(data, sort_keys=False))
    return folder / "scenario.yaml"


def trials(spec: str, n: int) -> dict[str, Any]:
    t0 = time.perf_counter()
    scenario = load_scenario(spec)
    load_s = time.perf_counter() - t0
    cpu, outcomes = [], []
    for seed in range(n):
        c0 = time.process_time()
        m = run_trial(scenario, seed).metrics
        cpu.append(time.process_time() - c0)
        outcomes.append(
            (m["end_reason"], m["human_contacts"], m["min_human_centre_distance_m"], m["robot_time_to_finish_s"])
        )
    return {
        "walls": len(scenario.world.walls),
        "load_s": round(load_s, 3),
        "cpu_per_trial_s": round(float(np.median(cpu)), 2),
        "completed": sum(o[0] == "completed" for o in outcomes),
        "contacts": sum(o[1] for o in outcomes),
        "closest_m": round(min(o[2] for o in outcomes), 3),
        "robot_time_s": round(float(np.mean([o[3] for o in outcomes if o[3] is not None])), 1),
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--trials", type=int, default=10)
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        rows = {
            "hand-written": trials("hallway", args.trials),
            "from a map": trials(str(map_version(Path(tmp))), args.trials),
        }
        load_world(Path(tmp) / "world.yaml")
    print(
        f"{'hallway world':<14} {'walls':>6} {'load s':>7} {'CPU/trial s':>12} "
        f"{'completed':>10} {'contacts':>9} {'closest m':>10} {'robot s':>8}"
    )
    for name, r in rows.items():
        print(
            f"{name:<14} {r['walls']:>6} {r['load_s']:>7} {r['cpu_per_trial_s']:>12} "
            f"{r['completed']:>7}/{args.trials:<2} {r['contacts']:>9} {r['closest_m']:>10} {r['robot_time_s']:>8}"
        )
    save(rows, OUT / "map_world.json")


if __name__ == "__main__":
    main()
