"""Human-aware navigation to one goal at a time: plan, watch the path for people, pass or wait.

HAVEN's rule (paper, Figure 3): the robot travels down the centre of every hallway (`lanes`) unless
a person blocks the centre path; then it curves around them on the side with room, its turn signal
showing that side, and returns to the centre line once they are passed or gone. It waits only when
passing is impossible and the person is close, or when the person stands at the robot's next stop.

All distances are measured along the route, and whether passing is possible comes from the room
beside the person (the corridor's width), not from straight-line distances to a goal far away.
Every check (`update`, at the planner's check rate) decides again, waiting included: a person who
steps aside lets the waiting robot pass.

Passing is a local manoeuvre on the route: a short straight (so the signal shows before the curve),
an arc out to a lateral offset, the offset held past the person, an arc back. Where that cannot be
fitted (a person at a corner of a furnished room) the route is re-planned with the people as
obstacles. Everything is a pure function of the poses and the time given, so a node and batch mode
behave the same.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from enum import Enum
from typing import Any

import numpy as np

from haven_sim.common.bodies import HUMAN_BODY
from haven_sim.common.events import Event, EventKind, Source, event
from haven_sim.common.geometry import Point, Pose2D
from haven_sim.common.params import param
from haven_sim.common.polyline import Polyline
from haven_sim.nav.lanes import Lane, onto_lanes
from haven_sim.nav.motion_style import MotionStyle
from haven_sim.nav.path_style import ShapeParams, shape_path
from haven_sim.nav.people_map import with_people
from haven_sim.nav.planner import GridPlanner, PlannerParams, PlanningError
from haven_sim.sim.occupancy import OccupancyGridData

REPLAN_RETRY_S = 2.0


@dataclass(frozen=True)
class NavigatorParams:
    pass_start_m: float = param(
        4.0,
        "start passing a person on the path this far ahead, along it (about the far edge of Hall's social zone, 3.6 m, plus the robot's reaction)",
    )
    pass_clearance_m: float = param(0.3, "preferred gap between the robot's and the person's bodies when passing")
    min_pass_clearance_m: float = param(0.15, "passing needs at least this gap; otherwise the robot waits")
    pass_angle_deg: float = param(30.0, "heading change of the curve out to the passing line and back")
    signal_lead_m: float = param(1.0, "straight driven before the curve so that the turn signal shows first")
    wait_gap_m: float = param(1.2, "a person who cannot be passed makes the robot stop this far before them, along the path (Hall's personal zone)")
    path_clearance_m: float = param(0.1, "a person within body radii + this of the upcoming path blocks it")
    diverge_m: float = param(0.15, "off the route by more than this, the robot is on a detour")
    goal_tolerance_m: float = param(0.1, "the goal counts as reached this close")
    use_goal_yaw: bool = param(True, "rotate to the goal's orientation at the end")

    def __post_init__(self) -> None:
        for name in (
            "pass_start_m",
            "pass_clearance_m",
            "min_pass_clearance_m",
            "signal_lead_m",
            "wait_gap_m",
            "path_clearance_m",
            "diverge_m",
            "goal_tolerance_m",
        ):
            if getattr(self, name) < 0:
                raise ValueError(f"{name} must not be negative, got {getattr(self, name)}")
        if not 5.0 <= self.pass_angle_deg <= 60.0:
            raise ValueError(f"pass_angle_deg must be within [5, 60] (beyond 60 the robot rotates in place), got {self.pass_angle_deg}")
        if self.min_pass_clearance_m > self.pass_clearance_m:
            raise ValueError("min_pass_clearance_m must not exceed pass_clearance_m")


class NavState(Enum):
    IDLE = "idle"
    FOLLOWING = "following"
    DETOUR = "detour"
    WAITING = "waiting"


@dataclass
class NavOutput:
    """What changed in one call: a path to publish, a new wait flag, events."""

    path: list[Pose2D] | None = None
    waiting: bool | None = None
    events: list[Event] = field(default_factory=list)


@dataclass(frozen=True)
class _OnPath:
    """A person on a path: where along it, how far off it (signed, + = left), and where they are."""

    s: float
    offset: float
    xy: Point


@dataclass(frozen=True)
class _Detour:
    poses: list[Pose2D]
    side: str
    back_s: float  # arc length along the poses where the curve back to the route begins (inf: none)
    clearance_m: float  # planned gap between the robot's and the person's bodies


def _xy(p: Point) -> list[float]:
    return [round(p[0], 3), round(p[1], 3)]


class Navigator:
    def __init__(
        self,
        grid: OccupancyGridData,
        planner: PlannerParams | None = None,
        shape: ShapeParams | None = None,
        params: NavigatorParams | None = None,
        style: MotionStyle | None = None,
        lanes: Sequence[Lane] = (),
    ) -> None:
        self.planner_params = planner or PlannerParams()
        self.shape = shape or ShapeParams()
        self.params = params or NavigatorParams()
        self.style = style or MotionStyle()
        self.lanes = tuple(lanes)
        self.set_map(grid)
        self.state = NavState.IDLE
        self.goal: Pose2D | None = None
        self.route = Polyline([(0.0, 0.0)])  # the planned (centre-line) route, as points
        self.original: list[Pose2D] = []  # the route as shaped poses
        self.active: list[Pose2D] = []  # what the robot follows now: the route or a detour
        self.side = ""  # of the current detour
        self._progress = 0.0  # arc length reached along `active`
        self._route_s = 0.0  # arc length reached along `route`
        self._back_s = math.inf  # arc length along a detour where it turns back to the route
        self._replan_tried_at = -math.inf

    def set_map(self, grid: OccupancyGridData) -> None:
        self.grid = grid
        self.planner = GridPlanner(grid, self.planner_params)

    @property
    def block_distance_m(self) -> float:
        return HUMAN_BODY.radius_m + self.planner_params.body_radius_m + self.params.path_clearance_m

    # -- planning ----------------------------------------------------------------------------------
    def _goal_yaw(self) -> float | None:
        # A NaN goal yaw means "any heading": no final rotation.
        goal = self.goal
        return goal.yaw if (goal is not None and self.params.use_goal_yaw and math.isfinite(goal.yaw)) else None

    def _shape(self, points: Sequence[Point], robot: Pose2D, planner: GridPlanner | None = None) -> list[Pose2D]:
        return shape_path(points, robot.yaw, self.style, self.shape, (planner or self.planner).hard_clear, self._goal_yaw())

    def _event(self, kind: EventKind, now: float, **data: Any) -> Event:
        return event(kind, now, Source.PLANNER, **data)

    def _visible(self, a: Point, b: Point) -> bool:
        return bool(self.planner.visible(np.array([a]), np.array([b]))[0])

    def set_goal(self, robot: Pose2D, goal: Pose2D, now: float) -> NavOutput:
        out = NavOutput()
        try:
            plan = self.planner.plan((robot.x, robot.y), (goal.x, goal.y))
        except PlanningError as e:
            self.state, self.goal, self.original, self.active = NavState.IDLE, None, [], []
            out.path, out.waiting = [], False
            out.events.append(self._event(EventKind.PLAN_REFUSED, now, goal=_xy((goal.x, goal.y)), reason=str(e)))
            return out
        self.goal = goal
        points = onto_lanes(plan.points, self.lanes, self._visible) if self.lanes else plan.points
        self.route = Polyline(points)
        self._route_s = 0.0
        poses = self._shape(points, robot)
        self._follow(poses, NavState.FOLLOWING)
        self.original = poses
        out.path, out.waiting = poses, False
        out.events.append(self._event(EventKind.PLAN_MADE, now, goal=_xy((goal.x, goal.y)), length_m=round(self.route.length, 3), poses=len(poses)))
        return out

    def _follow(self, poses: list[Pose2D], state: NavState, back_s: float = math.inf) -> None:
        self.active, self.state, self._progress, self._back_s = poses, state, 0.0, back_s
        self._line = Polyline(poses)

    # -- watching ----------------------------------------------------------------------------------
    def _advance(self, robot: Pose2D) -> None:
        if len(self._line) >= 2:
            self._progress = max(self._progress, self._line.project(robot.x, robot.y, self._progress, self._progress + 16.0).s)
        if len(self.route) >= 2:
            self._route_s = max(self._route_s, self.route.project(robot.x, robot.y, self._route_s, self._route_s + 16.0).s)

    def _on_path(self, line: Polyline, s_from: float, humans: Sequence[Point]) -> _OnPath | None:
        """The person ahead on `line` (from arc length `s_from`) that the robot meets first."""
        best: _OnPath | None = None
        for h in humans:
            proj = line.project(h[0], h[1], s_from)
            if proj.distance < self.block_distance_m and proj.s > s_from + 1e-6 and (best is None or proj.s < best.s):
                best = _OnPath(proj.s, self._signed_offset(line, proj.s, h), h)
        return best

    @staticmethod
    def _normal(line: Polyline, s: float) -> Point:
        """Unit vector to the left of `line` at arc length s."""
        i = line.moving_segment_at(s)
        d = line.points[i + 1] - line.points[i]
        n = math.hypot(d[0], d[1]) or 1.0
        return (-d[1] / n, d[0] / n)

    def _signed_offset(self, line: Polyline, s: float, p: Point) -> float:
        q = line.point_at(s)
        n = self._normal(line, s)
        return (p[0] - q[0]) * n[0] + (p[1] - q[1]) * n[1]

    def update(self, robot: Pose2D, humans: Sequence[Point], now: float) -> NavOutput:
        out = NavOutput()
        if self.state is NavState.IDLE or self.goal is None:
            return out
        if math.hypot(robot.x - self.goal.x, robot.y - self.goal.y) <= self.params.goal_tolerance_m:
            self.state = NavState.IDLE
            return out
        self._advance(robot)
        person = self._on_path(self._line, self._progress, humans)
        if person is None:
            if self.state is NavState.DETOUR and self._progress < self._back_s:
                self._maybe_revert(robot, humans, now, out)
            elif self.state is NavState.WAITING:
                self._resume(out, now)
            return out
        gap = person.s - self._progress
        if gap > self.params.pass_start_m:
            if self.state is NavState.WAITING:
                self._resume(out, now)
            return out
        # A person close ahead on the path: pass them if there is room, else wait when near.
        passing = self._pass(robot, person, humans) or self._replan_around(robot, person, humans, now)
        if passing is not None:
            if self.state is NavState.WAITING:
                out.waiting = False
                out.events.append(self._event(EventKind.RESUMED, now))
            self._follow(passing.poses, NavState.DETOUR, passing.back_s)
            self.side = passing.side
            out.path = passing.poses
            out.events.append(
                self._event(
                    EventKind.REPLANNED,
                    now,
                    reason="human on the path",
                    side=passing.side,
                    human=_xy(person.xy),
                    gap_m=round(gap, 2),
                    clearance_m=round(passing.clearance_m, 2),
                )
            )
            return out
        at_stop = self.route.length - self.route.project(*person.xy).s < self._need(self.params.min_pass_clearance_m)
        if (gap <= self.params.wait_gap_m or at_stop and gap <= self.params.wait_gap_m + 1.0) and self.state is not NavState.WAITING:
            reason = "human at the robot's next stop" if at_stop else "human on the path and no room to pass"
            self.state = NavState.WAITING
            out.waiting = True
            out.events.append(self._event(EventKind.WAITING, now, reason=f"{reason}, {gap:.1f} m ahead", human=_xy(person.xy)))
        return out

    def _resume(self, out: NavOutput, now: float) -> None:
        self.state = NavState.DETOUR if self.active is not self.original else NavState.FOLLOWING
        out.waiting = False
        out.events.append(self._event(EventKind.RESUMED, now))

    # -- passing -----------------------------------------------------------------------------------
    def _need(self, clearance: float) -> float:
        """Centre-to-centre lateral distance that leaves `clearance` between robot and person."""
        return HUMAN_BODY.radius_m + self.planner_params.body_radius_m + clearance

    def _room(self, at: Point, normal: Point) -> float:
        """How far the robot's centre may move from `at` along `normal` (walls and margin off)."""
        return self.planner.free_run(at, normal) - self.planner_params.inflation_m

    def _offset_at(self, p: Point) -> float:
        """The active path's signed lateral offset from the route beside point p."""
        proj = self._line.project(p[0], p[1], self._progress)
        return self._signed_offset(self.route, self.route.project(*proj.point).s, proj.point)

    def _pass(self, robot: Pose2D, person: _OnPath, humans: Sequence[Point]) -> _Detour | None:
        """Figure 3: a curve out to a line beside the person on the side with room, held past
        them, and a curve back to the route; None if it does not fit."""
        p = self.params
        route = self.route
        s_r = self._route_s
        s_h = route.project(*person.xy).s
        e = self._signed_offset(route, s_h, person.xy)
        at = route.point_at(s_h)
        n = self._normal(route, s_h)
        room = {"left": self._room(at, n), "right": self._room(at, (-n[0], -n[1]))}
        lateral = {
            "left": min(room["left"], e + self._need(p.pass_clearance_m)),
            "right": -min(room["right"], -e + self._need(p.pass_clearance_m)),
        }
        fits = {side: abs(lateral[side] - e) >= self._need(p.min_pass_clearance_m) - 1e-9 for side in lateral}
        # The side with more room beside the person (the right on a tie, as people keep right); a
        # detour keeps its side while that still fits.
        beside = {"left": room["left"] - e, "right": room["right"] + e}
        order = sorted(("right", "left"), key=lambda side: -round(beside[side], 2))
        if self.state is NavState.DETOUR and self.side in order:
            order.remove(self.side)
            order.insert(0, self.side)
        here = self._signed_offset(route, s_r, (robot.x, robot.y))
        tan = math.tan(math.radians(p.pass_angle_deg))
        steep = math.tan(min(self.style.arc_max_angle_rad * 0.9, math.radians(55.0)))
        past = self._need(p.pass_clearance_m) + HUMAN_BODY.radius_m
        for side in order:
            if not fits[side]:
                continue
            y = lateral[side]
            out_len = abs(y - here) / tan
            lead = p.signal_lead_m
            reach = s_h - s_r - past  # the passing line must be reached before the person
            if lead + out_len > reach:
                lead = max(0.0, reach - out_len)
                out_len = max(abs(y - here) / steep, reach - lead)
            if lead + out_len > reach + 1e-9:
                continue
            s_a, s_b = s_r + lead, s_r + lead + out_len
            s_c = s_h + past
            s_d = s_c + abs(y) / tan
            if s_c >= route.length - 0.05:
                continue  # the person is at the robot's next stop: no way back to the route
            pts: list[Point] = [(robot.x, robot.y)]
            if lead > 0.05:
                pts.append(self._beside(s_a, here))
            pts += [self._beside(s_b, y), self._beside(s_c, y)]
            if s_d < route.length - 0.05:
                pts.append(route.point_at(s_d))
            pts += [(float(x), float(yy)) for (x, yy), c in zip(route.points, route.cumulative) if c > min(s_d, route.length - 0.05) + 1e-6]
            if not self._clear(pts, humans):
                continue
            poses = self._shape(pts, robot)
            back_s = float(Polyline(poses).project(*self._beside(s_c, y)).s)
            return _Detour(poses, side, back_s, abs(y - e) - self._need(0.0))
        return None

    def _beside(self, s: float, offset: float) -> Point:
        q = self.route.point_at(s)
        n = self._normal(self.route, s)
        return (q[0] + n[0] * offset, q[1] + n[1] * offset)

    def _clear(self, pts: Sequence[Point], humans: Sequence[Point]) -> bool:
        """Every leg free of walls, and every person further than the "on the path" distance."""
        a, b = np.array(pts[:-1]), np.array(pts[1:])
        if not self.planner.visible(a, b).all():
            return False
        line = Polyline(pts)
        return all(line.project(h[0], h[1]).distance >= self.block_distance_m for h in humans)

    def _maybe_revert(self, robot: Pose2D, humans: Sequence[Point], now: float, out: NavOutput) -> None:
        """The person left the route or is passed: back to the centre line, as HAVEN's robot did."""
        if self._on_path(self.route, self._route_s, humans) is not None:
            return
        here = self._signed_offset(self.route, self._route_s, (robot.x, robot.y))
        if abs(here) <= self.params.diverge_m:  # not off the route yet: follow it again as it was
            self._follow(self.original, NavState.FOLLOWING)
            self._progress = self._line.project(robot.x, robot.y).s
            out.path = self.original
            out.events.append(self._event(EventKind.REVERTED, now))
            return
        s_d = self._route_s + abs(here) / math.tan(math.radians(self.params.pass_angle_deg))
        pts: list[Point] = [(robot.x, robot.y)]
        if s_d < self.route.length - 0.05:
            pts.append(self.route.point_at(s_d))
        pts += [(float(x), float(y)) for (x, y), c in zip(self.route.points, self.route.cumulative) if c > min(s_d, self.route.length - 0.05) + 1e-6]
        if not self._clear(pts, humans):
            return
        poses = self._shape(pts, robot)
        self._follow(poses, NavState.FOLLOWING)
        out.path = poses
        out.events.append(self._event(EventKind.REVERTED, now))

    # -- re-planning around people (where no passing line fits) --------------------------------------
    def _replan_around(self, robot: Pose2D, person: _OnPath, humans: Sequence[Point], now: float) -> _Detour | None:
        """Re-plan with every person as an obstacle and a wall from the blocking person across the
        side with less room (so the detour keeps to the roomier side). A whole new map is costly:
        tried at most every `REPLAN_RETRY_S`."""
        assert self.goal is not None
        if now - self._replan_tried_at < REPLAN_RETRY_S:
            return None
        self._replan_tried_at = now
        human = person.xy
        n = self._normal(self._line, person.s)
        room_left = self.planner.free_run(human, n)
        room_right = self.planner.free_run(human, (-n[0], -n[1]))
        side = "left" if room_left >= room_right else "right"
        closed = (-n[0], -n[1]) if side == "left" else n
        if max(room_left, room_right) - self.planner_params.inflation_m < self._need(self.params.min_pass_clearance_m) - HUMAN_BODY.radius_m:
            return None
        radius = HUMAN_BODY.radius_m + self.params.path_clearance_m  # as wide as the "on the path" test
        grid = with_people(
            self.grid, humans, radius, human, closed, min(room_left if side == "right" else room_right, 10.0) + self.planner_params.inflation_m
        )
        planner = GridPlanner(grid, self.planner_params)
        try:
            plan = planner.plan((robot.x, robot.y), (self.goal.x, self.goal.y))
        except PlanningError:
            return None
        line = Polyline(plan.points)
        gap = min(line.project(h[0], h[1]).distance for h in humans) - self._need(0.0)
        if gap < self.params.path_clearance_m:
            return None
        return _Detour(self._shape(plan.points, robot, planner), side, math.inf, gap)
