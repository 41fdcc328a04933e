"""Centre-line travel: a planned route that runs through a hallway is moved onto its centre line.

HAVEN's robot "travels down the centre of every hallway". A shortest path clips the inflated
corners instead, and after a room counted as reached 0.5 m off its centre the next leg is a
diagonal. `onto_lanes` replaces the stretch of a route inside a hallway with the hallway's centre
line, entered and left at its ends (the rooms' doorways), wherever the new legs are collision-free.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from haven_sim.common.geometry import Point
from haven_sim.common.polyline import Polyline

VisibleFn = Callable[[Point, Point], bool]  # is the straight leg a -> b free for the robot?

SAMPLE_M = 0.05
JOIN_M = 1.0  # a route starting inside a hallway joins its centre line this far ahead
MIN_COVER = 0.5  # a route that runs along at least this share of a hallway's length goes down its middle


@dataclass(frozen=True)
class Lane:
    """A hallway's centre line (two or more points) and its clear width."""

    points: tuple[Point, ...]
    width_m: float


def _inside(lane: Lane, pts: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """For each point: inside the lane's strip, and its arc length along the centre line."""
    line = Polyline(lane.points)
    inside = np.zeros(len(pts), dtype=bool)
    along = np.zeros(len(pts))
    for i, (x, y) in enumerate(pts):
        proj = line.project(float(x), float(y))
        along[i] = proj.s
        inside[i] = proj.distance <= lane.width_m / 2.0 and 1e-6 < proj.s < line.length - 1e-6
    return inside, along


def onto_lanes(route: Sequence[Point], lanes: Sequence[Lane], visible: VisibleFn) -> list[Point]:
    """`route` with each hallway stretch on the hallway's centre line (unchanged where that would
    not be collision-free)."""
    out: list[Point] = [(float(p[0]), float(p[1])) for p in route]
    for lane in lanes:
        out = _onto(out, lane, visible)
    return out


def _onto(route: list[Point], lane: Lane, visible: VisibleFn) -> list[Point]:
    line = Polyline(route)
    if line.length < SAMPLE_M:
        return route
    s = np.arange(0.0, line.length + SAMPLE_M, SAMPLE_M)
    pts = np.array([line.point_at(float(v)) for v in s])
    inside, along = _inside(lane, pts)
    idx = np.flatnonzero(inside)
    if len(idx) == 0:
        return route
    # The first contiguous run inside the strip.
    breaks = np.flatnonzero(np.diff(idx) > 1)
    run = idx[: breaks[0] + 1] if len(breaks) else idx
    lane_len = Polyline(lane.points).length
    if along[run].max() - along[run].min() < MIN_COVER * lane_len:
        return route
    centre = Polyline(lane.points if along[run[-1]] >= along[run[0]] else lane.points[::-1])
    a_in, a_out = (
        (along[run[0]], along[run[-1]])
        if along[run[-1]] >= along[run[0]]
        else (lane_len - along[run[0]], lane_len - along[run[-1]])
    )
    # Join at the hallway's end, or, for a route that starts (ends) inside it, a little ahead (behind).
    join = 0.0 if run[0] > 0 else min(a_in + JOIN_M, lane_len)
    leave = lane_len if run[-1] < len(s) - 1 else max(a_out - JOIN_M, join)
    middle = (
        [centre.point_at(join)]
        + [
            (float(p[0]), float(p[1]))
            for p, c in zip(centre.points, centre.cumulative, strict=True)
            if join < c < leave
        ]
        + [centre.point_at(leave)]
    )
    s_in, s_out = s[run[0]], s[run[-1]]
    before = [p for p, c in zip(route, line.cumulative, strict=True) if c < s_in - 1e-9] or [route[0]]
    after = [p for p, c in zip(route, line.cumulative, strict=True) if c > s_out + 1e-9] or [route[-1]]
    new = before + middle + after
    new = [p for i, p in enumerate(new) if i == 0 or math.hypot(p[0] - new[i - 1][0], p[1] - new[i - 1][1]) > 1e-6]
    for a, b in itertools.pairwise(new):
        if not visible((a[0], a[1]), (b[0], b[1])):
            return route
    return new
