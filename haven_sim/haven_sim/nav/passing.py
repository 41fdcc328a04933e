"""Geometry of passing a person beside a route: directions, offsets and the room to either side."""

from __future__ import annotations

import math

import numpy as np

from haven_sim.common.geometry import Point
from haven_sim.common.polyline import Polyline
from haven_sim.nav.planner import GridPlanner


def normal_at(line: Polyline, s: float) -> Point:
    """Unit vector to the left of `line` at arc length s."""
    i = line.moving_segment_at(s)
    d = line.points[i + 1] - line.points[i]
    n = math.hypot(d[0], d[1]) or 1.0
    return (-d[1] / n, d[0] / n)


def offset_from(line: Polyline, s: float, p: Point) -> float:
    """Signed lateral offset (+ = left) of point p from `line` at arc length s."""
    q = line.point_at(s)
    n = normal_at(line, s)
    return (p[0] - q[0]) * n[0] + (p[1] - q[1]) * n[1]


def beside(line: Polyline, s: float, offset: float) -> Point:
    """The point `offset` to the left (+) or right (-) of `line` at arc length s."""
    q = line.point_at(s)
    n = normal_at(line, s)
    return (q[0] + n[0] * offset, q[1] + n[1] * offset)


def room_beside(route: Polyline, planner: GridPlanner, s_from: float, s_to: float, side: float) -> float:
    """How far the robot's centre may move off `route` to the left (side +1) or right (-1) all
    along arc lengths [s_from, s_to], in the planner's inflated map."""
    step = planner.grid.resolution_m / 2.0
    room = math.inf
    for s in np.arange(max(0.0, s_from), min(route.length, s_to) + 1e-9, 0.25):
        q, n = route.point_at(float(s)), normal_at(route, float(s))
        d = 0.0
        while d < 3.0 and planner.is_free(q[0] + side * n[0] * (d + step), q[1] + side * n[1] * (d + step)):
            d += step
        room = min(room, d - step)  # a cell's quantisation off
    return max(0.0, room) if math.isfinite(room) else 0.0
