"""Nav2's servers over HAVEN's planner and controller, so Nav2 clients drive the simulated robot.

One process, the lifecycle nodes Nav2 users call by name, each configured and activated at start
as Nav2's lifecycle_manager does with autostart (so nav2_simple_commander's waitUntilNav2Active()
returns), each serving its actions while active:
- bt_navigator: navigate_to_pose, navigate_through_poses (the poses in turn, passed on the way);
- waypoint_follower: follow_waypoints (stopping at the first that fails, as Nav2's default);
- planner_server: compute_path_to_pose, from HAVEN's planner (arcs, straights and rotations);
- controller_server: follow_path, handed to HAVEN's controller on /plan;
- amcl: no localisation to do (the simulator's pose is exact, map -> odom the identity), it
  publishes /amcl_pose from /odom as AMCL does after an update; /initialpose is ignored, with a line.

The tasks are `haven_sim.nav.nav2_tasks.NavTask`: poses go out on /goal_pose, a cancel on
/haven/cancel_goal, and the suite's events say how it goes. One robot, one task: a new goal on
any of the servers preempts the one running (aborted, as in Nav2). The AR cues are unchanged:
they show the /plan the controller follows, whoever asked for it.
"""

from __future__ import annotations

import math
import sys
from collections.abc import Sequence
from typing import Any

from geometry_msgs.msg import PoseStamped, PoseWithCovarianceStamped
from lifecycle_msgs.msg import State
from nav2_msgs.action import FollowPath, FollowWaypoints, NavigateThroughPoses, NavigateToPose
from rclpy.action import ActionServer, CancelResponse, GoalResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.clock import Clock, ClockType
from rclpy.lifecycle import LifecycleNode, TransitionCallbackReturn

from haven_sim.common import topics
from haven_sim.common.geometry import Pose2D
from haven_sim.nav.nav2_tasks import NavTask, TaskKind
from haven_sim.nav.planner import PlanFailure
from haven_sim.nav.planning import PlannerConfig
from haven_sim.nodes import conversions as conv, wire
from haven_sim.nodes.component_node import declare_config
from haven_sim.nodes.nav2_planner import PathPlanner
from haven_sim.nodes.runner import run_node
from haven_sim.nodes.task_runner import TaskRunner, finish, goal_error, unusable

THREADS = 6  # for the servers' execute callbacks, which wait (one task runs at a time), and the inputs
AMCL_PERIOD_S = 0.5  # sim time between /amcl_pose messages


class Nav2Lifecycle(LifecycleNode):
    """A Nav2 server's lifecycle: configured and activated at start; goals only while active."""

    def __init__(self, name: str) -> None:
        super().__init__(name)
        self.active = False
        self.group = ReentrantCallbackGroup()

    def on_activate(self, state: State) -> TransitionCallbackReturn:
        self.active = True
        return super().on_activate(state)

    def on_deactivate(self, state: State) -> TransitionCallbackReturn:
        self.active = False
        return super().on_deactivate(state)

    def serve(self, action: Any, name: str, execute: Any, check: Any = None) -> ActionServer:
        def goal(request: Any) -> GoalResponse:
            why = "inactive" if not self.active else (check(request) if check is not None else None)
            if why:
                self.get_logger().warning(f"{name}: goal rejected: {why}")
                return GoalResponse.REJECT
            return GoalResponse.ACCEPT

        return ActionServer(
            self,
            action,
            name,
            execute,
            goal_callback=goal,
            cancel_callback=lambda _: CancelResponse.ACCEPT,
            callback_group=self.group,
        )


def _poses(msgs: Sequence[PoseStamped], map_frame: str) -> list[Pose2D] | str:
    """The poses of a goal, or why they cannot be driven to."""
    if not msgs:
        return "no poses"
    why = next((w for m in msgs if (w := unusable("pose", m, map_frame))), None)
    return why if why is not None else [conv.pose_from_stamped(m) for m in msgs]


class BtNavigator(Nav2Lifecycle):
    def __init__(self, map_frame: str) -> None:
        super().__init__("bt_navigator")
        self.map_frame = map_frame
        self.runner = TaskRunner(self, map_frame)
        self.paths: PathPlanner | None = None  # the planner server's, for what can be seen before driving
        self.serve(NavigateToPose, "navigate_to_pose", self.to_pose, lambda r: self._why([r.pose]))
        self.serve(NavigateThroughPoses, "navigate_through_poses", self.through_poses, lambda r: self._why(r.poses))

    def _why(self, msgs: Sequence[PoseStamped]) -> str | None:
        got = _poses(msgs, self.map_frame)
        return got if isinstance(got, str) else None

    def _navigate(self, handle: Any, kind: TaskKind, action: Any, msgs: Sequence[PoseStamped]) -> Any:
        poses = _poses(msgs, self.map_frame)
        assert not isinstance(poses, str)  # (checked when the goal came)
        task = NavTask(kind, poses, self.runner.now(), by=self.get_name())
        outside = (
            self.paths.first_outside(poses)
            if self.paths is not None and kind is TaskKind.NAVIGATE_THROUGH_POSES
            else None
        )
        if outside is not None:  # (Nav2 plans through every pose first: fails before the robot moves)
            task.fail(
                PlanFailure.GOAL_OUTSIDE_MAP,
                f"pose {outside} ({poses[outside].x:.2f}, {poses[outside].y:.2f}) is outside the map",
            )
        else:
            self.runner.run(handle, task, lambda p: self.runner.nav_feedback(action, p))
        result = action.Result()
        result.error_code, result.error_msg = goal_error(task)
        return finish(handle, task, result)

    def to_pose(self, handle: Any) -> Any:
        return self._navigate(handle, TaskKind.NAVIGATE_TO_POSE, NavigateToPose, [handle.request.pose])

    def through_poses(self, handle: Any) -> Any:
        return self._navigate(handle, TaskKind.NAVIGATE_THROUGH_POSES, NavigateThroughPoses, handle.request.poses)


class WaypointFollower(Nav2Lifecycle):
    def __init__(self, runner: TaskRunner, map_frame: str) -> None:
        super().__init__("waypoint_follower")
        self.runner, self.map_frame = runner, map_frame
        self.serve(FollowWaypoints, "follow_waypoints", self.follow, lambda r: self._why(r))

    def _why(self, request: Any) -> str | None:
        got = _poses(request.poses, self.map_frame)
        if isinstance(got, str):
            return got
        return None if request.goal_index < len(got) else f"goal_index {request.goal_index} is past the last pose"

    def follow(self, handle: Any) -> Any:
        request = handle.request
        poses = _poses(request.poses, self.map_frame)
        assert not isinstance(poses, str)
        task = NavTask(
            TaskKind.FOLLOW_WAYPOINTS, poses, self.runner.now(), by=self.get_name(), index=request.goal_index
        )

        def feedback(progress: Any) -> Any:
            return FollowWaypoints.Feedback(current_waypoint=progress.index)

        self.runner.run(handle, task, feedback)
        result = FollowWaypoints.Result()
        result.error_code, result.error_msg = goal_error(task)
        result.error_code = 0  # (as Nav2's waypoint follower: why a waypoint failed is in missed_waypoints)
        result.missed_waypoints = self.runner.missed(task, request.poses)
        return finish(handle, task, result)


class ControllerServer(Nav2Lifecycle):
    def __init__(self, runner: TaskRunner, map_frame: str) -> None:
        super().__init__("controller_server")
        self.runner, self.map_frame = runner, map_frame
        self.serve(FollowPath, "follow_path", self.follow, lambda r: self._why(r.path))

    def _why(self, path: Any) -> str | None:
        # (an empty path: INVALID_PATH, as Nav2's)
        return unusable("path", path, self.map_frame) if path.poses else None

    def follow(self, handle: Any) -> Any:
        poses = conv.path_from_msg(handle.request.path)
        result = FollowPath.Result()
        if not poses:
            result.error_code, result.error_msg = FollowPath.Result.INVALID_PATH, "the path is empty"
            handle.abort()
            return result
        task = NavTask(TaskKind.FOLLOW_PATH, poses, self.runner.now(), by=self.get_name())

        def feedback(progress: Any) -> Any:
            return FollowPath.Feedback(
                distance_to_goal=float(progress.distance_remaining_m), speed=float(progress.speed_mps)
            )

        self.runner.run(handle, task, feedback)
        result.error_code, result.error_msg = goal_error(task, FollowPath.Result.UNKNOWN)
        return finish(handle, task, result)


class PlannerServer(Nav2Lifecycle):
    """Declares the planner's parameters (PlannerConfig): its map frame is every server's."""

    def __init__(self) -> None:
        super().__init__("planner_server")
        self.config = declare_config(self, PlannerConfig)

    def start_planning(self, runner: TaskRunner) -> PathPlanner:
        return PathPlanner(self, runner, self.config)


class Amcl(Nav2Lifecycle):
    """/amcl_pose from /odom (latched, as AMCL publishes it), for clients that wait for a pose."""

    def __init__(self, map_frame: str) -> None:
        super().__init__("amcl")
        self.map_frame, self.last = map_frame, -math.inf
        specs = wire.specs()
        latched = specs[topics.MAP].pub_qos  # reliable, transient local, depth 1 (AMCL's amcl_pose QoS)
        self.pub = self.create_publisher(PoseWithCovarianceStamped, "amcl_pose", latched)
        self.create_subscription(specs[topics.ODOM].msg_type, topics.ODOM, self.on_odom, specs[topics.ODOM].sub_qos)
        self.create_subscription(PoseWithCovarianceStamped, "initialpose", self.on_initial, 10)

    def on_odom(self, msg: Any) -> None:
        t = conv.time_from_msg(msg.header.stamp)
        if not self.active or t - self.last < AMCL_PERIOD_S:
            return
        self.last = t
        out = PoseWithCovarianceStamped()
        out.header.stamp, out.header.frame_id = msg.header.stamp, self.map_frame
        out.pose.pose = msg.pose.pose  # (map -> odom is the identity: the simulator's pose is exact)
        self.pub.publish(out)

    def on_initial(self, msg: Any) -> None:
        self.get_logger().info(
            "initialpose ignored: the simulator knows where the robot is", throttle_duration_sec=10.0
        )


def make_nodes() -> list[Nav2Lifecycle]:
    """The servers, configured now and activated once the suite is there to carry their goals
    out (a reader on /goal_pose, a controller publishing /cmd_vel_nav), as lifecycle_manager
    brings Nav2 up in order: a client's first goal is then never lost."""
    planner = PlannerServer()
    frame = planner.config.map_frame
    bt = BtNavigator(frame)
    bt.paths = planner.start_planning(bt.runner)
    made = [bt, WaypointFollower(bt.runner, frame), ControllerServer(bt.runner, frame), planner, Amcl(frame)]
    for node in made:
        node.trigger_configure()

    def ready() -> None:
        if bt.count_subscribers(topics.GOAL) and bt.count_publishers(topics.CMD_VEL_NAV):
            timer.cancel()
            for node in made:
                node.trigger_activate()
            bt.get_logger().info(
                "Nav2 servers active: navigate_to_pose, navigate_through_poses, "
                "follow_waypoints, compute_path_to_pose, follow_path"
            )

    timer = bt.create_timer(0.2, ready, clock=Clock(clock_type=ClockType.STEADY_TIME))
    return made


def main(args: list[str] | None = None) -> None:
    sys.exit(run_node(make_nodes, args, threads=THREADS))


if __name__ == "__main__":
    main()
