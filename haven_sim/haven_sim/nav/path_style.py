"""HAVEN's motion style as a path: rotate in place, drive arcs, drive straight.

`shape_path` turns a planner's polyline into poses. At the start and at every corner, a heading
change larger than `arc_max_angle` (60 deg), or a next leg shorter than `too_close_distance`, means
stopping and rotating in place; otherwise the corner is replaced by a circular arc tangent to both
legs (at the start: an arc from the robot's heading onto a straight line to the next point), shrunk
until it is collision-free, or dropped for a rotation if it cannot be. The poses are spaced
`marker_spacing` apart and carry the segment kinds in nav_msgs/Path terms:

  * consecutive poses at one position with changing yaw: rotate in place;
  * yaw changing while moving: arc;
  * constant yaw while moving: straight.

`classify` reads any pose list back into those segments, so the controller and the AR cues treat a
swapped-in planner's path exactly like ours.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from enum import Enum

import numpy as np

from haven_sim.common.geometry import FloatArray, Point, Pose2D, wrap_angle

ClearFn = Callable[[FloatArray], bool]  # are all these (N, 2) points safe for the robot?


class SegmentKind(Enum):
    ROTATE = "rotate"
    ARC = "arc"
    STRAIGHT = "straight"


@dataclass(frozen=True)
class Segment:
    kind: SegmentKind
    start: int  # index of the first pose
    end: int  # index of the last pose (inclusive)


@dataclass(frozen=True)
class StyleParams:
    arc_max_angle_rad: float = math.radians(60.0)
    too_close_distance_m: float = 0.5
    marker_spacing_m: float = 0.4
    rotate_step_rad: float = math.radians(15.0)
    max_arc_radius_m: float = 1.0
    min_arc_radius_m: float = 0.15
    straight_tolerance_rad: float = math.radians(2.0)  # smaller heading changes are not corners

    def validate(self) -> None:
        if not 0 < self.arc_max_angle_rad <= math.pi:
            raise ValueError("arc_max_angle must be within (0, 180] degrees")
        for name in ("marker_spacing_m", "rotate_step_rad", "max_arc_radius_m", "min_arc_radius_m"):
            if not getattr(self, name) > 0:
                raise ValueError(f"{name} must be positive, got {getattr(self, name)}")
        if self.too_close_distance_m < 0:
            raise ValueError("too_close_distance_m must not be negative")


def _heading(a: Point, b: Point) -> float:
    return math.atan2(b[1] - a[1], b[0] - a[0])


def _dist(a: Point, b: Point) -> float:
    return math.hypot(b[0] - a[0], b[1] - a[1])


class _Builder:
    """Accumulates poses; every piece starts where the previous one ended."""

    def __init__(self, start: Pose2D, params: StyleParams) -> None:
        self.p = params
        self.poses: list[Pose2D] = [start]

    @property
    def last(self) -> Pose2D:
        return self.poses[-1]

    def rotate_to(self, yaw: float) -> None:
        here = self.last
        turn = wrap_angle(yaw - here.yaw)
        n = max(1, math.ceil(abs(turn) / self.p.rotate_step_rad - 1e-9))
        for k in range(1, n + 1):
            self.poses.append(Pose2D(here.x, here.y, wrap_angle(here.yaw + turn * k / n)))

    def straight_to(self, target: Point) -> None:
        here = self.last
        length = _dist((here.x, here.y), target)
        if length < 1e-9:
            return
        yaw = _heading((here.x, here.y), target)
        n = max(1, math.ceil(length / self.p.marker_spacing_m - 1e-9))
        for k in range(1, n + 1):
            f = k / n
            self.poses.append(Pose2D(here.x + (target[0] - here.x) * f, here.y + (target[1] - here.y) * f, yaw))

    def arc(self, points: list[Pose2D]) -> None:
        self.poses.extend(points[1:])


def _arc_poses(start: Pose2D, radius: float, turn: float, spacing: float) -> list[Pose2D]:
    """A circular arc from `start` (tangent to its yaw) turning by `turn` (rad, + = left)."""
    side = 1.0 if turn > 0 else -1.0
    cx = start.x - side * radius * math.sin(start.yaw)
    cy = start.y + side * radius * math.cos(start.yaw)
    n = max(2, math.ceil(abs(turn) * radius / spacing - 1e-9))
    out = []
    for k in range(n + 1):
        yaw = start.yaw + turn * k / n
        out.append(Pose2D(cx + side * radius * math.sin(yaw), cy - side * radius * math.cos(yaw), wrap_angle(yaw)))
    return out


def _start_arc(here: Pose2D, target: Point, radius: float) -> tuple[list[Pose2D], float] | None:
    """From `here`, an arc of `radius` that ends heading straight at `target`: (arc, turn) or None."""
    bearing = wrap_angle(_heading((here.x, here.y), target) - here.yaw)
    side = 1.0 if bearing > 0 else -1.0
    cx = here.x - side * radius * math.sin(here.yaw)
    cy = here.y + side * radius * math.cos(here.yaw)
    d = math.hypot(target[0] - cx, target[1] - cy)
    if d <= radius * 1.001:
        return None  # the target lies inside the turning circle: no such arc
    # Heading of the tangent line from the circle to the target, in the turning direction.
    to_target = math.atan2(target[1] - cy, target[0] - cx)
    tangent_yaw = to_target + side * math.asin(radius / d)
    turn = wrap_angle(tangent_yaw - here.yaw)
    if turn * side < 0:
        turn += side * 2.0 * math.pi
    return _arc_poses(here, radius, turn, 0.01), turn


def shape_path(
    points: Sequence[Point],
    start_yaw: float,
    params: StyleParams | None = None,
    is_clear: ClearFn | None = None,
    goal_yaw: float | None = None,
) -> list[Pose2D]:
    """Poses in HAVEN's style along the polyline `points` (points[0] is the robot's position)."""
    p = params or StyleParams()
    p.validate()
    clear = is_clear or (lambda pts: True)
    pts = [points[0]] + [q for a, q in zip(points, points[1:]) if _dist(a, q) > 1e-9]
    b = _Builder(Pose2D(pts[0][0], pts[0][1], wrap_angle(start_yaw)), p)
    if len(pts) >= 2:
        _start(b, pts[1], p, clear)
        for k in range(1, len(pts)):
            target = pts[k]
            if k == len(pts) - 1:
                b.straight_to(target)
            else:
                _corner(b, target, pts[k + 1], p, clear)
    if goal_yaw is not None and abs(wrap_angle(goal_yaw - b.last.yaw)) > p.straight_tolerance_rad:
        b.rotate_to(goal_yaw)
    return _resample(b.poses, p)


def _start(b: _Builder, target: Point, p: StyleParams, clear: ClearFn) -> None:
    here = b.last
    turn = wrap_angle(_heading((here.x, here.y), target) - here.yaw)
    if abs(turn) <= p.straight_tolerance_rad:
        return
    if abs(turn) <= p.arc_max_angle_rad and _dist((here.x, here.y), target) >= p.too_close_distance_m:
        radius = p.max_arc_radius_m
        while radius >= p.min_arc_radius_m:
            found = _start_arc(here, target, radius)
            if found is not None:
                arc, arc_turn = found
                if abs(arc_turn) <= p.arc_max_angle_rad and clear(np.array([(q.x, q.y) for q in arc])):
                    b.arc(_arc_poses(here, radius, arc_turn, p.marker_spacing_m))
                    return
            radius /= 2.0
    b.rotate_to(_heading((here.x, here.y), target))


def _corner(b: _Builder, corner: Point, after: Point, p: StyleParams, clear: ClearFn) -> None:
    here = b.last
    yaw_in = _heading((here.x, here.y), corner)
    yaw_out = _heading(corner, after)
    turn = wrap_angle(yaw_out - yaw_in)
    if abs(turn) <= p.straight_tolerance_rad:
        b.straight_to(corner)
        return
    leg_in, leg_out = _dist((here.x, here.y), corner), _dist(corner, after)
    if abs(turn) <= p.arc_max_angle_rad and leg_out >= p.too_close_distance_m:
        half = math.tan(abs(turn) / 2.0)
        # Tangent points may use all of the incoming leg but only half of the outgoing one (the
        # rest belongs to the next corner).
        radius = min(p.max_arc_radius_m, leg_in / half, 0.5 * leg_out / half)
        while radius >= p.min_arc_radius_m:
            t = radius * half
            t1 = (corner[0] - t * math.cos(yaw_in), corner[1] - t * math.sin(yaw_in))
            arc = _arc_poses(Pose2D(t1[0], t1[1], yaw_in), radius, turn, 0.01)
            if clear(np.array([(q.x, q.y) for q in arc])):
                b.straight_to(t1)
                b.arc(_arc_poses(Pose2D(t1[0], t1[1], yaw_in), radius, turn, p.marker_spacing_m))
                return
            radius /= 2.0
    b.straight_to(corner)
    b.rotate_to(yaw_out)


def _resample(poses: list[Pose2D], p: StyleParams) -> list[Pose2D]:
    """Drop exact repeats (straight pieces already come spaced; arcs and rotations too)."""
    out = [poses[0]]
    for q in poses[1:]:
        last = out[-1]
        if math.hypot(q.x - last.x, q.y - last.y) > 1e-9 or abs(wrap_angle(q.yaw - last.yaw)) > 1e-9:
            out.append(q)
    return out


def classify(
    poses: Sequence[Pose2D], position_eps_m: float = 1e-3, yaw_eps_rad: float = math.radians(0.5)
) -> list[Segment]:
    """Rotate / arc / straight segments of any pose list (ours or another planner's)."""
    kinds: list[SegmentKind | None] = []
    for a, q in zip(poses, poses[1:]):
        moved = math.hypot(q.x - a.x, q.y - a.y) > position_eps_m
        turned = abs(wrap_angle(q.yaw - a.yaw)) > yaw_eps_rad
        if not moved:
            kinds.append(SegmentKind.ROTATE if turned else None)
        else:
            kinds.append(SegmentKind.ARC if turned else SegmentKind.STRAIGHT)
    segments: list[Segment] = []
    for i, kind in enumerate(kinds):
        if kind is None:
            continue
        if segments and segments[-1].kind is kind and segments[-1].end == i:
            segments[-1] = Segment(kind, segments[-1].start, i + 1)
        else:
            segments.append(Segment(kind, i, i + 1))
    return segments
