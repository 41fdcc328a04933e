"""The controller: follows /plan in HAVEN's motion style and says when it has arrived.

`ControllerComponent` is the whole controller node without ROS (the node only wires it to topics):
it keeps the latest path, pose and wait flag, and at `rate_hz` commands the robot through the path
follower, reporting a `goal_reached` event once per path: when the follower has arrived, the
robot has come to rest (its final rotation braked to a stop) and the goal checker finds the pose
it rests at within the follower's xy and yaw tolerances. Resting outside them (it coasted past the
goal or turned too far), it drives back and turns again, as Nav2's controller server keeps going
until its goal checker agrees; a robot that cannot get there is left to the caller's progress
check or timeout. A "reached" is therefore a measured pose, whatever the machine's load.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from haven_sim.common import nodes, topics
from haven_sim.common.component import Handler, Message
from haven_sim.common.events import EventKind, Source, event
from haven_sim.common.geometry import ZERO_TWIST, Pose2D, Twist2D
from haven_sim.common.params import POSITIVE, config, group, param
from haven_sim.common.state import RobotState
from haven_sim.nav.follower import FollowerParams, PathFollower, Status
from haven_sim.nav.motion_style import MotionStyle
from haven_sim.robots.fields import RobotChoice

AT_REST_MPS, AT_REST_RPS = 0.01, 0.02  # the robot is at rest below these (odometry's speeds)
REST_WAIT_S = 3.0  # arrived but not at rest after this long (odometry gone quiet): checked all the same


@config
class ControllerConfig:
    robot: RobotChoice = group(RobotChoice)
    follower: FollowerParams = group(FollowerParams)
    style: MotionStyle = group(MotionStyle)
    rate_hz: float = param(20.0, "control rate (sim time)", POSITIVE)

    def __post_init__(self) -> None:
        if self.follower.yaw_goal_tolerance_rad < self.style.facing_tolerance_rad:
            raise ValueError(
                f"follower.yaw_goal_tolerance_rad ({self.follower.yaw_goal_tolerance_rad:g}) must be at least the "
                f"motion style's facing tolerance ({self.style.facing_tolerance_deg:g} deg), where a rotation ends"
            )


class ControllerComponent:
    name = nodes.CONTROLLER.name
    unread: frozenset[str] = frozenset()
    paces_clock = True  # on the free-running clock, sim time waits for this loop (topics.PACE) while `pacing`

    def __init__(self, config: ControllerConfig | None = None) -> None:
        self.config = config or ControllerConfig()
        self.follower = PathFollower(self.config.follower, self.config.style)
        self.robot: Pose2D | None = None
        self.twist = ZERO_TWIST
        self._arrived_at: float | None = None  # the follower arrived; goal_reached waits for rest
        self._active = False  # the last tick drove or rotated the robot
        self._plan: list[Pose2D] = []
        self.corrections = 0  # times the robot came to rest off its goal and went back to it
        self.pacing = False  # the last tick drove the robot, or stopped it: the clock waits for its command
        self.notes: list[str] = []  # logged by the node

    @property
    def period_s(self) -> float:
        return 1.0 / self.config.rate_hz

    def handlers(self) -> Mapping[str, Handler]:
        return {topics.PLAN: self.on_plan, topics.ODOM: self.on_odom, topics.WAIT: self.on_wait}

    def outputs(self) -> Sequence[str]:
        return (topics.CMD_VEL_NAV, topics.EVENTS)

    def on_plan(self, poses: Sequence[Pose2D], now: float) -> list[Message]:
        if poses and list(poses) == self._plan and self.follower.active:
            return []  # the plan being followed, sent again (a planner re-sending it): nothing changes
        self._plan = list(poses)
        self.follower.set_path(poses)
        self._arrived_at = None
        if not poses:  # a cleared plan stops the robot at once
            self._active = False
            return [Message(topics.CMD_VEL_NAV, Twist2D(), now)]
        return []

    def on_odom(self, state: RobotState, now: float) -> list[Message]:
        self.robot, self.twist = state.pose, state.twist
        return []

    def on_wait(self, waiting: bool, now: float) -> list[Message]:
        self.follower.waiting = waiting
        return []

    def tick(self, now: float) -> list[Message]:
        if self.robot is None:
            return []
        before = self.follower.status
        cmd = self.follower.command(self.robot)
        status = self.follower.status
        out: list[Message] = []
        moving = status in (Status.DRIVING, Status.ROTATING)
        # Publish while moving, once more when it stops (a zero), and while told to wait.
        if moving or self._active or status is Status.WAITING:
            out.append(Message(topics.CMD_VEL_NAV, cmd, now))
        self.pacing = moving or self._active
        self._active = moving
        goal = self.follower.goal
        if status is Status.ARRIVED and before is not Status.ARRIVED and goal is not None:
            self._arrived_at = now
        if (
            self._arrived_at is not None
            and goal is not None
            and (self._at_rest() or now - self._arrived_at >= REST_WAIT_S)
        ):
            self._arrived_at = None
            if not self.follower.at_goal(self.robot):
                xy, yaw = self.follower.off_goal(self.robot)
                self.corrections += 1
                self.notes.append(f"at rest {xy:.3f} m and {yaw:.3f} rad off the goal: going back to it")
                self.follower.correct(self.robot)
                return out
            pose = [round(v, 3) for v in self.robot]
            reached = event(
                EventKind.GOAL_REACHED, now, Source.CONTROLLER, goal=[round(goal.x, 3), round(goal.y, 3)], pose=pose
            )
            out.append(Message(topics.EVENTS, reached, now))
        return out

    def _at_rest(self) -> bool:
        t = self.twist
        return abs(t.vx) < AT_REST_MPS and abs(t.vy) < AT_REST_MPS and abs(t.wz) < AT_REST_RPS
