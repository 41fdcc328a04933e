"""The map with people in it, for re-planning around them where no passing line fits."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import replace

import numpy as np

from haven_sim.common.geometry import Point
from haven_sim.sim.occupancy import OCCUPIED, OccupancyGridData


def with_people(
    grid: OccupancyGridData,
    people: Sequence[Point],
    radius_m: float,
    blocker: Point,
    closed: Point,
    closed_len_m: float,
) -> OccupancyGridData:
    """`grid` with a disc of `radius_m` at every person and a wall `closed_len_m` long from the
    blocking person along `closed` (the side the robot must not take)."""
    g = grid
    data = g.data.copy()
    res = g.resolution_m
    r_cells = math.ceil(radius_m / res)
    rr, cc = np.mgrid[-r_cells : r_cells + 1, -r_cells : r_cells + 1]
    disk = rr**2 + cc**2 <= (radius_m / res) ** 2
    marks: list[tuple[int, int]] = []
    for hx, hy in people:
        r0, c0 = g.cell_of(hx, hy)
        marks += [(r0 + int(dr), c0 + int(dc)) for dr, dc in zip(rr[disk], cc[disk], strict=True)]
    for i in range(math.ceil(closed_len_m / (res / 2.0)) + 1):
        s = i * res / 2.0
        marks.append(g.cell_of(blocker[0] + closed[0] * s, blocker[1] + closed[1] * s))
    for r, c in marks:
        if 0 <= r < g.height and 0 <= c < g.width:
            data[r, c] = OCCUPIED
    return replace(g, data=data)
