"""Nav2's task actions carried out by HAVEN's own planner and controller, without ROS.

A `NavTask` is one goal of navigate_to_pose, navigate_through_poses or follow_waypoints (its poses
visited in turn, each sent on /goal_pose as RViz sends one; navigate_through_poses heads for the
next once within reach of one on the way, as Nav2's does) or of follow_path (a path handed to the
controller on /plan). The planner's and controller's events say how it goes: `goal_reached` at
the pose being visited (the robot at rest there, its final turn done) moves on to the next pose
or succeeds; `plan_refused` fails it, with the planner's `failure` (the node turns it into Nav2's
error code); a plan for another goal (somebody else's /goal_pose) aborts it, as a newer goal
preempts an older one in Nav2; a cancel drops the goal on /haven/cancel_goal and stops the robot.

Feedback as bt_navigator gives it: the robot's pose, the distance left along the plan (and on to
the poses still to visit), an estimate of the time left, and the "recoveries": what the robot did
to get round people so far (each wait and each detour).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from enum import Enum, StrEnum

from haven_sim.common import topics
from haven_sim.common.component import Message
from haven_sim.common.events import Event, EventKind
from haven_sim.common.geometry import Pose2D
from haven_sim.common.params import POSITIVE, config, param
from haven_sim.common.polyline import Polyline
from haven_sim.common.state import Goal, RobotState
from haven_sim.nav.planner import PlanFailure

# A goal_reached counts for the pose being visited this close to it: the planner moves a goal up
# to its snap radius (PlannerParams.snap_radius_m, 0.3 m) off an obstacle, the follower stops
# within its goal tolerance (0.1 m).
GOAL_MATCH_M = 0.5
# bt_navigator estimates the time left only above these (navigate_to_pose.cpp, Nav2 1.3: "if speed
# is higher than 1cm/s and at least 10cm to go").
ETA_MIN_SPEED_MPS, ETA_MIN_DISTANCE_M = 0.01, 0.1
RECOVERIES = (EventKind.WAITING, EventKind.REPLANNED)  # the planner's ways round a person
# navigate_through_poses passes a pose on the way this close to it without stopping there (Nav2
# 1.3.13's navigate_through_poses_w_replanning_and_recovery.xml: RemovePassedGoals radius 0.7).
VIAPOINT_RADIUS_M = 0.7
# Nav2's progress checker (nav2_controller SimpleProgressChecker, required_movement_radius 0.5 m):
# a robot that has not moved this far in `progress_timeout_s` has failed to make progress.
PROGRESS_RADIUS_M = 0.5


@config
class Nav2TaskParams:
    progress_timeout_s: float = param(
        30.0,
        "a Nav2 task whose robot has not moved 0.5 m in this much sim time fails (FAILED_TO_MAKE_PROGRESS), "
        "as Nav2's does once its progress checker (10 s) and recoveries are spent: "
        "a person who never leaves the way does not hold a client forever",
        POSITIVE,
    )


class TaskKind(StrEnum):
    NAVIGATE_TO_POSE = "navigate_to_pose"
    NAVIGATE_THROUGH_POSES = "navigate_through_poses"
    FOLLOW_WAYPOINTS = "follow_waypoints"
    FOLLOW_PATH = "follow_path"


class Outcome(Enum):
    SUCCEEDED = "succeeded"
    ABORTED = "aborted"
    CANCELED = "canceled"


@dataclass(frozen=True)
class Progress:
    """What a feedback message says now."""

    pose: Pose2D | None
    elapsed_s: float
    distance_remaining_m: float
    eta_s: float  # 0 where bt_navigator would not estimate it
    recoveries: int
    index: int  # the pose being visited
    remaining_poses: int  # including the one being visited
    speed_mps: float


@dataclass
class NavTask:
    kind: TaskKind
    poses: list[Pose2D]  # the poses to visit (follow_path: the path's)
    started: float
    by: str = "nav2"  # who cancels (the server's name), in the planner's goal_cancelled event
    index: int = 0
    outcome: Outcome | None = None
    failure: PlanFailure | None = None
    reason: str = ""
    recoveries: int = 0
    stalled: bool = False  # failed to make progress (Nav2TaskParams.progress_timeout_s)
    missed: list[tuple[int, PlanFailure]] = field(default_factory=list)  # (follow_waypoints) pose index, why
    _planned: bool = False  # the planner has made the plan for the pose being visited
    _robot: RobotState | None = None
    _line: Polyline | None = None
    _anchor: tuple[Pose2D, float] | None = None  # where and when the robot last made progress

    def start(self, now: float) -> list[Message]:
        """What goes out first: the path for follow_path, else the first pose as a goal."""
        if self.kind is TaskKind.FOLLOW_PATH:
            self._line, self._planned = Polyline(self.poses), True
            return [Message(topics.PLAN, list(self.poses), now)]
        return self._send(now)

    def _send(self, now: float) -> list[Message]:
        self._planned, self._line = False, None
        return [Message(topics.GOAL, Goal(self.poses[self.index]), now)]

    @property
    def target(self) -> Pose2D:
        return self.poses[-1] if self.kind is TaskKind.FOLLOW_PATH else self.poses[self.index]

    def _is_ours(self, xy: Sequence[float] | None) -> bool:
        return xy is not None and math.hypot(xy[0] - self.target.x, xy[1] - self.target.y) <= GOAL_MATCH_M

    # -- inputs ----------------------------------------------------------------------------------
    def on_event(self, e: Event, now: float) -> list[Message]:
        if self.outcome is not None:
            return []
        kind, goal = e.kind, e.data.get("goal")
        if kind is EventKind.PLAN_MADE:
            if not self._planned and self._is_ours(goal):
                self._planned = True
            elif self._planned:  # a plan for somebody else's goal: ours is preempted, as in Nav2
                self._end(Outcome.ABORTED, "preempted by a plan for another goal")
            # (else a plan for an earlier goal, made before ours came: ours is still to come)
        elif (
            kind is EventKind.PLAN_REFUSED
            and self.kind is not TaskKind.FOLLOW_PATH
            and not self._planned
            and (goal is None or self._is_ours(goal))
        ):
            failure = PlanFailure(e.data.get("failure", PlanFailure.UNKNOWN))
            return self._failed(failure, str(e.data.get("reason", "")), now)
        elif kind is EventKind.GOAL_CANCELLED:
            self._end(Outcome.ABORTED, f"goal cancelled by {e.data.get('by', 'somebody')}")
        elif kind in RECOVERIES and self._planned:
            self.recoveries += 1
        elif kind is EventKind.GOAL_REACHED and self._planned and self._is_ours(goal):
            return self._reached(now)
        return []

    def on_plan(self, poses: Sequence[Pose2D]) -> None:
        """The /plan the robot follows now (for the distance left)."""
        if self._planned and poses:
            self._line = Polyline(list(poses))

    def on_odom(self, state: RobotState, now: float) -> list[Message]:
        """The robot's pose; navigate_through_poses goes on to the next pose once the robot has
        come within VIAPOINT_RADIUS_M of one on the way (Nav2 passes them, it does not stop)."""
        self._robot = state
        on_the_way = (
            self.kind is TaskKind.NAVIGATE_THROUGH_POSES
            and self.outcome is None
            and self._planned
            and self.index + 1 < len(self.poses)
        )
        if not on_the_way or math.hypot(state.pose.x - self.target.x, state.pose.y - self.target.y) > VIAPOINT_RADIUS_M:
            return []
        self.index += 1
        return self._send(now)

    def cancel(self, now: float) -> list[Message]:
        """The client's cancel: the goal dropped, the robot stopped."""
        self._end(Outcome.CANCELED, "canceled")
        return self._stop(now)

    def check_progress(self, now: float, timeout_s: float) -> list[Message]:
        """Fail a task whose robot has not moved PROGRESS_RADIUS_M in `timeout_s` (stopping it)."""
        here = self._robot.pose if self._robot is not None else None
        if self.outcome is not None or here is None:
            return []
        if (
            self._anchor is None
            or math.hypot(here.x - self._anchor[0].x, here.y - self._anchor[0].y) > PROGRESS_RADIUS_M
        ):
            self._anchor = (here, now)
        if now - self._anchor[1] < timeout_s:
            return []
        self.stalled = True
        self._end(Outcome.ABORTED, f"no progress: the robot moved less than {PROGRESS_RADIUS_M:g} m in {timeout_s:g} s")
        return self._stop(now)

    def _stop(self, now: float) -> list[Message]:
        if self.kind is TaskKind.FOLLOW_PATH:
            return [Message(topics.PLAN, [], now)]
        return [Message(topics.CANCEL_GOAL, self.by, now)]

    # -- outcomes --------------------------------------------------------------------------------
    def _reached(self, now: float) -> list[Message]:
        if self.kind is TaskKind.FOLLOW_PATH or self.index + 1 >= len(self.poses):
            self._end(Outcome.SUCCEEDED)
            return []
        self.index += 1
        return self._send(now)

    def fail(self, failure: PlanFailure, reason: str) -> None:
        """Failed before it started (a pose the planner cannot plan to, seen beforehand)."""
        self._failed(failure, reason, self.started)

    def _failed(self, failure: PlanFailure, reason: str, now: float) -> list[Message]:
        self.failure = failure
        if self.kind is TaskKind.FOLLOW_WAYPOINTS:
            self.missed.append((self.index, failure))  # (Nav2's waypoint follower stops at a failure by default)
        self._end(Outcome.ABORTED, reason or failure.value)
        return []

    def preempt(self, reason: str = "preempted by a new goal") -> None:
        self._end(Outcome.ABORTED, reason)

    def _end(self, outcome: Outcome, reason: str = "") -> None:
        if self.outcome is None:
            self.outcome, self.reason = outcome, reason

    # -- feedback --------------------------------------------------------------------------------
    def progress(self, now: float) -> Progress:
        robot = self._robot
        here = robot.pose if robot is not None else None
        speed = math.hypot(robot.twist.vx, robot.twist.vy) if robot is not None else 0.0
        left = self._distance_left(here)
        eta = left / speed if speed > ETA_MIN_SPEED_MPS and left > ETA_MIN_DISTANCE_M else 0.0
        remaining = 1 if self.kind is TaskKind.FOLLOW_PATH else len(self.poses) - self.index
        return Progress(here, now - self.started, left, eta, self.recoveries, self.index, remaining, speed)

    def _distance_left(self, here: Pose2D | None) -> float:
        if here is None:
            return 0.0
        target = self.target
        if self._line is not None and len(self._line) >= 2:
            left = self._line.length - self._line.project(here.x, here.y).s
        else:  # (no plan yet: as the crow flies)
            left = math.hypot(target.x - here.x, target.y - here.y)
        if self.kind is not TaskKind.FOLLOW_PATH:
            later = self.poses[self.index :]
            left += sum(math.hypot(b.x - a.x, b.y - a.y) for a, b in itertools.pairwise(later))
        return left
