"""Map inputs are bounded: a map image is opened only when it is a regular file, the wall boxes are
the greedy boxes made in one pass and refused in one line past `MAX_WALL_BOXES`, a 4,000 x 4,000
map is refused or loaded within 10 s and 500 MB, and a map_server YAML given as a world says how
to make it one."""

import os
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np
import pytest
from map_maker import make_map_world
from PIL import Image

from haven_sim.sim.map_image import MAX_WALL_BOXES, MapImage, wall_boxes, wall_rectangles
from haven_sim.sim.world import WorldError
from haven_sim.sim.world_file import load_world


def refused(path, *words):
    with pytest.raises(WorldError) as e:
        load_world(path)
    said = str(e.value)
    assert "\n" not in said and all(w in said for w in words), said
    return said


def test_a_fifo_as_the_map_image_is_refused_without_being_opened(tmp_path):
    make_map_world(tmp_path)
    (tmp_path / "map.pgm").unlink()
    os.mkfifo(tmp_path / "map.pgm")

    def unblock():  # only if the loader opened the FIFO and waits for a writer: give it one
        fd = os.open(tmp_path / "map.pgm", os.O_WRONLY | os.O_NONBLOCK)
        os.close(fd)

    guard = threading.Timer(20.0, unblock)
    guard.start()
    try:
        t0 = time.monotonic()
        refused(tmp_path / "world.yaml", "map.pgm: image: cannot be read as an image: not a regular file")
        assert time.monotonic() - t0 < 10.0
    finally:
        guard.cancel()
    (tmp_path / "map.pgm").unlink()
    (tmp_path / "map.pgm").mkdir()
    refused(tmp_path / "world.yaml", "map.pgm: image: cannot be read as an image: a folder")


def test_only_the_map_image_formats_are_decoded(tmp_path):
    make_map_world(tmp_path)
    Image.open(tmp_path / "map.pgm").save(tmp_path / "map.tif")
    (tmp_path / "map.tif").rename(tmp_path / "map.pgm")  # a TIFF named .pgm: PIL would read it, a map is never one
    refused(tmp_path / "world.yaml", "map.pgm: image: cannot be read as an image: cannot identify image file")


def greedy(blocked):
    """The reference: the greedy maximal rectangles cell by cell (the loader's rule, written plainly)."""
    covered = np.zeros_like(blocked)
    boxes = []
    for r in range(blocked.shape[0]):
        c = 0
        while c < blocked.shape[1]:
            if not blocked[r, c] or covered[r, c]:
                c += 1
                continue
            c1 = c
            while c1 < blocked.shape[1] and blocked[r, c1] and not covered[r, c1]:
                c1 += 1
            r1 = r + 1
            while r1 < blocked.shape[0] and blocked[r1, c:c1].all() and not covered[r1, c:c1].any():
                r1 += 1
            covered[r:r1, c:c1] = True
            boxes.append((r, r1, c, c1))
            c = c1
    return boxes


def test_wall_boxes_are_the_greedy_rectangles(tmp_path):
    rng = np.random.default_rng(5)
    for trial in range(150):
        h, w = rng.integers(1, 30, 2)
        if trial % 3 == 0:
            blocked = rng.random((h, w)) < 0.5  # noise
        else:
            blocked = np.zeros((h, w), bool)
            for _ in range(rng.integers(0, 6)):  # walls and furniture
                r, c = rng.integers(0, h), rng.integers(0, w)
                blocked[r : r + rng.integers(1, 12), c : c + rng.integers(1, 12)] = True
            if trial % 3 == 2:
                blocked = np.repeat(blocked, 3, axis=0)  # rows repeating the one above
        assert [tuple(b) for b in wall_rectangles(blocked).tolist()] == greedy(blocked), trial


def test_a_map_fragmented_past_the_box_limit_is_refused_in_one_line():
    rows, cols = np.indices((200, 200))
    cells = np.where((rows + cols) % 2 == 0, 100, 0).astype(np.int8)  # a checkerboard: 20,000 one-cell boxes
    checker = MapImage(cells, 0.05, (0.0, 0.0), "checker.pgm")
    with pytest.raises(WorldError) as e:
        wall_boxes(checker)
    said = str(e.value)
    assert (
        said.startswith("checker.pgm: ") and f"more than {MAX_WALL_BOXES:,} wall boxes" in said and "\n" not in said
    ), said
    assert len(wall_boxes(checker, limit=20_000)) == 20_000


def test_a_map_server_yaml_given_as_a_world_says_how_to_make_a_world(tmp_path):
    make_map_world(tmp_path)
    refused(tmp_path / "map.yaml", "map.yaml: this is a map_server map", "not a world", "`map: map.yaml`")


# The peak resident memory of the loading process itself: VmHWM (ru_maxrss would also count what
# the parent held when it forked, which Linux keeps across exec).
LOAD = textwrap.dedent(
    """
    import sys, time
    from haven_sim.sim.world import WorldError
    from haven_sim.sim.world_file import load_world
    t0 = time.perf_counter()
    try:
        world = load_world(sys.argv[1])
        said = f"loaded {len(world.walls)} walls"
    except WorldError as e:
        said = f"refused: {e}"
    peak_kb = next(int(line.split()[1]) for line in open("/proc/self/status") if line.startswith("VmHWM:"))
    print(time.perf_counter() - t0, peak_kb / 1024, said, sep="\\t")
    """
)


def load_in_a_process(world):
    out = subprocess.run(
        [sys.executable, "-c", LOAD, str(world)], capture_output=True, text=True, timeout=120, check=True
    ).stdout
    seconds, peak_mb, said = out.strip().split("\t")
    return float(seconds), float(peak_mb), said


@pytest.mark.integration
def test_a_4000_by_4000_map_is_refused_or_loaded_within_10_s_and_500_mb(tmp_path):
    """The largest map a world may have (4,000 x 4,000 cells of 0.025 m: 100 m), through the real
    loader in its own process: a checkerboard (8 million one-cell boxes) is refused, a building
    with 9,500 pillars loads."""
    rows, cols = np.indices((4000, 4000))
    Image.fromarray(np.where((rows + cols) % 2 == 0, 0, 254).astype(np.uint8)).save(tmp_path / "checker.pgm")
    building = np.full((4000, 4000), 254, np.uint8)
    building[:8], building[-8:], building[:, :8], building[:, -8:] = 0, 0, 0, 0
    building[100:3880:40, 100:3900:38] = 0  # 95 x 100 pillars of one cell, and 4 walls: 9,504 boxes
    Image.fromarray(building).save(tmp_path / "building.pgm")
    for name in ("checker", "building"):
        (tmp_path / f"{name}.yaml").write_text(
            f"name: {name}\nmap: {{image: {name}.pgm, resolution: 0.025}}\nrobot: {{start: [1.0, 1.0, 0.0]}}\n"
        )
    seconds, peak_mb, said = load_in_a_process(tmp_path / "checker.yaml")
    assert said.startswith("refused: ") and f"more than {MAX_WALL_BOXES:,} wall boxes" in said, said
    assert seconds < 10.0 and peak_mb < 500.0, (seconds, peak_mb)
    seconds, peak_mb, said = load_in_a_process(tmp_path / "building.yaml")
    assert said == "loaded 9504 walls" and seconds < 10.0 and peak_mb < 500.0, (seconds, peak_mb, said)
