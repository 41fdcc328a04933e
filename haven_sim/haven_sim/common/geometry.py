"""Plain 2-D geometry types shared by the core modules (REP-103: x forward, y left, yaw CCW)."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import NamedTuple

import numpy as np
import numpy.typing as npt

Point = tuple[float, float]
FloatArray = npt.NDArray[np.float64]
BoolArray = npt.NDArray[np.bool_]


class Pose2D(NamedTuple):
    """A pose in the plane (a NamedTuple: cheap to create in the physics loop)."""

    x: float
    y: float
    yaw: float = 0.0

    def distance_to(self, other: Pose2D | Point) -> float:
        return math.hypot(other[0] - self.x, other[1] - self.y)


class Twist2D(NamedTuple):
    """Body-frame velocity: linear x (forward), linear y (left, humans only), angular z."""

    vx: float = 0.0
    vy: float = 0.0
    wz: float = 0.0

    def is_finite(self) -> bool:
        return math.isfinite(self.vx) and math.isfinite(self.vy) and math.isfinite(self.wz)


ZERO_TWIST = Twist2D()


def stamp_parts(t: float) -> tuple[int, int]:
    """Seconds as (sec, nanosec) for a builtin_interfaces/Time."""
    sec = math.floor(t)
    return sec, min(round((t - sec) * 1e9), 999_999_999)


def wrap_angle(a: float) -> float:
    """Angle wrapped to [-pi, pi)."""
    return (a + math.pi) % (2.0 * math.pi) - math.pi


def yaw_to_quaternion(yaw: float) -> tuple[float, float, float, float]:
    """(x, y, z, w) of a rotation about z."""
    return (0.0, 0.0, math.sin(yaw / 2.0), math.cos(yaw / 2.0))


def quaternion_to_yaw(x: float, y: float, z: float, w: float) -> float:
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


MAX_WIRE_COORDINATE_M = 1e6  # a position beyond this in a message is nonsense (and grid arithmetic would overflow)


def checked_pose(x: float, y: float, qx: float, qy: float, qz: float, qw: float) -> Pose2D:
    """A pose read from a message (a live one, or one recorded in a bag) that may come from any
    node: ValueError names the field that is not finite or out of range. The all-zero quaternion
    is "any heading" (a NaN yaw), as a goal without a heading is sent."""
    for name, value, bound in (("position.x", x, MAX_WIRE_COORDINATE_M), ("position.y", y, MAX_WIRE_COORDINATE_M)):
        if not (math.isfinite(value) and abs(value) <= bound):
            raise ValueError(f"{name} must be finite and within +-{bound:g}, got {value!r}")
    for name, value in (("orientation.x", qx), ("orientation.y", qy), ("orientation.z", qz), ("orientation.w", qw)):
        if not math.isfinite(value):
            raise ValueError(f"{name} must be finite, got {value!r}")
    if abs(qx) + abs(qy) + abs(qz) + abs(qw) < 1e-9:
        return Pose2D(float(x), float(y), math.nan)
    return Pose2D(float(x), float(y), quaternion_to_yaw(qx, qy, qz, qw))


def polygon_edges(polygon: list[Point]) -> FloatArray:
    """Closed polygon -> (N, 4) array of edges x0, y0, x1, y1."""
    pts = np.asarray(polygon, dtype=float)
    nxt = np.roll(pts, -1, axis=0)
    return np.hstack([pts, nxt])


def polygons_edges(polygons: Sequence[Sequence[Point]]) -> FloatArray:
    """Closed polygons -> one (N, 4) array of all their edges x0, y0, x1, y1, in one pass (a world
    made from a map has thousands of wall boxes)."""
    sizes = np.array([len(p) for p in polygons], dtype=np.intp)
    if not sizes.sum():
        return np.zeros((0, 4))
    pts = np.array([xy for p in polygons for xy in p], dtype=float)
    ends = np.cumsum(sizes)
    nxt = np.arange(1, len(pts) + 1)
    nxt[ends[sizes > 0] - 1] = (ends - sizes)[sizes > 0]  # each polygon's last point closes on its first
    return np.hstack([pts, pts[nxt]])


def points_in_polygon(xs: FloatArray, ys: FloatArray, polygon: list[Point]) -> npt.NDArray[np.bool_]:
    """Even-odd rule, vectorised over the query points."""
    inside = np.zeros(xs.shape, dtype=bool)
    n = len(polygon)
    for i in range(n):
        x0, y0 = polygon[i]
        x1, y1 = polygon[(i + 1) % n]
        if y0 == y1:
            continue
        crosses = (ys < y0) != (ys < y1)
        x_at = x0 + (ys - y0) * (x1 - x0) / (y1 - y0)
        inside ^= crosses & (xs < x_at)
    return inside


def segment_to_polygon(a: Point, b: Point, thickness: float) -> list[Point]:
    """A wall given as a centre line with thickness, as a rectangle (ends extended by half the thickness)."""
    ax, ay = a
    bx, by = b
    length = math.hypot(bx - ax, by - ay)
    ux, uy = (bx - ax) / length, (by - ay) / length
    h = thickness / 2.0
    nx, ny = -uy * h, ux * h
    ax, ay = ax - ux * h, ay - uy * h
    bx, by = bx + ux * h, by + uy * h
    return [(ax + nx, ay + ny), (ax - nx, ay - ny), (bx - nx, by - ny), (bx + nx, by + ny)]


def polygon_area(polygon: list[Point]) -> float:
    """Signed area (positive counter-clockwise)."""
    s = 0.0
    n = len(polygon)
    for i in range(n):
        x0, y0 = polygon[i]
        x1, y1 = polygon[(i + 1) % n]
        s += x0 * y1 - x1 * y0
    return s / 2.0


def distance_point_to_edges(x: float, y: float, edges: FloatArray) -> float:
    """Smallest distance from a point to any of the edges (N, 4)."""
    if len(edges) == 0:
        return math.inf
    a = edges[:, 0:2]
    d = edges[:, 2:4] - a
    p = np.array([x, y])
    ln2 = np.einsum("ij,ij->i", d, d)
    t = np.clip(np.einsum("ij,ij->i", p - a, d) / np.where(ln2 > 0, ln2, 1.0), 0.0, 1.0)
    closest = a + d * t[:, None]
    return float(np.min(np.hypot(closest[:, 0] - x, closest[:, 1] - y)))


MAX_POLYGON_VERTICES = 500  # a world polygon, a robot footprint


def polygon_problem(points: list[Point]) -> str | None:
    """Why `points` (at most `MAX_POLYGON_VERTICES` of them) is not a simple polygon, or None."""
    n = len(points)
    a = np.asarray(points, dtype=float)
    b = np.roll(a, -1, axis=0)
    same = np.flatnonzero(np.all(a == b, axis=1))
    if len(same):
        i = int(same[0])
        return f"point {(i + 1) % n} repeats point {i}"
    d = b - a
    turn = d[:, 0] * np.roll(d, -1, axis=0)[:, 1] - d[:, 1] * np.roll(d, -1, axis=0)[:, 0]
    back = np.flatnonzero((turn == 0) & (np.einsum("ij,ij->i", d, np.roll(d, -1, axis=0)) < 0))
    if len(back):
        return f"folds back on itself at point {(int(back[0]) + 1) % n}"
    first, second = np.triu_indices(n, 2)
    keep = ~((first == 0) & (second == n - 1))  # the last edge and the first are neighbours
    first, second = first[keep], second[keep]
    hit = _segments_meet(a[first], b[first], a[second], b[second])
    if hit.any():
        e, f = (int(x[int(np.argmax(hit))]) for x in (first, second))
        return f"is not simple: its edges from point {e} to {e + 1} and from point {f} to {(f + 1) % n} cross or touch"
    return None


def _cross(o: FloatArray, p: FloatArray, q: FloatArray) -> FloatArray:
    result: FloatArray = (p[:, 0] - o[:, 0]) * (q[:, 1] - o[:, 1]) - (p[:, 1] - o[:, 1]) * (q[:, 0] - o[:, 0])
    return result


def _within(p: FloatArray, q: FloatArray, r: FloatArray) -> BoolArray:
    """Whether r (collinear with p-q) lies on the segment p-q."""
    lo, hi = np.minimum(p, q), np.maximum(p, q)
    inside: BoolArray = np.all((lo <= r) & (r <= hi), axis=1)
    return inside


def _segments_meet(p1: FloatArray, q1: FloatArray, p2: FloatArray, q2: FloatArray) -> BoolArray:
    o1, o2 = _cross(p1, q1, p2), _cross(p1, q1, q2)
    o3, o4 = _cross(p2, q2, p1), _cross(p2, q2, q1)
    proper = (o1 * o2 < 0) & (o3 * o4 < 0)
    touch = (
        (o1 == 0) & _within(p1, q1, p2)
        | (o2 == 0) & _within(p1, q1, q2)
        | (o3 == 0) & _within(p2, q2, p1)
        | (o4 == 0) & _within(p2, q2, q1)
    )
    meet: BoolArray = proper | touch
    return meet
