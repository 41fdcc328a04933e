"""Path following in HAVEN's motion style, for any nav_msgs/Path-like pose list.

The path is cut at its rotate-in-place segments into alternating actions: rotate on the spot to a
yaw (at `rotate_speed`, 50 deg/s, until within `facing_tolerance`, 5 deg), and drive along a piece
by pure pursuit (arcs come out as arcs), slowing so as to stop where the piece ends. If the robot
finds itself facing more than `arc_max_angle` away from where it must go, it stops and rotates
first, as HAVEN's robot did. Unlike the original it never stalls on a small heading error and it
finishes: the last action done, it reports arrival and stays stopped.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from enum import Enum

import numpy as np

from haven_sim.common.geometry import FloatArray, Pose2D, Twist2D, wrap_angle
from haven_sim.nav.path_style import SegmentKind, classify


@dataclass(frozen=True)
class ControllerParams:
    linear_speed_mps: float = 0.4
    min_linear_speed_mps: float = 0.05
    rotate_speed_rps: float = math.radians(50.0)
    facing_tolerance_rad: float = math.radians(5.0)
    arc_max_angle_rad: float = math.radians(60.0)
    goal_tolerance_m: float = 0.1
    lookahead_m: float = 0.35
    decel_mps2: float = 0.4  # plan stops within the robot's 0.5 m/s^2
    angular_decel_rps2: float = 3.0
    max_angular_speed_rps: float = 1.5

    def validate(self) -> None:
        for name, value in vars(self).items():
            if not value > 0:
                raise ValueError(f"controller {name} must be positive, got {value}")


class Status(Enum):
    IDLE = "idle"  # no path
    ROTATING = "rotating"
    DRIVING = "driving"
    WAITING = "waiting"
    ARRIVED = "arrived"


@dataclass(frozen=True)
class _Rotate:
    x: float
    y: float
    yaw: float


@dataclass(frozen=True)
class _Drive:
    points: FloatArray  # (N, 2) polyline, N >= 2
    cumulative: FloatArray  # arc length at each point


def _actions(poses: Sequence[Pose2D]) -> list[_Rotate | _Drive]:
    actions: list[_Rotate | _Drive] = []
    for seg in classify(poses):
        if seg.kind is SegmentKind.ROTATE:
            end = poses[seg.end]
            actions.append(_Rotate(end.x, end.y, end.yaw))
            continue
        pts = np.array([(q.x, q.y) for q in poses[seg.start : seg.end + 1]], dtype=float)
        if actions and isinstance(actions[-1], _Drive):  # arc and straight pieces drive as one
            pts = np.vstack([actions[-1].points, pts[1:]])
            actions.pop()
        cum = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(pts, axis=0).T))])
        actions.append(_Drive(pts, cum))
    return actions


class PathFollower:
    def __init__(self, params: ControllerParams | None = None) -> None:
        self.params = params or ControllerParams()
        self.params.validate()
        self.set_path([])
        self.waiting = False

    def set_path(self, poses: Sequence[Pose2D]) -> None:
        """A new path replaces the old one; following starts at its first action."""
        self._actions = _actions(poses)
        self._index = 0
        self._progress = 0.0  # arc length reached along the current drive piece
        self._realigning = False
        self.goal = poses[-1] if poses else None
        if not poses:
            self.status = Status.IDLE
        else:
            self.status = Status.DRIVING if self._actions else Status.ARRIVED

    @property
    def active(self) -> bool:
        return self._index < len(self._actions)

    def command(self, pose: Pose2D) -> Twist2D:
        """The velocity for this control tick."""
        if self.waiting and self.active:
            self.status = Status.WAITING
            return Twist2D()
        while self.active:
            action = self._actions[self._index]
            cmd = self._rotate(pose, action) if isinstance(action, _Rotate) else self._drive(pose, action)
            if cmd is not None:
                return cmd
            self._index += 1
            self._progress = 0.0
            self._realigning = False
        if self.goal is not None:
            self.status = Status.ARRIVED
        return Twist2D()

    def _turn(self, err: float) -> Twist2D:
        p = self.params
        speed = min(p.rotate_speed_rps, math.sqrt(2.0 * p.angular_decel_rps2 * abs(err)))
        return Twist2D(0.0, 0.0, math.copysign(max(speed, 0.1), err))

    def _rotate(self, pose: Pose2D, action: _Rotate) -> Twist2D | None:
        err = wrap_angle(action.yaw - pose.yaw)
        if abs(err) <= self.params.facing_tolerance_rad:
            return None
        self.status = Status.ROTATING
        return self._turn(err)

    def _drive(self, pose: Pose2D, action: _Drive) -> Twist2D | None:
        p = self.params
        pts, cum = action.points, action.cumulative
        total = float(cum[-1])
        self._progress = self._project(pose, action)
        remaining = total - self._progress
        end = pts[-1]
        to_end = math.hypot(end[0] - pose.x, end[1] - pose.y)
        last = self._index == len(self._actions) - 1
        if to_end <= (p.goal_tolerance_m if last else max(p.goal_tolerance_m, 0.05)) and remaining <= p.lookahead_m:
            return None
        target = self._point_at(action, min(total, self._progress + p.lookahead_m))
        if math.hypot(target[0] - pose.x, target[1] - pose.y) < 1e-6:
            target = end
        dx, dy = target[0] - pose.x, target[1] - pose.y
        alpha = wrap_angle(math.atan2(dy, dx) - pose.yaw)
        # Facing far away from the path: stop and turn on the spot first (HAVEN's rule).
        if self._realigning or abs(alpha) > p.arc_max_angle_rad:
            self._realigning = abs(alpha) > p.facing_tolerance_rad
            if self._realigning:
                self.status = Status.ROTATING
                return self._turn(alpha)
        self.status = Status.DRIVING
        stop_in = max(remaining, to_end)
        v = min(p.linear_speed_mps, math.sqrt(2.0 * p.decel_mps2 * stop_in))
        v = max(v, p.min_linear_speed_mps)
        dist = max(math.hypot(dx, dy), 1e-6)
        w = 2.0 * v * math.sin(alpha) / dist
        w = max(-p.max_angular_speed_rps, min(p.max_angular_speed_rps, w))
        return Twist2D(v, 0.0, w)

    def _project(self, pose: Pose2D, action: _Drive) -> float:
        """Arc length of the closest point on the piece, searched forward from the last progress
        (a path that loops back on itself is still followed in order)."""
        pts, cum = action.points, action.cumulative
        window = self._progress + 2.0 * self.params.lookahead_m + 0.5
        i0 = min(len(pts) - 2, max(0, int(np.searchsorted(cum, self._progress, side="right")) - 1))
        i1 = max(i0 + 1, min(len(pts) - 1, int(np.searchsorted(cum, window, side="right"))))
        a, b = pts[i0:i1], pts[i0 + 1 : i1 + 1]
        d = b - a
        ln2 = np.einsum("ij,ij->i", d, d)
        t = np.clip(np.einsum("ij,ij->i", np.array([pose.x, pose.y]) - a, d) / np.where(ln2 > 0, ln2, 1.0), 0.0, 1.0)
        closest = a + d * t[:, None]
        k = int(np.argmin(np.hypot(closest[:, 0] - pose.x, closest[:, 1] - pose.y)))
        s = float(cum[i0 + k] + t[k] * math.sqrt(ln2[k]))
        return max(self._progress, s)

    @staticmethod
    def _point_at(action: _Drive, s: float) -> tuple[float, float]:
        pts, cum = action.points, action.cumulative
        i = min(len(pts) - 2, max(0, int(np.searchsorted(cum, s, side="right")) - 1))
        seg = cum[i + 1] - cum[i]
        f = 0.0 if seg <= 0 else (s - cum[i]) / seg
        return (float(pts[i, 0] + (pts[i + 1, 0] - pts[i, 0]) * f), float(pts[i, 1] + (pts[i + 1, 1] - pts[i, 1]) * f))
