"""A stand-in for nav2_simple_commander's BasicNavigator where Nav2 is not installed (it has no
wheel): the same calls, written here against the nav2_msgs interfaces, doing on the wire what
BasicNavigator does (Nav2 1.3, robot_navigator.py): `<node>/get_state` until "active", an
/initialpose published until /amcl_pose (transient local) comes, each task as an action goal
with its feedback kept, a cancel on the goal handle. Where nav2_simple_commander is installed,
drive.py uses the real one instead."""

from __future__ import annotations

import time
from enum import Enum
from typing import Any

import rclpy
from action_msgs.msg import GoalStatus
from geometry_msgs.msg import PoseStamped, PoseWithCovarianceStamped
from lifecycle_msgs.srv import GetState
from nav2_msgs.action import ComputePathToPose, FollowPath, FollowWaypoints, NavigateThroughPoses, NavigateToPose
from rclpy.action import ActionClient
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy


class TaskResult(Enum):
    UNKNOWN = 0
    SUCCEEDED = 1
    CANCELED = 2
    FAILED = 3


class Commander(Node):
    def __init__(self) -> None:
        super().__init__("test_commander")
        self.goal_handle: Any = None
        self.result_future: Any = None
        self.feedback: Any = None
        self.status: int | None = None
        self.initial_pose_received = False
        self.actions = {
            "navigate_to_pose": ActionClient(self, NavigateToPose, "navigate_to_pose"),
            "navigate_through_poses": ActionClient(self, NavigateThroughPoses, "navigate_through_poses"),
            "follow_waypoints": ActionClient(self, FollowWaypoints, "follow_waypoints"),
            "follow_path": ActionClient(self, FollowPath, "follow_path"),
            "compute_path_to_pose": ActionClient(self, ComputePathToPose, "compute_path_to_pose"),
        }
        latched = QoSProfile(
            depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL, reliability=ReliabilityPolicy.RELIABLE
        )
        self.create_subscription(PoseWithCovarianceStamped, "amcl_pose", self._on_amcl_pose, latched)
        self.initial_pose_pub = self.create_publisher(PoseWithCovarianceStamped, "initialpose", 10)

    def _on_amcl_pose(self, msg: Any) -> None:
        self.initial_pose_received = True

    def _on_feedback(self, msg: Any) -> None:
        self.feedback = msg.feedback

    def waitUntilNav2Active(self, navigator: str = "bt_navigator", localizer: str = "amcl") -> None:
        self._wait_active(localizer)
        while not self.initial_pose_received:
            self.initial_pose_pub.publish(PoseWithCovarianceStamped())
            rclpy.spin_once(self, timeout_sec=1.0)
        self._wait_active(navigator)

    def _wait_active(self, node_name: str) -> None:
        client = self.create_client(GetState, f"{node_name}/get_state")
        while not client.wait_for_service(timeout_sec=1.0):
            pass
        state = "unknown"
        while state != "active":
            # (asked again when no answer comes: a server that has not yet matched this client's
            # response reader drops the answer, "failed to send response", on a busy machine)
            future = client.call_async(GetState.Request())
            rclpy.spin_until_future_complete(self, future, timeout_sec=2.0)
            state = future.result().current_state.label if future.done() and future.result() is not None else "unknown"
            if state != "active":
                time.sleep(0.5)

    def _send(self, name: str, goal: Any) -> bool:
        client = self.actions[name]
        while not client.wait_for_server(timeout_sec=1.0):
            pass
        future = client.send_goal_async(goal, self._on_feedback)
        rclpy.spin_until_future_complete(self, future)
        self.goal_handle = future.result()
        if not self.goal_handle.accepted:
            return False
        self.result_future = self.goal_handle.get_result_async()
        return True

    def goToPose(self, pose: PoseStamped, behavior_tree: str = "") -> bool:
        return self._send("navigate_to_pose", NavigateToPose.Goal(pose=pose, behavior_tree=behavior_tree))

    def goThroughPoses(self, poses: list[PoseStamped], behavior_tree: str = "") -> bool:
        return self._send("navigate_through_poses", NavigateThroughPoses.Goal(poses=poses, behavior_tree=behavior_tree))

    def followWaypoints(self, poses: list[PoseStamped]) -> bool:
        return self._send("follow_waypoints", FollowWaypoints.Goal(poses=poses))

    def followPath(self, path: Any, controller_id: str = "", goal_checker_id: str = "") -> bool:
        return self._send(
            "follow_path", FollowPath.Goal(path=path, controller_id=controller_id, goal_checker_id=goal_checker_id)
        )

    def getPath(self, start: PoseStamped, goal: PoseStamped, planner_id: str = "", use_start: bool = False) -> Any:
        if not self._send(
            "compute_path_to_pose",
            ComputePathToPose.Goal(start=start, goal=goal, planner_id=planner_id, use_start=use_start),
        ):
            return None
        rclpy.spin_until_future_complete(self, self.result_future)
        self.status = self.result_future.result().status
        return self.result_future.result().result.path if self.status == GoalStatus.STATUS_SUCCEEDED else None

    def cancelTask(self) -> None:
        if self.result_future:
            rclpy.spin_until_future_complete(self, self.goal_handle.cancel_goal_async())

    def isTaskComplete(self) -> bool:
        if not self.result_future:
            return True
        rclpy.spin_until_future_complete(self, self.result_future, timeout_sec=0.1)
        if self.result_future.result():
            self.status = self.result_future.result().status
            return True
        return False

    def getFeedback(self) -> Any:
        return self.feedback

    def getResult(self) -> TaskResult:
        return {
            GoalStatus.STATUS_SUCCEEDED: TaskResult.SUCCEEDED,
            GoalStatus.STATUS_ABORTED: TaskResult.FAILED,
            GoalStatus.STATUS_CANCELED: TaskResult.CANCELED,
        }.get(self.status, TaskResult.UNKNOWN)
