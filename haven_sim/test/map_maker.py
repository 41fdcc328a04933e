"""A ROS map made by the tests themselves (never a shipped one): two rooms joined by a door, drawn
into a PGM as map_saver writes one (0 occupied, 254 free, an unknown grey around), with its
map_server YAML and a HAVEN overlay (rooms, starts, a gem each, the charging base)."""

from pathlib import Path

import numpy as np
from PIL import Image

RESOLUTION = 0.05
ORIGIN = (-1.0, -2.0)
UNKNOWN_GREY = 128  # between the thresholds: unknown (map_saver's own 205 reads as free with free_thresh 0.25)


def map_pixels() -> np.ndarray:
    """10 x 7 m: a 8 x 6 m building (0.2 m walls) split by a wall with a 1 m door, unknown outside."""
    res = RESOLUTION
    img = np.full((int(7 / res), int(10 / res)), UNKNOWN_GREY, np.uint8)
    r0, r1, c0, c1 = 10, 10 + int(6 / res), 10, 10 + int(8 / res)
    img[r0:r1, c0:c1] = 0
    img[r0 + 4 : r1 - 4, c0 + 4 : c1 - 4] = 254
    mid = (c0 + c1) // 2
    img[r0 + 4 : r1 - 4, mid : mid + 3] = 0
    door = (r0 + r1) // 2
    img[door - 10 : door + 10, mid : mid + 3] = 254
    return img


OVERLAY = """name: test_map
map: {map_yaml}
rooms:
  - {{name: A, centre: [1.5, 1.0]}}
  - {{name: B, centre: [5.5, 1.0]}}
charging_base: {{position: [0.5, 3.5], radius: 0.4}}
robot: {{start: [1.0, 0.0, 0.0]}}
humans: [{{id: h1, start: [5.5, 3.0, 3.14]}}]  # facing the dividing wall, the door to its left
gems:
  - {{id: g1, owner: robot, position: [6.0, -0.5], radius: 0.3}}
  - {{id: g2, owner: human, position: [1.0, 3.0], radius: 0.3}}
"""

SCENARIO = """name: test_map_visit
world: {world}
kind: hallway
timeout_s: 200
robot: {{route: [B, A]}}
humans: [{{id: h1, model: walker, route: [A, B], speed_mps: 0.8}}]
"""


def make_map_world(folder: Path, pixels: np.ndarray | None = None, suffix: str = ".pgm") -> Path:
    """Writes map image, map YAML, world overlay and a scenario into `folder`; returns the scenario."""
    folder.mkdir(parents=True, exist_ok=True)
    Image.fromarray(map_pixels() if pixels is None else pixels).save(folder / f"map{suffix}")
    (folder / "map.yaml").write_text(
        f"image: map{suffix}\nmode: trinary\nresolution: {RESOLUTION}\norigin: [{ORIGIN[0]}, {ORIGIN[1]}, 0.0]\n"
        "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.25\n"
    )
    (folder / "world.yaml").write_text(OVERLAY.format(map_yaml="map.yaml"))
    (folder / "scenario.yaml").write_text(SCENARIO.format(world="world.yaml"))
    return folder / "scenario.yaml"
