"""The planner: /goal_pose in, /plan out in HAVEN's rotate / arc / straight style, human-aware.

`PlannerComponent` is the whole planner node without ROS. It plans on whatever /map holds (ours or
any nav_msgs/OccupancyGrid) from the robot's /odom pose; a goal that comes before the map or the
pose waits (the newest one wins); a goal in a frame other than the map's, or with a position that
is not finite, is refused with an event. At `check_rate_hz` it watches /humans through the navigator:
a person on the upcoming path makes the robot pass them (a new /plan) or wait (/haven/wait). Given
the world's hallways (`lanes`), it routes the robot down their centre lines.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace

from haven_sim.common import contain, nodes, plugins, topics
from haven_sim.common.component import Handler, Message
from haven_sim.common.events import PLAN_POSES, EventKind, Source, event
from haven_sim.common.geometry import Pose2D
from haven_sim.common.params import POSITIVE, Bounds, config, group, param
from haven_sim.common.state import Goal, HumanPoses, RobotState
from haven_sim.nav.lanes import Lane
from haven_sim.nav.motion_style import MotionStyle
from haven_sim.nav.navigator import Navigator, NavOutput
from haven_sim.nav.navigator_params import NavigatorParams
from haven_sim.nav.path_style import ShapeParams
from haven_sim.nav.planner import PlannerParams
from haven_sim.nav.planner_kind import Contained, planner_class
from haven_sim.robots.fields import RobotChoice
from haven_sim.sim.occupancy import OccupancyGridData
from haven_sim.sim.world import World

ODOM_FRAME = "odom"  # coincides with the map frame while odometry has no drift
STORM_QUIET_S = 1.0  # sim time without a goal that ends a goal storm


@dataclass
class GoalStorm:
    start: float
    goals: int  # received since the quiet spell before it
    superseded: int = 0  # replaced before they were planned


@config
class PlannerConfig:
    robot: RobotChoice = group(RobotChoice)
    planner: PlannerParams = group(PlannerParams)
    shape: ShapeParams = group(ShapeParams)
    style: MotionStyle = group(MotionStyle)
    navigator: NavigatorParams = group(NavigatorParams)
    algorithm: str = param(
        "visibility",
        "the path planner: a registered planner (haven plugins), "
        "whose points are shaped into arcs, straights and rotations",
    )
    check_rate_hz: float = param(5.0, "how often the path is checked for people (sim time)", POSITIVE)
    goal_interval_s: float = param(
        0.1,
        "goals closer together than this (sim time) are coalesced: "
        "the newest is planned once it has passed (a goal storm: one plan each)",
        Bounds(0.0, 10.0),
    )
    map_frame: str = param("map", "frame of /plan and of accepted goals")
    world: str = param(
        "",
        "world file whose hallway centre lines the robot keeps to ('': plan on /map alone; haven run passes its world)",
    )

    def __post_init__(self) -> None:
        registered = plugins.registry("planners")
        if self.algorithm not in registered:
            raise ValueError(f"algorithm: {registered.unknown(self.algorithm)}")


def world_lanes(world: World) -> tuple[Lane, ...]:
    """The world's hallways as lanes for the navigator."""
    return tuple(Lane(h.centreline, h.width) for h in world.hallways)


class PlannerComponent:
    name = nodes.PLANNER.name
    unread: frozenset[str] = frozenset()

    def __init__(self, config: PlannerConfig | None = None, lanes: Sequence[Lane] = ()) -> None:
        self.config = config or PlannerConfig()
        self.lanes = tuple(lanes)
        self.nav: Navigator | None = None
        self.robot: Pose2D | None = None
        self.humans: list[tuple[float, float]] = []
        self.pending: Pose2D | None = None  # the newest goal not planned yet (no map or pose yet, or coalesced)
        self.planned_at: float | None = None  # when the last goal was planned (sim time)
        self.storm: GoalStorm | None = None  # goals coming faster than goal_interval_s
        self.last_goal: float | None = None  # when the last goal came (sim time)
        self.burst, self.burst_start = 0, 0.0  # goals since the last STORM_QUIET_S without one, and when the first came
        self.notes: list[str] = []  # for the node's log
        self.warnings: list[str] = []
        self.told_failure = False  # the lab's planner failed and a `plugin_failed` event said so

    @property
    def period_s(self) -> float:
        return 1.0 / self.config.check_rate_hz

    def handlers(self) -> Mapping[str, Handler]:
        return {
            topics.MAP: self.on_map,
            topics.ODOM: self.on_odom,
            topics.HUMANS: self.on_humans,
            topics.GOAL: self.on_goal,
            topics.CANCEL_GOAL: self.on_cancel,
        }

    def outputs(self) -> Sequence[str]:
        return (topics.PLAN, topics.WAIT, topics.EVENTS)

    def on_map(self, grid: OccupancyGridData, now: float) -> list[Message]:
        c = self.config
        if self.nav is None:
            self.nav = Navigator(grid, c.planner, c.shape, c.navigator, c.style, self.lanes, planner_class(c.algorithm))
        else:
            self.nav.set_map(grid)
        self.notes.append(
            f"map {grid.width} x {grid.height} at {grid.resolution_m:g} m; path planner {self.config.algorithm}"
        )
        return self._try_pending(now)

    def on_odom(self, state: RobotState, now: float) -> list[Message]:
        self.robot = state.pose
        return self._try_pending(now)

    def on_humans(self, humans: HumanPoses, now: float) -> list[Message]:
        self.humans = [(p.x, p.y) for p in humans.values()]
        return []

    def on_goal(self, goal: Goal, now: float) -> list[Message]:
        reason = self.refusal(goal)
        if reason is not None:
            self.warnings.append(f"refused goal: {reason}")
            refused = event(EventKind.PLAN_REFUSED, now, Source.PLANNER, reason=reason)
            return [Message(topics.EVENTS, refused, now)]
        if self.last_goal is None or now - self.last_goal >= STORM_QUIET_S:
            self.burst, self.burst_start = 0, now  # goals since the last quiet spell
        self.burst, self.last_goal = self.burst + 1, now
        # one not planned yet: the newest wins
        if self.pending is not None and self.nav is not None and self.robot is not None:
            if self.storm is None:
                self.storm = GoalStorm(self.burst_start, self.burst - 1)
                self.warnings.append(
                    "goal storm: goals closer together than "
                    f"{self.config.goal_interval_s:g} s; planning only the newest (counted)"
                )
            self.storm.superseded += 1
        if self.storm is not None:
            self.storm.goals += 1
        self.pending = goal.pose
        return self._try_pending(now)

    def on_cancel(self, by: str, now: float) -> list[Message]:
        """Drop the goal (and one not planned yet): the robot stops; said in a `goal_cancelled` event."""
        had = self.pending is not None or (self.nav is not None and self.nav.goal is not None)
        self.pending = None
        if self.nav is None or not had:
            return []
        cancelled = event(EventKind.GOAL_CANCELLED, now, Source.PLANNER, by=by or "unknown")
        return [*self._messages(self.nav.cancel(), now), Message(topics.EVENTS, cancelled, now)]

    def refusal(self, goal: Goal) -> str | None:
        """Why a goal cannot even be planned for, or None."""
        frame = goal.frame or self.config.map_frame
        if frame not in (self.config.map_frame, ODOM_FRAME):
            return f"goal frame '{frame}' is not '{self.config.map_frame}'"
        if not (math.isfinite(goal.pose.x) and math.isfinite(goal.pose.y)):
            return "goal position is not finite"
        return None

    def _try_pending(self, now: float) -> list[Message]:
        if self.pending is None or self.nav is None or self.robot is None:
            return []
        if self.planned_at is not None and now - self.planned_at < self.config.goal_interval_s - 1e-9:
            return []  # coalesced: planned once the interval has passed (at an /odom or the next check)
        goal, self.pending, self.planned_at = self.pending, None, now
        out = self.nav.set_goal(self.robot, goal, now)
        self.warnings += [
            f"refused goal ({goal.x:.2f}, {goal.y:.2f}): {e['reason']}"
            for e in out.events
            if e.kind is EventKind.PLAN_REFUSED
        ]
        return self._messages(out, now)

    def tick(self, now: float) -> list[Message]:
        if self.nav is None or self.robot is None:
            return []
        out = self._try_pending(now) + self._storm_over(now)
        return self._failures(now) + out + self._messages(self.nav.update(self.robot, self.humans, now), now)

    def _failures(self, now: float) -> list[Message]:
        """A `plugin_failed` event for the lab's planner's first failure (common/contain.py): the trial ends, not
        valid."""
        search = self.nav.search_class if self.nav is not None else None
        if not isinstance(search, Contained) or not search.failed or self.told_failure:
            return []
        self.told_failure = True
        self.warnings.append(search.failed[0].reason)
        return [Message(topics.EVENTS, contain.failed_event(search.failed[0], now, Source.PLANNER), now)]

    def _storm_over(self, now: float) -> list[Message]:
        """A goal storm ends after STORM_QUIET_S without a goal: one event with how many it brought."""
        storm, last = self.storm, self.last_goal or 0.0
        if storm is None or self.pending is not None or now - last < STORM_QUIET_S:
            return []
        self.storm, seconds = None, round(last - storm.start, 3)
        self.notes.append(f"goal storm over: {storm.goals} goals in {seconds:g} s, {storm.superseded} never planned")
        e = event(
            EventKind.GOAL_STORM, now, Source.PLANNER, goals=storm.goals, superseded=storm.superseded, seconds=seconds
        )
        return [Message(topics.EVENTS, e, now)]

    @staticmethod
    def _messages(out: NavOutput, now: float) -> list[Message]:
        """The events, the first of them tagged with the poses of the /plan that goes with it
        (`plan_poses`: the validity check finds each plan in a recording by it)."""
        events = list(out.events)
        if out.path is not None and events:
            events[0] = replace(events[0], data={**events[0].data, PLAN_POSES: len(out.path)})
        msgs = [Message(topics.EVENTS, e, now) for e in events]
        if out.path is not None:
            msgs.append(Message(topics.PLAN, out.path, now))
        if out.waiting is not None:
            msgs.append(Message(topics.WAIT, out.waiting, now))
        return msgs
