"""A path as a polyline with arc length: the one point-to-polyline projection every module uses
(the navigator watching for people, the path follower, the AR cues consuming markers)."""

from __future__ import annotations

import bisect
import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from haven_sim.common.geometry import FloatArray, Point, Pose2D


@dataclass(frozen=True)
class Projection:
    """The closest point of a polyline to a query point."""

    distance: float  # from the query point to the polyline
    segment: int  # index of the segment's first point
    s: float  # arc length of the closest point from the polyline's start
    point: Point


class Polyline:
    """Points (N, 2) with their cumulative arc length. Consecutive repeated points (a rotation in
    place) are kept: they are zero-length segments."""

    def __init__(self, points: FloatArray | Sequence[Point] | Sequence[Pose2D]) -> None:
        pts = np.asarray([(p[0], p[1]) for p in points], dtype=float).reshape(-1, 2)
        self.points = pts
        self._xy: list[tuple[float, float]] = [(px, py) for px, py in pts.tolist()]
        steps = np.hypot(*np.diff(pts, axis=0).T) if len(pts) > 1 else np.zeros(0)
        self.cumulative: FloatArray = np.concatenate([[0.0], np.cumsum(steps)]) if len(pts) else np.zeros(0)
        self._cum: list[float] = self.cumulative.tolist()  # the same values as plain floats, for per-query use

    def __len__(self) -> int:
        return len(self.points)

    @property
    def length(self) -> float:
        return self._cum[-1] if self._cum else 0.0

    def _segment_at(self, s: float) -> int:
        i = bisect.bisect_right(self._cum, s) - 1  # = cumulative.searchsorted(s, "right") - 1
        i, last = (0 if i < 0 else i), len(self._xy) - 2
        return i if i < last else last  # = min(last, max(0, i))

    def project(self, x: float, y: float, s_from: float = 0.0, s_to: float = math.inf) -> Projection:
        """The closest point among the segments overlapping arc lengths [s_from, s_to]."""
        pts = self.points
        if len(pts) == 0:
            raise ValueError("cannot project onto an empty polyline")
        if len(pts) == 1:
            return Projection(math.hypot(pts[0, 0] - x, pts[0, 1] - y), 0, 0.0, (float(pts[0, 0]), float(pts[0, 1])))
        lo = self._segment_at(s_from)
        hi = len(pts) - 1 if math.isinf(s_to) else max(lo + 1, min(len(pts) - 1, self._segment_at(s_to) + 1))
        dist, k, t, ln2, cx, cy = self._closest(x, y, lo, hi)
        return Projection(dist, k, float(self._cum[k] + t * math.sqrt(ln2)), (cx, cy))

    def _closest(self, x: float, y: float, lo: int, hi: int) -> tuple[float, int, float, float, float, float]:
        """(distance, segment, t along it, its squared length, closest point) of the first nearest
        segment in lo..hi-1. Plain floats, segment by segment: a query spans a few segments, and
        numpy's per-call overhead cost more than the arithmetic. The same operations in the same
        order as the array form this replaced, and numpy's hypot for the distances that can be the
        nearest (squared distances within rounding of the least): the same numbers to the last bit."""
        xy = self._xy
        found = []
        for i in range(lo, hi):
            (ax, ay), (bx, by) = xy[i], xy[i + 1]
            dx, dy = bx - ax, by - ay
            ln2 = dx * dx + dy * dy
            t = ((x - ax) * dx + (y - ay) * dy) / (ln2 if ln2 > 0 else 1.0)
            t = 0.0 if t < 0.0 else (1.0 if t > 1.0 else t)  # = min(max(t, 0.0), 1.0), NaN and -0.0 kept alike
            cx, cy = ax + dx * t, ay + dy * t
            found.append(((cx - x) ** 2 + (cy - y) ** 2, i, t, ln2, cx, cy))
        near = min(f[0] for f in found) * (1.0 + 1e-9) + 1e-300
        return min(
            ((float(np.hypot(cx - x, cy - y)), i, t, ln2, cx, cy) for q, i, t, ln2, cx, cy in found if q <= near),
            key=lambda c: c[0],
        )

    def point_at(self, s: float) -> Point:
        """The point at arc length s (clamped to the ends); on a zero-length segment, its start."""
        xy, cum = self._xy, self._cum
        if len(xy) == 1:
            return xy[0]
        s = min(max(s, 0.0), cum[-1])
        i = self._segment_at(s)
        seg = cum[i + 1] - cum[i]
        f = 0.0 if seg <= 0 else (s - cum[i]) / seg
        (ax, ay), (bx, by) = xy[i], xy[i + 1]
        return (float(ax + (bx - ax) * f), float(ay + (by - ay) * f))

    def moving_segment_at(self, s: float) -> int:
        """Index of the segment of non-zero length that holds arc length s (rotations skipped)."""
        i = self._segment_at(s)
        while i > 0 and self._cum[i + 1] - self._cum[i] <= 1e-12:
            i -= 1
        return i
