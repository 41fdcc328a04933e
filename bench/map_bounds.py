"""Map inputs at their limits: the largest map a world may have (4,000 x 4,000 cells of 0.025 m,
100 m), loaded through a world file's `map:` by the real loader, each case in its own process
(wall time, and peak resident memory as the kernel's VmHWM of that process):

- a checkerboard PGM (8 million one-cell wall boxes): refused past `MAX_WALL_BOXES` (10,000);
- a building with pillars, just under the cap (9,504 boxes): loaded, then what a trial builds
  from it (physics + scan, 500 steps with 100 scans), its /map grid and `haven world show`'s picture;
- a FIFO named as the map image: refused without being opened;
- the built-in planner on the pillar map (38,000 corners: its world check and a plan refused in one
  line), and at its cap (`planner.MAX_SIGHT_WORK`): 100 corners spread over the 100 m map, ~300 over
  a 10 m one (graph build and a plan).

usage: python bench/map_bounds.py [--json bench/out/map_bounds.json]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import textwrap
from pathlib import Path

import numpy as np
from PIL import Image

sys.path.insert(0, str(Path(__file__).resolve().parent))
from common import OUT, save

CELLS, RESOLUTION = 4000, 0.025

CHILD = textwrap.dedent(
    """
    import json, sys, time
    from pathlib import Path

    def peak_mb():
        return next(int(line.split()[1]) for line in open("/proc/self/status") if line.startswith("VmHWM:")) / 1024

    out = {}
    t0 = time.perf_counter()
    from haven_sim.sim.world import WorldError
    from haven_sim.sim.world_file import load_world
    t1 = time.perf_counter()
    try:
        world = load_world(sys.argv[1])
    except WorldError as e:
        out.update(result="refused", line=str(e))
    else:
        out.update(result="loaded", walls=len(world.walls))
    out.update(import_s=t1 - t0, load_s=time.perf_counter() - t1, load_peak_mb=peak_mb())
    if out["result"] == "loaded" and sys.argv[2:] == ["--downstream"]:
        from haven_sim.common.geometry import Twist2D
        from haven_sim.sim.occupancy import rasterise
        from haven_sim.sim.simulation import Simulation
        from haven_scenarios.tools.commands.world import draw
        t = time.perf_counter(); sim = Simulation(world); out["simulation_build_s"] = time.perf_counter() - t
        t = time.perf_counter()
        for k in range(500):
            sim.command_robot(Twist2D(0.5, 0.0, 0.3)); sim.step()
            if k % 5 == 0:
                sim.scan()
        out["steps_500_s"] = time.perf_counter() - t
        t = time.perf_counter(); rasterise(world); out["map_grid_s"] = time.perf_counter() - t
        t = time.perf_counter(); draw(world, Path(sys.argv[1]).with_suffix(".png")); \
out["world_show_picture_s"] = time.perf_counter() - t
        out["total_peak_mb"] = peak_mb()
    print(json.dumps(out))
    """
)


PLANNER = textwrap.dedent(
    """
    import json, sys, time
    import numpy as np
    from haven_sim.nav.planner import GridPlanner, PlanningError, check_plannable, sight_work
    from haven_sim.sim.occupancy import OccupancyGridData, rasterise
    from haven_sim.sim.world import WorldError
    from haven_sim.sim.world_file import load_world

    def peak_mb():
        return next(int(line.split()[1]) for line in open("/proc/self/status") if line.startswith("VmHWM:")) / 1024

    out = {}
    if sys.argv[1].endswith(".yaml"):
        world = load_world(sys.argv[1])
        t = time.perf_counter()
        try:
            check_plannable(world, sys.argv[1]); out["world_check"] = "plannable"
        except WorldError as e:
            out["world_check"] = str(e)
        out["world_check_s"] = time.perf_counter() - t
        grid, goal = rasterise(world), (98.0, 97.0)
    else:  # pillars every `step` cells on a square map of `cells` cells of 0.025 m
        cells, k = (int(v) for v in sys.argv[1:3])
        data = np.zeros((cells, cells), np.int8)
        data[:8], data[-8:], data[:, :8], data[:, -8:] = 100, 100, 100, 100
        m = cells // 20; step = (cells - 2 * m) // k
        for r in range(k):
            for c in range(k):
                data[m + r * step, m + c * step + (r % 2) * step // 3] = 100
        grid, goal = OccupancyGridData(0.025, cells, cells, 0.0, 0.0, data), (cells * 0.025 - 1.0, cells * 0.025 - 1.5)
    t = time.perf_counter(); planner = GridPlanner(grid); out["grid_s"] = time.perf_counter() - t
    out.update(corners=len(planner.nodes), sight_work=sight_work(len(planner.nodes), grid))
    t = time.perf_counter()
    try:
        out["plan"] = f"{planner.plan((1.0, 1.0), goal).length_m:.2f} m"
    except PlanningError as e:
        out["plan"] = f"refused: {e}"
    out.update(first_plan_s=time.perf_counter() - t, peak_mb=peak_mb())
    print(json.dumps(out))
    """
)


def world(folder: Path, name: str, pixels: np.ndarray | None) -> Path:
    if pixels is not None:
        Image.fromarray(pixels).save(folder / f"{name}.pgm")
    else:
        os.mkfifo(folder / f"{name}.pgm")
    text = f"name: {name}\nmap: {{image: {name}.pgm, resolution: {RESOLUTION}}}\nrobot: {{start: [1.0, 1.0, 0.0]}}\n"
    (folder / f"{name}.yaml").write_text(text)
    return folder / f"{name}.yaml"


def run(path: Path, downstream: bool, child: str = CHILD, *more: str) -> dict[str, object]:
    cmd = [sys.executable, "-c", child, str(path), *more] + (["--downstream"] if downstream else [])
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=600, check=True)
    result: dict[str, object] = json.loads(done.stdout)
    return result


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--json", default=str(OUT / "map_bounds.json"))
    args = ap.parse_args()
    rows, cols = np.indices((CELLS, CELLS))
    checker = np.where((rows + cols) % 2 == 0, 0, 254).astype(np.uint8)
    del rows, cols
    building = np.full((CELLS, CELLS), 254, np.uint8)
    building[:8], building[-8:], building[:, :8], building[:, -8:] = 0, 0, 0, 0
    building[100:3880:40, 100:3900:38] = 0  # 95 x 100 one-cell pillars and the 4 outer walls: 9,504 boxes
    out = {}
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        cases = {"checkerboard": (checker, False), "pillars": (building, True), "fifo": (None, False)}
        for name, (pixels, downstream) in cases.items():
            out[name] = run(world(folder, name, pixels), downstream)
            print(name, json.dumps(out[name]), flush=True)
        out["planner: pillars"] = run(folder / "pillars.yaml", False, PLANNER)
        out["planner: 100 m, at the cap"] = run(Path("4000"), False, PLANNER, "5")
        out["planner: 10 m, at the cap"] = run(Path("400"), False, PLANNER, "9")
        for name in [k for k in out if k.startswith("planner")]:
            print(name, json.dumps(out[name]), flush=True)
    save(out, args.json)


if __name__ == "__main__":
    main()
