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
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from enum import Enum
from typing import Any

import numpy as np

from haven_sim.common import contain
from haven_sim.common.bodies import HUMAN_BODY
from haven_sim.common.events import Event, EventKind, Source, event
from haven_sim.common.geometry import Point, Pose2D
from haven_sim.common.polyline import Polyline
from haven_sim.nav.lanes import Lane, onto_lanes
from haven_sim.nav.motion_style import MotionStyle
from haven_sim.nav.navigator_params import NavigatorParams
from haven_sim.nav.passing import beside, normal_at, offset_from, room_beside
from haven_sim.nav.path_style import ShapeParams, shape_path
from haven_sim.nav.people_map import with_people
from haven_sim.nav.planner import GridPlanner, Plan, PlanFailure, PlannerParams, PlanningError
from haven_sim.nav.planner_kind import PathSearch
from haven_sim.sim.occupancy import OccupancyGridData

REPLAN_RETRY_S = 2.0
REJOIN_MIN_M = 0.3  # a return to the route meets it at least this far ahead
ONCOMING_MPS = 0.2  # a person coming toward the robot faster than this along its path is oncoming


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
        search: Callable[[OccupancyGridData, PlannerParams], PathSearch] | None = None,
    ) -> None:
        self.planner_params = planner or PlannerParams()
        # The path search (a `haven.planners` plugin; ours by default); the map's geometry (free
        # runs, line of sight) is always asked of our GridPlanner.
        self.search_class = search if search is not None and search is not GridPlanner else None
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
        self._seen: tuple[float, list[Point], Point] | None = None  # (when, the people, the robot) at this check
        self._before: tuple[float, list[Point], Point] | None = None  # ... and at the one before

    def set_map(self, grid: OccupancyGridData) -> None:
        self.grid = grid
        self.planner = GridPlanner(grid, self.planner_params)
        self.search = self._searcher(grid, self.planner)

    def _searcher(self, grid: OccupancyGridData, ours: GridPlanner) -> PathSearch:
        return self.search_class(grid, self.planner_params) if self.search_class is not None else ours

    def _plan(self, search: PathSearch, start: Point, goal: Point) -> Plan:
        """A plan from `search`; a lab's planner that fails otherwise than with PlanningError
        refuses the goal with what it raised (the trial goes on; ours is trusted)."""
        if self.search_class is None:
            return search.plan(start, goal)
        try:
            return search.plan(start, goal)
        except PlanningError:
            raise
        except Exception as e:
            raise PlanningError(f"the planner failed: {contain.failure(e)}", PlanFailure.UNKNOWN) from None

    @property
    def block_distance_m(self) -> float:
        return HUMAN_BODY.radius_m + self.planner_params.body_radius_m + self.params.path_gap_m

    # -- planning ----------------------------------------------------------------------------------
    def _goal_yaw(self) -> float | None:
        # A NaN goal yaw means "any heading": no final rotation.
        goal = self.goal
        return goal.yaw if (goal is not None and self.params.use_goal_yaw and math.isfinite(goal.yaw)) else None

    def _shape(self, points: Sequence[Point], robot: Pose2D, planner: GridPlanner | None = None) -> list[Pose2D]:
        return shape_path(
            points, robot.yaw, self.style, self.shape, (planner or self.planner).hard_clear, self._goal_yaw()
        )

    def _event(self, kind: EventKind, now: float, **data: Any) -> Event:
        return event(kind, now, Source.PLANNER, **data)

    def _visible(self, a: Point, b: Point) -> bool:
        return bool(self.planner.visible(np.array([a]), np.array([b]))[0])

    def set_goal(self, robot: Pose2D, goal: Pose2D, now: float) -> NavOutput:
        out = NavOutput()
        try:
            plan = self._plan(self.search, (robot.x, robot.y), (goal.x, goal.y))
        except PlanningError as e:
            out = self.cancel()
            out.events.append(
                self._event(EventKind.PLAN_REFUSED, now, goal=_xy((goal.x, goal.y)), reason=str(e), failure=e.failure)
            )
            return out
        self.goal = goal
        points = onto_lanes(plan.points, self.lanes, self._visible) if self.lanes else plan.points
        self.route = Polyline(points)
        self._route_s = 0.0
        poses = self._shape(points, robot)
        self._follow(poses, NavState.FOLLOWING)
        self.original = poses
        out.path, out.waiting = poses, False
        out.events.append(
            self._event(
                EventKind.PLAN_MADE,
                now,
                goal=_xy((goal.x, goal.y)),
                length_m=round(self.route.length, 3),
                poses=len(poses),
            )
        )
        return out

    def cancel(self) -> NavOutput:
        """Drop the goal: an empty path (the controller stops at once) and no waiting."""
        self.state, self.goal, self.original, self.active = NavState.IDLE, None, [], []
        out = NavOutput()
        out.path, out.waiting = [], False
        return out

    def _follow(self, poses: list[Pose2D], state: NavState, back_s: float = math.inf) -> None:
        self.active, self.state, self._progress, self._back_s = poses, state, 0.0, back_s
        self._line = Polyline(poses)

    # -- watching ----------------------------------------------------------------------------------
    def _advance(self, robot: Pose2D) -> None:
        if len(self._line) >= 2:
            self._progress = max(
                self._progress, self._line.project(robot.x, robot.y, self._progress, self._progress + 16.0).s
            )
        if len(self.route) >= 2:
            self._route_s = max(
                self._route_s, self.route.project(robot.x, robot.y, self._route_s, self._route_s + 16.0).s
            )

    def _on_path(
        self, line: Polyline, s_from: float, humans: Sequence[Point], within: float | None = None
    ) -> _OnPath | None:
        """The person ahead on `line` (from arc length `s_from`; closer to it than `within`, by
        default the "on the path" distance) that the robot meets first."""
        best: _OnPath | None = None
        for h in humans:
            proj = line.project(h[0], h[1], s_from)
            if (
                proj.distance < (within or self.block_distance_m)
                and proj.s > s_from + 1e-6
                and (best is None or proj.s < best.s)
            ):
                best = _OnPath(proj.s, offset_from(line, proj.s, h), h)
        return best

    def update(self, robot: Pose2D, humans: Sequence[Point], now: float) -> NavOutput:
        out = NavOutput()
        if self.state is NavState.IDLE or self.goal is None:
            return out
        if math.hypot(robot.x - self.goal.x, robot.y - self.goal.y) <= self.params.goal_tolerance_m:
            self.state = NavState.IDLE
            return out
        self._advance(robot)
        seen, self._seen = self._seen, (now, list(humans), (robot.x, robot.y))
        self._before = seen
        person = self._on_path(self._line, self._progress, humans)
        if person is None:
            if self.state is NavState.DETOUR and self._progress < self._back_s:
                self._maybe_revert(robot, humans, now, out)
            elif self.state is NavState.WAITING:
                self._resume(out, now)
            return out
        gap = person.s - self._progress
        towards, ahead = self._speeds(person, robot, humans, now)
        if gap > self.params.pass_start_m and gap > self.params.pass_start_s * max(0.0, towards + ahead):
            if self.state is NavState.WAITING:
                self._resume(out, now)
            return out
        # A person close ahead on the path: pass them if there is room, else wait when near. One
        # standing at the robot's next stop cannot be passed (no way back onto the route after them).
        at_stop = self.route.length - self.route.project(*person.xy).s < self._past + 0.05
        passing = None if at_stop else self._pass(robot, person, humans, towards > ONCOMING_MPS)
        # not round someone at arm's length
        if passing is None and not at_stop and gap > self._need(self.params.pass_gap_m):
            passing = self._replan_around(robot, person, humans, now)
        if passing is not None:
            if self.state is NavState.WAITING:
                out.waiting = False
                out.events.append(self._event(EventKind.RESUMED, now))
            self._follow(passing.poses, NavState.DETOUR, passing.back_s)
            self.side = passing.side
            out.path = passing.poses
            data = {
                "side": passing.side,
                "human": _xy(person.xy),
                "gap_m": round(gap, 2),
                "clearance_m": round(passing.clearance_m, 2),
            }
            out.events.append(self._event(EventKind.REPLANNED, now, reason="human on the path", **data))
            return out
        wait_gap = self.params.wait_distance_m  # (beyond the arm's length below, where re-planning is not tried)
        if (gap <= wait_gap or (at_stop and gap <= wait_gap + 1.0)) and self.state is not NavState.WAITING:
            reason = "human at the robot's next stop" if at_stop else "human on the path and no room to pass"
            self.state = NavState.WAITING
            out.waiting = True
            out.events.append(
                self._event(EventKind.WAITING, now, reason=f"{reason}, {gap:.1f} m ahead", human=_xy(person.xy))
            )
        return out

    def _speeds(self, person: _OnPath, robot: Pose2D, humans: Sequence[Point], now: float) -> tuple[float, float]:
        """(the person's speed toward the robot, the robot's speed), along the path there, from the
        last check (zeros at the first)."""
        seen = self._before
        if seen is None or now <= seen[0] or len(seen[1]) != len(humans):
            return 0.0, 0.0
        dt = now - seen[0]
        (px, py), (rx, ry) = seen[1][list(humans).index(person.xy)], seen[2]
        n = normal_at(self._line, person.s)
        tx, ty = n[1], -n[0]  # the path's direction there
        towards = -((person.xy[0] - px) * tx + (person.xy[1] - py) * ty) / dt
        return towards, ((robot.x - rx) * tx + (robot.y - ry) * ty) / dt

    def _resume(self, out: NavOutput, now: float) -> None:
        self.state = NavState.DETOUR if self.active is not self.original else NavState.FOLLOWING
        out.waiting = False
        out.events.append(self._event(EventKind.RESUMED, now))

    # -- passing -----------------------------------------------------------------------------------
    def _need(self, clearance: float) -> float:
        """Centre-to-centre lateral distance that leaves `clearance` between robot and person."""
        return HUMAN_BODY.radius_m + self.planner_params.body_radius_m + clearance

    @property
    def _past(self) -> float:
        """How far beyond a person, along the route, the passing line is held."""
        return self._need(self.params.pass_gap_m) + HUMAN_BODY.radius_m

    def _pass(self, robot: Pose2D, person: _OnPath, humans: Sequence[Point], oncoming: bool = False) -> _Detour | None:
        """Figure 3: a curve out to a line beside the person on the side with room, held past
        them, and a curve back to the route; None if it does not fit."""
        p = self.params
        route = self.route
        s_r = self._route_s
        s_h = route.project(*person.xy).s
        e = offset_from(route, s_h, person.xy)
        around = (s_h - self._past, s_h + self._past)
        room = {
            side: room_beside(route, self.planner, *around, sign) for side, sign in (("left", 1.0), ("right", -1.0))
        }
        lateral = {
            "left": min(room["left"], e + self._need(p.pass_gap_m)),
            "right": -min(room["right"], -e + self._need(p.pass_gap_m)),
        }
        fits = {side: abs(lateral[side] - e) >= self._need(p.min_pass_gap_m) - 1e-9 for side in lateral}
        # Someone coming the other way is passed on the right, as people keep right (they do the
        # same); someone standing on the side with more room beside them (the right on a tie). A
        # detour keeps its side while that still fits.
        free = {"left": room["left"] - e, "right": room["right"] + e}
        order = ["right", "left"] if oncoming else sorted(("right", "left"), key=lambda side: -round(free[side], 2))
        if self.state is NavState.DETOUR and self.side in order:
            order.remove(self.side)
            order.insert(0, self.side)
        here = offset_from(route, s_r, (robot.x, robot.y))
        tan = math.tan(math.radians(p.pass_angle_deg))
        steep = math.tan(min(self.style.arc_max_angle_rad * 0.9, math.radians(55.0)))
        past = self._past
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
            pts: list[Point] = [(robot.x, robot.y)]
            if lead > 0.05:
                pts.append(beside(self.route, s_a, here))
            pts += [beside(self.route, s_b, y), beside(self.route, s_c, y), *self._rejoin(s_d)]
            if not self._clear(pts, humans):
                continue
            poses = self._shape(pts, robot)
            back_s = float(Polyline(poses).project(*beside(self.route, s_c, y)).s)
            return _Detour(poses, side, back_s, abs(y - e) - self._need(0.0))
        return None

    def _rejoin(self, s: float) -> list[Point]:
        """The route from arc length s (where a detour meets it again) to its end."""
        route, end = self.route, self.route.length - 0.05
        back = [route.point_at(s)] if s < end else []
        return back + [
            (float(x), float(y))
            for (x, y), c in zip(route.points, route.cumulative, strict=True)
            if c > min(s, end) + 1e-6
        ]

    def _clear(self, pts: Sequence[Point], humans: Sequence[Point], by: float | None = None) -> bool:
        """Every leg free of walls, and every person further than `by` (default: the "on the path"
        distance)."""
        a, b = np.array(pts[:-1]), np.array(pts[1:])
        if not self.planner.visible(a, b).all():
            return False
        line = Polyline(pts)
        return all(line.project(h[0], h[1]).distance >= (by or self.block_distance_m) for h in humans)

    def _maybe_revert(self, robot: Pose2D, humans: Sequence[Point], now: float, out: NavOutput) -> None:
        """The person left the route or is passed: back to the centre line, as HAVEN's robot did.
        "Left" means far enough aside that the robot passes them with `pass_gap_m` on the
        centre line; nearer than that, the robot keeps its passing line."""
        passing = self._need(self.params.pass_gap_m)
        if self._on_path(self.route, self._route_s, humans, within=passing) is not None:
            return
        here = offset_from(self.route, self._route_s, (robot.x, robot.y))
        # Back onto the route at the passing angle (a robot not off it yet just goes on along it),
        # as a path from where the robot is: never the whole route again from its start.
        s_d = self._route_s + max(abs(here) / math.tan(math.radians(self.params.pass_angle_deg)), REJOIN_MIN_M)
        pts: list[Point] = [(robot.x, robot.y), *self._rejoin(s_d)]
        if not self._clear(pts, humans, by=passing):
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
        n = normal_at(self._line, person.s)
        room_left = self.planner.free_run(human, n)
        room_right = self.planner.free_run(human, (-n[0], -n[1]))
        side = "left" if room_left >= room_right else "right"
        closed = (-n[0], -n[1]) if side == "left" else n
        if (
            max(room_left, room_right) - self.planner_params.inflation_m
            < self._need(self.params.min_pass_gap_m) - HUMAN_BODY.radius_m
        ):
            return None
        radius = HUMAN_BODY.radius_m + self.params.path_gap_m  # as wide as the "on the path" test
        grid = with_people(
            self.grid,
            humans,
            radius,
            human,
            closed,
            min(room_left if side == "right" else room_right, 10.0) + self.planner_params.inflation_m,
        )
        planner = GridPlanner(grid, self.planner_params)
        try:
            plan = self._plan(self._searcher(grid, planner), (robot.x, robot.y), (self.goal.x, self.goal.y))
        except PlanningError:
            return None
        line = Polyline(plan.points)
        gap = min(line.project(h[0], h[1]).distance for h in humans) - self._need(0.0)
        if gap < self.params.path_gap_m:
            return None
        return _Detour(self._shape(plan.points, robot, planner), side, math.inf, gap)
