"""Human-aware navigation to one goal at a time: plan, watch the path for people, wait or detour.

HAVEN's rule (paper, object retrieval): when a human stands on the robot's upcoming path, the robot
waits if the human is within `wait_distance_m` of the robot or of its goal, and otherwise re-plans
around the human, signalling the side; if the human leaves the original path before the robot
reaches the detour, it returns to the original path. The same logic serves the hallway (a person
on the centre line) and the room (a person on the projected path).

Everything is a pure function of the poses and the time given, so a node and batch mode behave the
same.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from enum import Enum
from typing import Any

import numpy as np

from haven_sim.common.bodies import HUMAN_BODY
from haven_sim.common.events import Event, EventKind, Source, event
from haven_sim.common.geometry import Point, Pose2D
from haven_sim.common.params import param
from haven_sim.common.polyline import Polyline
from haven_sim.nav.motion_style import MotionStyle
from haven_sim.nav.path_style import ShapeParams, shape_path
from haven_sim.nav.planner import GridPlanner, Plan, PlannerParams, PlanningError
from haven_sim.sim.occupancy import OCCUPIED, OccupancyGridData


@dataclass(frozen=True)
class NavigatorParams:
    wait_distance_m: float = param(2.0, "HAVEN: a person on the path this close to the robot or its goal makes it wait")
    path_clearance_m: float = param(0.1, "a person within body radii + this of the upcoming path blocks it")
    diverge_m: float = param(0.15, "a detour starts where it is this far from the original path")
    goal_tolerance_m: float = param(0.1, "the goal counts as reached this close")
    use_goal_yaw: bool = param(True, "rotate to the goal's orientation at the end")

    def __post_init__(self) -> None:
        for name in ("wait_distance_m", "path_clearance_m", "diverge_m", "goal_tolerance_m"):
            if getattr(self, name) < 0:
                raise ValueError(f"{name} must not be negative, got {getattr(self, name)}")


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
    ) -> None:
        self.planner_params = planner or PlannerParams()
        self.shape = shape or ShapeParams()
        self.params = params or NavigatorParams()
        self.style = style or MotionStyle()
        self.set_map(grid)
        self.state = NavState.IDLE
        self.goal: Pose2D | None = None
        self.original: list[Pose2D] = []
        self.active: list[Pose2D] = []
        self._progress = 0.0  # arc length reached along `active`
        self._diverge = 0.0  # arc length along `active` (a detour) where it leaves the original path

    def set_map(self, grid: OccupancyGridData) -> None:
        self.grid = grid
        self.planner = GridPlanner(grid, self.planner_params)

    @property
    def block_distance_m(self) -> float:
        return HUMAN_BODY.radius_m + self.planner_params.body_radius_m + self.params.path_clearance_m

    # -- planning ----------------------------------------------------------------------------------
    def _shape(self, plan: Plan, robot: Pose2D, planner: GridPlanner) -> list[Pose2D]:
        # A NaN goal yaw means "any heading": no final rotation.
        goal = self.goal
        goal_yaw = goal.yaw if (goal is not None and self.params.use_goal_yaw and math.isfinite(goal.yaw)) else None
        return shape_path(plan.points, robot.yaw, self.style, self.shape, planner.hard_clear, goal_yaw)

    def _event(self, kind: EventKind, now: float, **data: Any) -> Event:
        return event(kind, now, Source.PLANNER, **data)

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
        poses = self._shape(plan, robot, self.planner)
        self._follow(poses, NavState.FOLLOWING)
        self.original = poses
        out.path, out.waiting = poses, False
        out.events.append(self._event(EventKind.PLAN_MADE, now, goal=_xy((goal.x, goal.y)), length_m=round(plan.length_m, 3), poses=len(poses)))
        return out

    def _follow(self, poses: list[Pose2D], state: NavState) -> None:
        self.active, self.state, self._progress = poses, state, 0.0
        self._line = Polyline(poses)

    # -- watching ----------------------------------------------------------------------------------
    def _advance(self, robot: Pose2D) -> None:
        if len(self._line) >= 2:
            self._progress = max(self._progress, self._line.project(robot.x, robot.y, self._progress, self._progress + 16.0).s)

    def _blocker(self, line: Polyline, s_from: float, humans: Sequence[Point]) -> Point | None:
        """The human standing on the path from arc length `s_from` on that the robot meets first."""
        best: tuple[float, Point] | None = None
        for h in humans:
            proj = line.project(h[0], h[1], s_from)
            if proj.distance < self.block_distance_m and (best is None or proj.s < best[0]):
                best = (proj.s, h)
        return None if best is None else best[1]

    def update(self, robot: Pose2D, humans: Sequence[Point], now: float) -> NavOutput:
        out = NavOutput()
        if self.state is NavState.IDLE or self.goal is None:
            return out
        if math.hypot(robot.x - self.goal.x, robot.y - self.goal.y) <= self.params.goal_tolerance_m:
            self.state = NavState.IDLE
            return out
        self._advance(robot)
        if self.state is NavState.WAITING:
            if self._blocker(self._line, self._progress, humans) is None:
                self.state = NavState.DETOUR if self.active is not self.original else NavState.FOLLOWING
                out.waiting = False
                out.events.append(self._event(EventKind.RESUMED, now))
            return out
        if self.state is NavState.DETOUR and self._progress < self._diverge:
            original = Polyline(self.original)
            behind = original.project(robot.x, robot.y).s
            if self._blocker(original, behind, humans) is None:
                # The human left the original path before the robot reached the detour: go back.
                self._follow(self.original, NavState.FOLLOWING)
                self._advance(robot)
                out.path = self.original
                out.events.append(self._event(EventKind.REVERTED, now))
                return out
        human = self._blocker(self._line, self._progress, humans)
        if human is None:
            return out
        to_robot = math.hypot(human[0] - robot.x, human[1] - robot.y)
        to_goal = math.hypot(human[0] - self.goal.x, human[1] - self.goal.y)
        if to_robot <= self.params.wait_distance_m or to_goal <= self.params.wait_distance_m:
            near = "robot" if to_robot <= to_goal else "goal"
            return self._wait(out, now, f"human on the path {min(to_robot, to_goal):.1f} m from the {near}", human)
        detour = self._detour(robot, human, humans)
        if detour is None:
            return self._wait(out, now, "human on the path and no room to pass", human)
        poses, side = detour
        self._follow(poses, NavState.DETOUR)
        self._diverge = self._divergence(poses)
        out.path = poses
        out.events.append(self._event(EventKind.REPLANNED, now, reason="human on the path", side=side, human=_xy(human)))
        return out

    def _wait(self, out: NavOutput, now: float, reason: str, human: Point) -> NavOutput:
        self.state = NavState.WAITING
        out.waiting = True
        out.events.append(self._event(EventKind.WAITING, now, reason=reason, human=_xy(human)))
        return out

    def _divergence(self, detour: Sequence[Pose2D]) -> float:
        original = Polyline(self.original)
        line = Polyline(detour)
        for i, p in enumerate(detour):
            if original.project(p.x, p.y).distance > self.params.diverge_m:
                return float(line.cumulative[i])
        return line.length

    def _detour(self, robot: Pose2D, human: Point, humans: Sequence[Point]) -> tuple[list[Pose2D], str] | None:
        """Re-plan with the human as an obstacle, passing on the side with more room."""
        assert self.goal is not None
        k = min(self._line.project(human[0], human[1]).segment, len(self._line) - 2)
        pts = self._line.points
        heading = math.atan2(pts[k + 1, 1] - pts[k, 1], pts[k + 1, 0] - pts[k, 0]) if len(pts) > 1 else robot.yaw
        left = (-math.sin(heading), math.cos(heading))
        room_left = self.planner.free_run(human, left)
        room_right = self.planner.free_run(human, (-left[0], -left[1]))
        side = "left" if room_left >= room_right else "right"
        closed = (-left[0], -left[1]) if side == "left" else left
        grid = self._with_humans(humans, human, closed, min(room_left if side == "right" else room_right, 10.0))
        planner = GridPlanner(grid, self.planner_params)
        try:
            plan = planner.plan((robot.x, robot.y), (self.goal.x, self.goal.y))
        except PlanningError:
            return None
        return self._shape(plan, robot, planner), side

    def _with_humans(self, humans: Sequence[Point], blocker: Point, closed: Point, closed_len: float) -> OccupancyGridData:
        """The map with every human as an obstacle, and a wall from the blocking human across the
        side the robot must not take."""
        g = self.grid
        data = g.data.copy()
        res = g.resolution_m
        # As wide as the "on the path" test, so that the detour itself does not count as blocked.
        radius = HUMAN_BODY.radius_m + self.params.path_clearance_m
        r_cells = int(math.ceil(radius / res))
        rr, cc = np.mgrid[-r_cells : r_cells + 1, -r_cells : r_cells + 1]
        disk = rr**2 + cc**2 <= (radius / res) ** 2
        marks: list[tuple[int, int]] = []
        for hx, hy in humans:
            r0, c0 = g.cell_of(hx, hy)
            marks += [(r0 + int(dr), c0 + int(dc)) for dr, dc in zip(rr[disk], cc[disk])]
        n = int(math.ceil((closed_len + self.planner_params.inflation_m) / (res / 2.0)))
        for i in range(n + 1):
            s = i * res / 2.0
            marks.append(g.cell_of(blocker[0] + closed[0] * s, blocker[1] + closed[1] * s))
        for r, c in marks:
            if 0 <= r < g.height and 0 <= c < g.width:
                data[r, c] = OCCUPIED
        return replace(g, data=data)
