"""compute_path_to_pose from HAVEN's planner, for the planner_server in nav2_node.

The path is the one our planner node would send on /plan for that goal (HAVEN's rotate / arc /
straight shape, down the world's hallway centre lines), from the request's start or the robot's
pose; nothing is driven. `planner_id` names a registered planner (`haven plugins`), '' the
configured one. The planner's parameters are the planner node's (PlannerConfig; the planner_server declares them).
"""

from __future__ import annotations

import threading
import time
from collections.abc import Sequence
from typing import Any

from nav2_msgs.action import ComputePathToPose

from haven_sim.common import topics
from haven_sim.common.events import EventKind
from haven_sim.common.geometry import Pose2D
from haven_sim.nav.navigator import Navigator
from haven_sim.nav.planner import PlanFailure
from haven_sim.nav.planner_kind import planner_class
from haven_sim.nav.planning import PlannerConfig, world_lanes
from haven_sim.nodes import conversions as conv, wire
from haven_sim.nodes.task_runner import TaskRunner, failure_code, unusable
from haven_sim.sim.occupancy import OccupancyGridData
from haven_sim.sim.world import resolve_world_path
from haven_sim.sim.world_file import load_world

Result = ComputePathToPose.Result


class PathPlanner:
    def __init__(self, node: Any, runner: TaskRunner, config: PlannerConfig) -> None:
        self.node, self.runner = node, runner
        self.config = c = config
        self.lanes = world_lanes(load_world(resolve_world_path(c.world))) if c.world else ()
        self.grid: OccupancyGridData | None = None
        self.navigators: dict[str, Navigator] = {}  # by planner name, for the map in hand
        self.lock = threading.Lock()
        spec = wire.specs()[topics.MAP]
        node.create_subscription(spec.msg_type, topics.MAP, self._on_map, spec.sub_qos)
        node.serve(ComputePathToPose, "compute_path_to_pose", self.compute, self._why)

    def _why(self, request: Any) -> str | None:
        """Why a request cannot be planned for, or None."""
        frame = self.config.map_frame
        return unusable("goal", request.goal, frame) or (
            unusable("start", request.start, frame) if request.use_start else None
        )

    def _on_map(self, msg: Any) -> None:
        grid = conv.occupancy_from_msg(msg)
        with self.lock:
            self.grid, self.navigators = grid, {}

    def first_outside(self, poses: Sequence[Pose2D]) -> int | None:
        """The index of the first pose outside the map (None: all inside, or no map yet)."""
        with self.lock:
            grid = self.grid
        if grid is None:
            return None
        cells = (grid.cell_of(p.x, p.y) for p in poses)
        return next((i for i, (r, c) in enumerate(cells) if not (0 <= r < grid.height and 0 <= c < grid.width)), None)

    def _navigator(self, planner_id: str) -> Navigator | str:
        """The navigator for `planner_id`, or why there is none."""
        name = planner_id or self.config.algorithm
        if self.grid is None:
            return "no /map yet"
        if name not in self.navigators:
            try:
                search = planner_class(name)
            except Exception as e:
                return str(e)
            c = self.config
            self.navigators[name] = Navigator(self.grid, c.planner, c.shape, c.navigator, c.style, self.lanes, search)
        return self.navigators[name]

    def compute(self, handle: Any) -> Any:
        request, result, started = handle.request, Result(), time.monotonic()
        now = self.runner.now()
        with self.lock:
            nav = self._navigator(request.planner_id)
            robot = self.runner.robot
            start = (
                conv.pose_from_stamped(request.start)
                if request.use_start
                else (robot.pose if robot is not None else None)
            )
            if isinstance(nav, str) or start is None:
                why = nav if isinstance(nav, str) else "no /odom yet (the robot's pose is the start)"
                result.error_code = (
                    Result.INVALID_PLANNER if isinstance(nav, str) and self.grid is not None else Result.UNKNOWN
                )
                result.error_msg = why
                handle.abort()
                return result
            out = nav.set_goal(start, conv.pose_from_stamped(request.goal), now)
            nav.cancel()  # (this navigator only plans)
        refused = [e for e in out.events if e.kind is EventKind.PLAN_REFUSED]
        result.planning_time = conv.duration_msg(time.monotonic() - started)
        if refused:
            e = refused[0]
            result.error_code, result.error_msg = failure_code(PlanFailure(e.data["failure"])), str(e.data["reason"])
            handle.abort()
            return result
        result.path = conv.path_msg(now, out.path or [], self.config.map_frame)
        handle.succeed()
        return result
