"""What a world must satisfy beyond its format, with the limits a world file is held to.

- every coordinate within ±`MAX_COORDINATE_M` of the origin, and everything in the world (walls,
  obstacles, start poses, gems, rooms, hallways, the charging base) within a `MAX_EXTENT_M` square:
  the simulator and the planner rasterise the world's bounding box into an occupancy grid (0.05 m
  cells by default), which stays at most about 2,000 x 2,000 cells;
- polygons simple (`common.geometry.polygon_problem`, the rule a robot's footprint is held to too):
  at most `MAX_POLYGON_VERTICES` points, no point repeating the one before it, no two edges
  crossing or touching (except neighbours at their shared point);
- the robot's and each person's whole body (a disc of their radius) clear of solid geometry at start.
"""

from __future__ import annotations

import numpy as np

from haven_sim.common.geometry import Point, polygons_edges
from haven_sim.sim.world import Shape

MAX_COORDINATE_M = 1000.0
MAX_EXTENT_M = 100.0


def span_problem(items: list[tuple[str, list[Point]]]) -> tuple[str, str] | None:
    """(key, problem) of the first item that takes the world beyond `MAX_EXTENT_M` in x or y."""
    lo = [np.inf, np.inf]
    hi = [-np.inf, -np.inf]
    for key, points in items:
        for x, y in points:
            lo = [min(lo[0], x), min(lo[1], y)]
            hi = [max(hi[0], x), max(hi[1], y)]
            if hi[0] - lo[0] > MAX_EXTENT_M or hi[1] - lo[1] > MAX_EXTENT_M:
                span = f"{hi[0] - lo[0]:.0f} m x {hi[1] - lo[1]:.0f} m"
                return (
                    key,
                    f"({x:g}, {y:g}) makes the world span {span}; "
                    f"a world fits in {MAX_EXTENT_M:g} m x {MAX_EXTENT_M:g} m",
                )
    return None


def overlapping_shape(shapes: list[Shape], x: float, y: float, radius: float) -> tuple[Shape, bool] | None:
    """The first shape a disc of `radius` at (x, y) overlaps, and whether its centre is inside it."""
    if not shapes:
        return None
    counts = [len(s.polygon) for s in shapes]
    e = polygons_edges([s.polygon for s in shapes])
    owner = np.repeat(np.arange(len(shapes)), counts)
    x0, y0, x1, y1 = e[:, 0], e[:, 1], e[:, 2], e[:, 3]
    spans = (y < y0) != (y < y1)  # even-odd rule, as points_in_polygon
    x_at = x0 + (y - y0) * (x1 - x0) / np.where(spans, y1 - y0, 1.0)
    inside = np.bincount(owner, weights=spans & (x < x_at), minlength=len(shapes)) % 2 == 1
    dx, dy = x1 - x0, y1 - y0
    ln2 = dx * dx + dy * dy
    t = np.clip(((x - x0) * dx + (y - y0) * dy) / np.where(ln2 > 0, ln2, 1.0), 0.0, 1.0)
    near = np.hypot(x0 + t * dx - x, y0 + t * dy - y) < radius
    hit = inside | (np.bincount(owner, weights=near, minlength=len(shapes)) > 0)
    if not hit.any():
        return None
    k = int(np.argmax(hit))
    return shapes[k], bool(inside[k])
