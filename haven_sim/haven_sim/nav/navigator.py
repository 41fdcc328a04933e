"""Human-aware navigation to one goal at a time: plan, watch the path for people, wait or detour.

HAVEN's rule (paper, object retrieval): when a human stands on the robot's upcoming path, the robot
waits if the human is within `wait_distance` of the robot or of its goal, and otherwise re-plans
around the human, signalling the side; if the human leaves the original path before the robot
reaches the detour, it returns to the original path. The same logic serves the hallway (a person
on the centre line) and the room (a person on the projected path).

Everything is a pure function of the poses given, so a node and batch mode behave the same.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from enum import Enum
from typing import Any

import numpy as np

from haven_sim.common.geometry import FloatArray, Point, Pose2D
from haven_sim.sim.occupancy import OCCUPIED, OccupancyGridData
from haven_sim.nav.path_style import StyleParams, shape_path
from haven_sim.nav.planner import GridPlanner, Plan, PlannerParams, PlanningError


@dataclass(frozen=True)
class NavigatorParams:
    wait_distance_m: float = 2.0
    human_radius_m: float = 0.25
    path_clearance_m: float = 0.1  # a human this close to the robot's swept path blocks it
    diverge_m: float = 0.15  # where a detour leaves the original path
    goal_tolerance_m: float = 0.1
    use_goal_yaw: bool = True


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
    events: list[dict[str, Any]] = field(default_factory=list)


def _poly(poses: Sequence[Pose2D]) -> FloatArray:
    return np.array([(p.x, p.y) for p in poses], dtype=float).reshape(-1, 2)


def distance_to_polyline(pts: FloatArray, x: float, y: float) -> tuple[float, int]:
    """Distance from (x, y) to a polyline and the index of the nearest segment's start."""
    if len(pts) == 1:
        return math.hypot(pts[0, 0] - x, pts[0, 1] - y), 0
    a, b = pts[:-1], pts[1:]
    d = b - a
    ln2 = np.einsum("ij,ij->i", d, d)
    t = np.clip(np.einsum("ij,ij->i", np.array([x, y]) - a, d) / np.where(ln2 > 0, ln2, 1.0), 0.0, 1.0)
    c = a + d * t[:, None]
    dist = np.hypot(c[:, 0] - x, c[:, 1] - y)
    k = int(np.argmin(dist))
    return float(dist[k]), k


class Navigator:
    def __init__(
        self,
        grid: OccupancyGridData,
        planner: PlannerParams | None = None,
        style: StyleParams | None = None,
        params: NavigatorParams | None = None,
    ) -> None:
        self.planner_params = planner or PlannerParams()
        self.style = style or StyleParams()
        self.params = params or NavigatorParams()
        self.set_map(grid)
        self.state = NavState.IDLE
        self.goal: Pose2D | None = None
        self.original: list[Pose2D] = []
        self.active: list[Pose2D] = []
        self.detour_side = ""
        self._progress = 0  # index into `active` of the segment the robot is on
        self._diverge = 0  # index into `active` (a detour) where it leaves the original path

    def set_map(self, grid: OccupancyGridData) -> None:
        self.grid = grid
        self.planner = GridPlanner(grid, self.planner_params)

    @property
    def block_distance_m(self) -> float:
        return self.params.human_radius_m + self.planner_params.robot_radius_m + self.params.path_clearance_m

    # -- planning ----------------------------------------------------------------------------------
    def _shape(self, plan: Plan, robot: Pose2D, planner: GridPlanner) -> list[Pose2D]:
        # A NaN goal yaw means "any heading": no final rotation.
        goal_yaw = self.goal.yaw if (self.goal is not None and self.params.use_goal_yaw and math.isfinite(self.goal.yaw)) else None
        hard = planner.hard_clear
        return shape_path(plan.points, robot.yaw, self.style, hard, goal_yaw)

    def set_goal(self, robot: Pose2D, goal: Pose2D) -> NavOutput:
        out = NavOutput()
        try:
            plan = self.planner.plan((robot.x, robot.y), (goal.x, goal.y))
        except PlanningError as e:
            self.state, self.goal, self.original, self.active = NavState.IDLE, None, [], []
            out.path, out.waiting = [], False
            out.events.append({"type": "plan_refused", "goal": [round(goal.x, 3), round(goal.y, 3)], "reason": str(e)})
            return out
        self.goal = goal
        poses = self._shape(plan, robot, self.planner)
        self.original = self.active = poses
        self.state, self._progress, self.detour_side = NavState.FOLLOWING, 0, ""
        out.path, out.waiting = poses, False
        out.events.append({"type": "plan_made", "goal": [round(goal.x, 3), round(goal.y, 3)], "length_m": round(plan.length_m, 3), "poses": len(poses)})
        return out

    def cancel(self) -> NavOutput:
        self.state, self.goal, self.original, self.active = NavState.IDLE, None, [], []
        return NavOutput(path=[], waiting=False, events=[{"type": "goal_cancelled"}])

    # -- watching ----------------------------------------------------------------------------------
    def _advance(self, robot: Pose2D) -> None:
        pts = _poly(self.active)
        if len(pts) < 2:
            return
        lo = self._progress
        hi = min(len(pts), lo + 40)
        _, k = distance_to_polyline(pts[lo:hi], robot.x, robot.y)
        self._progress = lo + k

    def _blocker(self, path: Sequence[Pose2D], start: int, humans: Sequence[Point]) -> Point | None:
        """The nearest human standing on the path from index `start` on, if any."""
        rest = _poly(path[start:])
        best: tuple[int, Point] | None = None
        for h in humans:
            d, k = distance_to_polyline(rest, h[0], h[1])
            if d < self.block_distance_m and (best is None or k < best[0]):
                best = (k, h)
        return None if best is None else best[1]

    def update(self, robot: Pose2D, humans: Sequence[Point]) -> NavOutput:
        out = NavOutput()
        if self.state is NavState.IDLE or self.goal is None:
            return out
        if math.hypot(robot.x - self.goal.x, robot.y - self.goal.y) <= self.params.goal_tolerance_m:
            self.state = NavState.IDLE
            return out
        self._advance(robot)
        if self.state is NavState.WAITING:
            if self._blocker(self.active, self._progress, humans) is None:
                self.state = NavState.DETOUR if self.active is not self.original else NavState.FOLLOWING
                out.waiting = False
                out.events.append({"type": "resumed"})
            return out
        if self.state is NavState.DETOUR and self._progress < self._diverge:
            _, behind = distance_to_polyline(_poly(self.original), robot.x, robot.y)
            if self._blocker(self.original, behind, humans) is None:
                # The human left the original path before the robot reached the detour: go back.
                self.active, self.state, self._progress, self.detour_side = self.original, NavState.FOLLOWING, 0, ""
                self._advance(robot)
                out.path = self.original
                out.events.append({"type": "reverted"})
                return out
        human = self._blocker(self.active, self._progress, humans)
        if human is None:
            return out
        to_robot = math.hypot(human[0] - robot.x, human[1] - robot.y)
        to_goal = math.hypot(human[0] - self.goal.x, human[1] - self.goal.y)
        if to_robot <= self.params.wait_distance_m or to_goal <= self.params.wait_distance_m:
            near = "robot" if to_robot <= to_goal else "goal"
            return self._wait(out, f"human on the path {min(to_robot, to_goal):.1f} m from the {near}", human)
        detour = self._detour(robot, human, humans)
        if detour is None:
            return self._wait(out, "human on the path and no room to pass", human)
        poses, side = detour
        self.active, self.state, self._progress, self.detour_side = poses, NavState.DETOUR, 0, side
        self._diverge = self._divergence(poses)
        out.path = poses
        out.events.append({"type": "replanned", "reason": "human on the path", "side": side, "human": [round(human[0], 3), round(human[1], 3)]})
        return out

    def _wait(self, out: NavOutput, reason: str, human: Point) -> NavOutput:
        self.state = NavState.WAITING
        out.waiting = True
        out.events.append({"type": "waiting", "reason": reason, "human": [round(human[0], 3), round(human[1], 3)]})
        return out

    def _divergence(self, detour: Sequence[Pose2D]) -> int:
        original = _poly(self.original)
        for i, p in enumerate(detour):
            if distance_to_polyline(original, p.x, p.y)[0] > self.params.diverge_m:
                return i
        return len(detour)

    def _detour(self, robot: Pose2D, human: Point, humans: Sequence[Point]) -> tuple[list[Pose2D], str] | None:
        """Re-plan with the human as an obstacle, passing on the side with more room."""
        assert self.goal is not None
        pts = _poly(self.active)
        _, k = distance_to_polyline(pts, human[0], human[1])
        k = min(k, len(pts) - 2)
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
        radius = self.params.human_radius_m + self.params.path_clearance_m
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
