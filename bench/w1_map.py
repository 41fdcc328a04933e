"""The peers' W1/W2 map (../shared/peers/common.py) as a HAVEN world, so our figures and the peers'
come from the same geometry: a 20 m x 20 m square, 0.10 m walls, four rooms of ~9.9 x 8.9 m and an
E-W hallway 1.9 m wide, joined by five 1 m doors."""

from __future__ import annotations

from typing import Any

import numpy as np

from haven_sim.sim.world import World
from haven_sim.sim.world_file import parse_world

ROOMS = {  # free rectangles (xmin, ymin, xmax, ymax)
    "sw": (0.10, 0.10, 9.95, 8.95),
    "se": (10.05, 0.10, 19.90, 8.95),
    "hall": (0.10, 9.05, 19.90, 10.95),
    "nw": (0.10, 11.05, 9.95, 19.90),
    "ne": (10.05, 11.05, 19.90, 19.90),
}
WALLS = [
    (0.0, 0.0, 20.0, 0.10),
    (0.0, 19.90, 20.0, 20.0),
    (0.0, 0.10, 0.10, 19.90),
    (19.90, 0.10, 20.0, 19.90),
    (0.10, 8.95, 4.0, 9.05),
    (5.0, 8.95, 14.0, 9.05),
    (15.0, 8.95, 19.90, 9.05),
    (0.10, 10.95, 4.0, 11.05),
    (5.0, 10.95, 14.0, 11.05),
    (15.0, 10.95, 19.90, 11.05),
    (9.95, 0.10, 10.05, 4.0),
    (9.95, 5.0, 10.05, 8.95),
    (9.95, 11.05, 10.05, 19.90),
]
AGENT_ROOMS = ["se", "nw", "ne", "hall"]  # the robot drives in "sw", as in the peers' W1


def room_box(name: str, pad: float = 0.5) -> tuple[float, float, float, float]:
    x0, y0, x1, y1 = ROOMS[name]
    return x0 + pad, y0 + pad, x1 - pad, y1 - pad


def w1_world(n_humans: int, seed: int = 0) -> World:
    """Robot at (5, 2.5) in the SW room; humans spread over the other rooms, >= 0.8 m apart."""
    rng = np.random.default_rng(seed)
    per = [n_humans // 4 + (1 if i < n_humans % 4 else 0) for i in range(4)] if n_humans != 1 else [1, 0, 0, 0]
    humans: list[dict[str, Any]] = []
    placed: list[tuple[float, float]] = []
    for room, k in zip(AGENT_ROOMS, per, strict=True):
        x0, y0, x1, y1 = room_box(room)
        while k > 0:
            x, y = float(rng.uniform(x0, x1)), float(rng.uniform(y0, y1))
            if all((x - a) ** 2 + (y - b) ** 2 >= 0.8**2 for a, b in placed):
                placed.append((x, y))
                humans.append({"id": f"h{len(humans)}", "start": [x, y, float(rng.uniform(-np.pi, np.pi))]})
                k -= 1
    data = {
        "name": f"peers_w1_{n_humans}",
        "walls": [{"polygon": [[a, b], [c, b], [c, d], [a, d]]} for a, b, c, d in WALLS],
        "rooms": [{"name": n, "centre": [(r[0] + r[2]) / 2, (r[1] + r[3]) / 2]} for n, r in ROOMS.items()],
        "robot": {"start": [5.0, 2.5, 0.0]},
        "humans": humans,
    }
    return parse_world(data, source="bench/w1_map.py")


def human_rooms(n_humans: int) -> list[str]:
    per = [n_humans // 4 + (1 if i < n_humans % 4 else 0) for i in range(4)] if n_humans != 1 else [1, 0, 0, 0]
    return [room for room, k in zip(AGENT_ROOMS, per, strict=True) for _ in range(k)]
