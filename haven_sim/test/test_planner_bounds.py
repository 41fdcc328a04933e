"""The built-in planner's time and memory are bounded: its visibility graph is built only for a map
within `MAX_PLANNER_NODES` corners and `MAX_SIGHT_WORK` line-of-sight samples (else a plan is
refused in one line, and a world is refused where it is validated), and line of sight is tested a
bounded number of samples at a time."""

import subprocess
import sys
import textwrap

import numpy as np
import pytest
from PIL import Image

from haven_sim.nav import planner as planner_module
from haven_sim.nav.planner import (
    MAX_PLANNER_NODES,
    MAX_SIGHT_WORK,
    GridPlanner,
    PlanningError,
    check_plannable,
    sight_work,
)
from haven_sim.sim.occupancy import OccupancyGridData
from haven_sim.sim.world import WorldError
from haven_sim.sim.world_file import load_world


def pillars(cells: int, every: int, resolution: float = 0.05) -> OccupancyGridData:
    """A walled square map with one-cell pillars every `every` cells (4 corners each, inflated)."""
    data = np.zeros((cells, cells), np.int8)
    data[:2], data[-2:], data[:, :2], data[:, -2:] = 100, 100, 100, 100
    data[every:-every:every, every:-every:every] = 100
    return OccupancyGridData(resolution, cells, cells, 0.0, 0.0, data)


def test_line_of_sight_in_bounded_chunks_gives_the_same_answers(monkeypatch):
    planner = GridPlanner(pillars(120, 15))
    rng = np.random.default_rng(3)
    a, b = rng.uniform(0.0, 6.0, (300, 2)), rng.uniform(0.0, 6.0, (300, 2))
    whole = planner.visible(a, b)
    monkeypatch.setattr(planner_module, "MAX_SIGHT_SAMPLES", 500)  # ~2 segments a chunk
    assert np.array_equal(planner.visible(a, b), whole) and 0 < whole.sum() < len(whole)
    assert len(planner.visible(a[:0], b[:0])) == 0


def test_a_map_past_the_caps_is_refused_at_the_first_plan_in_one_line():
    grid = pillars(400, 14)  # 27 x 27 pillars: 2,916 corners
    planner = GridPlanner(grid)  # the geometry (free runs, sight) is there for any map
    assert len(planner.nodes) > MAX_PLANNER_NODES and planner.is_free(0.4, 0.4)
    assert planner.plan((0.4, 0.4), (0.4, 5.0)).length_m == pytest.approx(4.6)  # in sight: no graph needed
    with pytest.raises(PlanningError) as e:
        planner.plan((0.4, 0.4), (19.6, 19.6))
    said = str(e.value)
    assert (
        f"the map has {len(planner.nodes):,} corners" in said
        and f"at most {MAX_PLANNER_NODES:,}" in said
        and "\n" not in said
    ), said
    assert planner._graph is None  # nothing N x N was made


def test_the_sight_work_cap_scales_with_the_map():
    assert sight_work(200, pillars(400, 40)) < MAX_SIGHT_WORK < sight_work(200, pillars(4000, 400, 0.025))
    big = GridPlanner(pillars(4000, 400, 0.025))  # 100 m: 81 pillars, 324 corners, far apart
    assert len(big.nodes) < MAX_PLANNER_NODES
    with pytest.raises(PlanningError, match="corner pairs x the map's diagonal"):
        big.plan((0.5, 0.5), (99.0, 99.0))


def test_a_world_past_the_caps_is_refused_naming_the_world(tmp_path):
    grid = pillars(400, 14)
    Image.fromarray(np.where(grid.data[::-1] >= 50, 0, 254).astype(np.uint8)).save(tmp_path / "dots.pgm")
    (tmp_path / "dots.yaml").write_text(
        "name: dots\nmap: {image: dots.pgm, resolution: 0.05}\nrobot: {start: [0.4, 0.4, 0.0]}\n"
    )
    world = load_world(tmp_path / "dots.yaml")
    with pytest.raises(WorldError) as e:
        check_plannable(world, "dots.yaml")
    said = str(e.value)
    assert (
        said.startswith("dots.yaml: world dots: the map has ")
        and f"at most {MAX_PLANNER_NODES:,}" in said
        and "\n" not in said
    ), said


# Peak resident memory of the child itself (VmHWM), as test_map_bounds measures the loader.
PLAN = textwrap.dedent(
    """
    import sys, time
    from haven_sim.nav.planner import GridPlanner, PlanningError, check_plannable
    from haven_sim.sim.occupancy import rasterise
    from haven_sim.sim.world import WorldError
    from haven_sim.sim.world_file import load_world
    world = load_world(sys.argv[1])
    t0 = time.perf_counter()
    try:
        check_plannable(world, "pillars.yaml")
        said = "plannable"
    except WorldError as e:
        said = f"refused: {e}"
    t1 = time.perf_counter()
    try:
        GridPlanner(rasterise(world)).plan((1.0, 1.0), (98.0, 97.0))
        planned = "planned"
    except PlanningError as e:
        planned = f"plan refused: {e}"
    t2 = time.perf_counter()
    peak_kb = next(int(line.split()[1]) for line in open("/proc/self/status") if line.startswith("VmHWM:"))
    print(t1 - t0, t2 - t1, peak_kb / 1024, said, planned, sep="\\t")
    """
)


@pytest.mark.integration
def test_the_pillar_map_is_refused_in_one_line_within_10_s_and_500_mb(tmp_path):
    """bench/map_bounds.py's 9,504-box pillar map (100 m, the most boxes the loader takes): the
    world check and the planner each refuse it in one line, without building its 38,000-node graph."""
    building = np.full((4000, 4000), 254, np.uint8)
    building[:8], building[-8:], building[:, :8], building[:, -8:] = 0, 0, 0, 0
    building[100:3880:40, 100:3900:38] = 0
    Image.fromarray(building).save(tmp_path / "pillars.pgm")
    (tmp_path / "pillars.yaml").write_text(
        "name: pillars\nmap: {image: pillars.pgm, resolution: 0.025}\nrobot: {start: [1.0, 1.0, 0.0]}\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", PLAN, str(tmp_path / "pillars.yaml")],
        capture_output=True,
        text=True,
        timeout=300,
        check=True,
    )
    check_s, plan_s, peak_mb, said, planned = out.stdout.strip().split("\t")
    assert (
        said.startswith("refused: pillars.yaml: world pillars: the map has ")
        and f"at most {MAX_PLANNER_NODES:,}" in said
    ), said
    assert planned.startswith("plan refused: the map has ") and "corners for the built-in planner" in planned, planned
    assert float(check_s) < 10.0 and float(plan_s) < 10.0 and float(peak_mb) < 500.0, (check_s, plan_s, peak_mb)
