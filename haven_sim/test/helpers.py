"""Small worlds built in code for the core tests."""

from __future__ import annotations

from typing import Any

from haven_sim.world import World, parse_world


def box_world(size: float = 10.0, thickness: float = 0.1, **extra: Any) -> World:
    """An empty square room [0, size]^2 whose wall centre lines run on its border."""
    s = size
    data: dict[str, Any] = {
        "name": "box",
        "walls": [
            {"segment": [[0, 0], [s, 0]], "thickness": thickness},
            {"segment": [[s, 0], [s, s]], "thickness": thickness},
            {"segment": [[s, s], [0, s]], "thickness": thickness},
            {"segment": [[0, s], [0, 0]], "thickness": thickness},
        ],
        "robot": {"start": [s / 2, s / 2, 0.0]},
    }
    data.update(extra)
    return parse_world(data, source="box.yaml")
