"""HAVEN's motion style as a path: rotate in place, drive arcs, drive straight.

`shape_path` turns a planner's polyline into poses. At the start and at every corner the motion
style (`motion_style.MotionStyle`) decides between rotating in place and an arc; an arc is tangent
to both legs (at the start: from the robot's heading onto a straight line to the next point), shrunk
until it is collision-free, or dropped for a rotation if it cannot be. The poses are spaced
`marker_spacing_m` apart and carry the segment kinds in the /plan convention (`common.paths`).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Sequence

import numpy as np

from haven_sim.common.geometry import FloatArray, Point, Pose2D, wrap_angle
from haven_sim.common.params import POSITIVE, Bounds, config, param
from haven_sim.nav.motion_style import MotionStyle

ClearFn = Callable[[FloatArray], bool]  # are all these (N, 2) points safe for the robot?


@config
class ShapeParams:
    marker_spacing_m: float = param(0.4, "pose spacing of /plan along straight parts and arcs", POSITIVE)
    rotate_step_deg: float = param(15.0, "pose spacing of /plan's rotations in place", POSITIVE)
    max_arc_radius_m: float = param(1.0, "corners become arcs of at most this radius", POSITIVE)
    min_arc_radius_m: float = param(
        0.15, "an arc that must be tighter than this to clear obstacles becomes a rotation", POSITIVE
    )
    straight_tolerance_deg: float = param(
        2.0, "heading changes smaller than this are not corners", Bounds(0.0, 90.0, high_open=True)
    )

    @property
    def rotate_step_rad(self) -> float:
        return math.radians(self.rotate_step_deg)

    @property
    def straight_tolerance_rad(self) -> float:
        return math.radians(self.straight_tolerance_deg)


def _heading(a: Point, b: Point) -> float:
    return math.atan2(b[1] - a[1], b[0] - a[0])


def _dist(a: Point, b: Point) -> float:
    return math.hypot(b[0] - a[0], b[1] - a[1])


class _Builder:
    """Accumulates poses; every piece starts where the previous one ended."""

    def __init__(self, start: Pose2D, params: ShapeParams) -> None:
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
    style: MotionStyle | None = None,
    params: ShapeParams | None = None,
    is_clear: ClearFn | None = None,
    goal_yaw: float | None = None,
) -> list[Pose2D]:
    """Poses in HAVEN's style along the polyline `points` (points[0] is the robot's position)."""
    m = style or MotionStyle()
    p = params or ShapeParams()
    clear = is_clear or (lambda pts: True)
    pts = [points[0]] + [q for a, q in itertools.pairwise(points) if _dist(a, q) > 1e-9]
    if (
        len(pts) >= 2
        and not m.rotate_in_place
        and abs(wrap_angle(_heading(pts[0], pts[1]) - start_yaw)) > m.arc_max_angle_rad
    ):
        # A holonomic robot sets off straight where a differential drive would rotate first (an
        # arc from its heading would swing it away from the way, up to a loop).
        start_yaw = _heading(pts[0], pts[1])
    b = _Builder(Pose2D(pts[0][0], pts[0][1], wrap_angle(start_yaw)), p)
    if len(pts) >= 2:
        _start(b, pts[1], m, p, clear)
        for k in range(1, len(pts)):
            target = pts[k]
            if k == len(pts) - 1:
                b.straight_to(target)
            else:
                _corner(b, target, pts[k + 1], m, p, clear)
    if goal_yaw is not None and abs(wrap_angle(goal_yaw - b.last.yaw)) > p.straight_tolerance_rad:
        b.rotate_to(goal_yaw)
    return _without_repeats(b.poses)


def _start(b: _Builder, target: Point, m: MotionStyle, p: ShapeParams, clear: ClearFn) -> None:
    here = b.last
    turn = wrap_angle(_heading((here.x, here.y), target) - here.yaw)
    if abs(turn) <= p.straight_tolerance_rad:
        return
    if not m.rotates_in_place(turn, _dist((here.x, here.y), target)):
        radius = p.max_arc_radius_m
        while radius >= p.min_arc_radius_m:
            found = _start_arc(here, target, radius)
            if found is not None:
                arc, arc_turn = found
                if not m.rotates_in_place(arc_turn) and clear(np.array([(q.x, q.y) for q in arc])):
                    b.arc(_arc_poses(here, radius, arc_turn, p.marker_spacing_m))
                    return
            radius /= 2.0
    b.rotate_to(_heading((here.x, here.y), target))


def _corner(b: _Builder, corner: Point, after: Point, m: MotionStyle, p: ShapeParams, clear: ClearFn) -> None:
    here = b.last
    yaw_in = _heading((here.x, here.y), corner)
    yaw_out = _heading(corner, after)
    turn = wrap_angle(yaw_out - yaw_in)
    if abs(turn) <= p.straight_tolerance_rad:
        b.straight_to(corner)
        return
    leg_in, leg_out = _dist((here.x, here.y), corner), _dist(corner, after)
    if not m.rotates_in_place(turn, leg_out):
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


def _without_repeats(poses: list[Pose2D]) -> list[Pose2D]:
    """Drop exact repeats where one piece ends and the next begins."""
    out = [poses[0]]
    for q in poses[1:]:
        last = out[-1]
        if math.hypot(q.x - last.x, q.y - last.y) > 1e-9 or abs(wrap_angle(q.yaw - last.yaw)) > 1e-9:
            out.append(q)
    return out
