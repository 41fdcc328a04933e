"""Path following in HAVEN's motion style, for any nav_msgs/Path-like pose list.

The path is read from its geometry (`common.paths.read_path`: any planner's path, the goal yaw on its
last pose honoured) and cut at its rotate-in-place segments into alternating actions: rotate on the spot to a
yaw, and drive along a piece by pure pursuit (arcs come out as arcs), slowing so as to stop where the
piece ends (a holonomic robot moves straight at the pure-pursuit point, sideways if need be, and
turns to face its way as it goes). If the robot finds itself facing away from where it must go by more than the motion
style allows for an arc (after a push, say), it stops and rotates first, as HAVEN's robot did. Unlike
the original it never stalls on a small heading error and it finishes: the last action done, it
reports arrival and stays stopped.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from enum import Enum

from haven_sim.common.geometry import Pose2D, Twist2D, wrap_angle
from haven_sim.common.params import POSITIVE, config, param
from haven_sim.common.paths import SegmentKind, read_path
from haven_sim.common.polyline import Polyline
from haven_sim.nav.motion_style import MotionStyle
from haven_sim.robots.fields import from_robot

HEADING_GAIN = 2.0  # a holonomic robot turns to face its way at this rate per radian off (1/s), within its turn rate
# Going back to a goal it came to rest off (`PathFollower.correct`), the robot moves at most this
# many m/s per metre (rad/s per radian) still to go: slow enough that a command applied a few
# tenths of a second late still ends inside the goal checker's tolerances.
CORRECTION_GAIN = 1.0


@config
class FollowerParams:
    linear_speed_mps: float = from_robot("motion.cruise_speed_mps")  # along arcs and straights
    min_linear_speed_mps: float = param(0.05, "slowest speed while still driving toward a stop", POSITIVE)
    goal_tolerance_m: float = param(
        0.1,
        "the goal checker's xy tolerance: the goal counts as reached "
        "with the robot at rest this close (Nav2's default: 0.25)",
        POSITIVE,
    )
    yaw_goal_tolerance_rad: float = param(
        0.1,
        "the goal checker's yaw tolerance: at rest, the robot must face the path's last pose this closely "
        "(Nav2's default: 0.25); at least the motion style's facing tolerance, where a rotation ends",
        POSITIVE,
    )
    lookahead_m: float = param(0.35, "pure-pursuit lookahead along the path", POSITIVE)
    decel_mps2: float = param(0.4, "planned deceleration to each stop (the robot can do 0.5 m/s^2)", POSITIVE)
    angular_decel_rps2: float = param(3.0, "planned angular deceleration at the end of a rotation", POSITIVE)
    max_angular_speed_rps: float = from_robot("motion.max_turn_rate_rps")  # while driving
    holonomic: bool = from_robot("holonomic")  # moves in any direction: straight at the lookahead point


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


def _actions(poses: Sequence[Pose2D], style: MotionStyle) -> list[_Rotate | Polyline]:
    actions: list[_Rotate | Polyline] = []
    for seg in read_path(poses, style.arc_max_angle_rad, style.facing_tolerance_rad).segments:
        if seg.kind is SegmentKind.ROTATE:
            end = poses[seg.end]
            actions.append(_Rotate(end.x, end.y, seg.yaw))
            continue
        piece = [(q.x, q.y) for q in poses[seg.start : seg.end + 1]]
        previous = actions[-1] if actions else None
        if isinstance(previous, Polyline):  # arc and straight pieces drive as one
            actions.pop()
            piece = [(float(x), float(y)) for x, y in previous.points] + piece[1:]
        actions.append(Polyline(piece))
    return actions


class PathFollower:
    def __init__(self, params: FollowerParams | None = None, style: MotionStyle | None = None) -> None:
        self.params = params or FollowerParams()
        self.style = style or MotionStyle()
        self.set_path([])
        self.waiting = False

    def set_path(self, poses: Sequence[Pose2D]) -> None:
        """A new path replaces the old one; following starts at its first action."""
        self._actions = _actions(poses, self.style)
        self._index = 0
        self._progress = 0.0  # arc length reached along the current drive piece
        self._realigning = False
        self._correcting = False  # going back to the goal, slowly (`correct`)
        self.goal = poses[-1] if poses else None
        if not poses:
            self.status = Status.IDLE
        else:
            self.status = Status.DRIVING if self._actions else Status.ARRIVED

    @property
    def active(self) -> bool:
        return self._index < len(self._actions)

    def off_goal(self, pose: Pose2D) -> tuple[float, float]:
        """How far `pose` is from the goal: (metres, radians; 0 where the goal has no heading)."""
        goal = self.goal
        if goal is None:
            return 0.0, 0.0
        yaw = abs(wrap_angle(goal.yaw - pose.yaw)) if math.isfinite(goal.yaw) else 0.0
        return math.hypot(goal.x - pose.x, goal.y - pose.y), yaw

    def at_goal(self, pose: Pose2D) -> bool:
        """The goal checker (Nav2's SimpleGoalChecker's rule, our tolerances): within
        `goal_tolerance_m` and `yaw_goal_tolerance_rad` of the path's last pose."""
        xy, yaw = self.off_goal(pose)
        return xy <= self.params.goal_tolerance_m and yaw <= self.params.yaw_goal_tolerance_rad

    def correct(self, pose: Pose2D) -> None:
        """Arrived but not at the goal (the robot coasted past it, or turned too far): drive back to
        it and turn to its heading again, in the motion style (a goal behind is turned to first)."""
        goal = self.goal
        if goal is None:
            return
        xy, _ = self.off_goal(pose)
        actions: list[_Rotate | Polyline] = []
        if xy > self.params.goal_tolerance_m:
            actions.append(Polyline([(pose.x, pose.y), (goal.x, goal.y)]))
        if math.isfinite(goal.yaw):
            actions.append(_Rotate(goal.x, goal.y, goal.yaw))
        self._actions, self._index, self._progress, self._realigning = actions, 0, 0.0, False
        self._correcting = True
        self.status = Status.DRIVING

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
        speed = min(self.style.rotate_speed_rps, math.sqrt(2.0 * self.params.angular_decel_rps2 * abs(err)))
        if self._correcting:
            speed = min(speed, CORRECTION_GAIN * abs(err))
        return Twist2D(0.0, 0.0, math.copysign(max(speed, 0.05 if self._correcting else 0.1), err))

    def _rotate(self, pose: Pose2D, action: _Rotate) -> Twist2D | None:
        err = wrap_angle(action.yaw - pose.yaw)
        if self.style.facing(err):
            return None
        self.status = Status.ROTATING
        return self._turn(err)

    def _drive(self, pose: Pose2D, piece: Polyline) -> Twist2D | None:
        p = self.params
        total = piece.length
        # Searched forward from the last progress, so a path that loops back is still followed in order.
        self._progress = max(
            self._progress, piece.project(pose.x, pose.y, self._progress, self._progress + 2.0 * p.lookahead_m + 0.5).s
        )
        remaining = total - self._progress
        end = piece.point_at(total)
        to_end = math.hypot(end[0] - pose.x, end[1] - pose.y)
        last = self._index == len(self._actions) - 1
        if to_end <= (p.goal_tolerance_m if last else max(p.goal_tolerance_m, 0.05)) and remaining <= p.lookahead_m:
            return None
        target = piece.point_at(min(total, self._progress + p.lookahead_m))
        if math.hypot(target[0] - pose.x, target[1] - pose.y) < 1e-6:
            target = end
        dx, dy = target[0] - pose.x, target[1] - pose.y
        alpha = wrap_angle(math.atan2(dy, dx) - pose.yaw)
        # Facing far away from the path: stop and turn on the spot first (HAVEN's rule).
        if self._realigning or self.style.rotates_in_place(alpha):
            self._realigning = not self.style.facing(alpha)
            if self._realigning:
                self.status = Status.ROTATING
                return self._turn(alpha)
        self.status = Status.DRIVING
        stop_in = max(remaining, to_end)
        v = min(p.linear_speed_mps, math.sqrt(2.0 * p.decel_mps2 * stop_in))
        if self._correcting:
            v = min(v, CORRECTION_GAIN * stop_in)
        v = max(v, p.min_linear_speed_mps)
        dist = max(math.hypot(dx, dy), 1e-6)
        if p.holonomic:  # sideways as needed (no swing out on a tight turn), turning to face the way
            w = max(-p.max_angular_speed_rps, min(p.max_angular_speed_rps, HEADING_GAIN * alpha))
            return Twist2D(v * math.cos(alpha), v * math.sin(alpha), w)
        w = 2.0 * v * math.sin(alpha) / dist
        w = max(-p.max_angular_speed_rps, min(p.max_angular_speed_rps, w))
        return Twist2D(v, 0.0, w)
