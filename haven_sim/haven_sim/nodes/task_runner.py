"""Runs one Nav2 action goal as a `NavTask` and says how it ended, for the servers in nav2_node.

The runner owns what every task reads (/haven/events, /odom, /plan) and writes (/goal_pose,
/haven/cancel_goal, /plan), with the topic table's QoS. One robot, one task: a new goal on any
server preempts the running one. An action's execute callback waits in `run` (on its own
executor thread), sending feedback, until the task has an outcome or the client cancels.
"""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Callable, Sequence
from typing import Any

from geometry_msgs.msg import PoseStamped
from nav2_msgs.action import ComputePathThroughPoses, ComputePathToPose, FollowPath
from nav2_msgs.msg import MissedWaypoint
from rclpy.node import Node

from haven_sim.common import topics
from haven_sim.common.component import Message
from haven_sim.common.state import RobotState
from haven_sim.nav.nav2_tasks import Nav2TaskParams, NavTask, Outcome, Progress, TaskKind
from haven_sim.nav.planner import PlanFailure
from haven_sim.nodes import conversions as conv, wire
from haven_sim.nodes.component_node import declare_config
from haven_sim.nodes.runner import refused, stop_requested

FEEDBACK_PERIOD_S = 0.1  # wall time between feedback messages (bt_navigator sends one each tree tick)
_P = ComputePathToPose.Result


def failure_code(failure: PlanFailure, result: Any = _P) -> int:
    """The planner's failure as Nav2's planner server reports it: the constant of that name in
    ComputePathToPose's result (or ComputePathThroughPoses', whose codes are its own)."""
    return int(getattr(result, failure.name))


def unusable(what: str, msg: Any, map_frame: str) -> str | None:
    """Why a stamped pose or path cannot be driven to or planned for, or None: a frame other than
    the map's (or odom, which coincides with it; '' counts as the map), a position not finite."""
    if msg.header.frame_id not in ("", map_frame, "odom"):
        return f"{what} frame '{msg.header.frame_id}' is not '{map_frame}'"
    poses = [p.pose for p in msg.poses] if hasattr(msg, "poses") else [msg.pose]
    if not all(math.isfinite(p.position.x) and math.isfinite(p.position.y) for p in poses):
        return f"{what} position is not finite"
    return None


def goal_error(task: NavTask, otherwise: int = _P.UNKNOWN) -> tuple[int, str]:
    """(error_code, error_msg) of a task's result: 0 unless aborted; the planner's failure as the
    planner server's code (bt_navigator passes its tree's failing node's code on; through poses,
    ComputePathThroughPoses'), else `otherwise`."""
    if task.outcome is not Outcome.ABORTED:
        return 0, ""
    if task.stalled:  # (the controller server's code, which bt_navigator passes on)
        return FollowPath.Result.FAILED_TO_MAKE_PROGRESS, task.reason
    if task.failure is not None:
        through = task.kind is TaskKind.NAVIGATE_THROUGH_POSES
        return failure_code(task.failure, ComputePathThroughPoses.Result if through else _P), task.reason
    return otherwise, task.reason


def finish(handle: Any, task: NavTask, result: Any) -> Any:
    """End the goal as the task ended and return its result."""
    if task.outcome is Outcome.SUCCEEDED:
        handle.succeed()
    elif task.outcome is Outcome.CANCELED:
        handle.canceled()
    else:
        handle.abort()
    return result


class TaskRunner:
    def __init__(self, node: Node, map_frame: str) -> None:
        self.node, self.frame = node, map_frame
        self.params = declare_config(node, Nav2TaskParams)
        self.lock = threading.Lock()
        self.task: NavTask | None = None
        self.robot: RobotState | None = None
        table = wire.specs(wire.Frames(map=map_frame))
        self.specs = {t: table[t] for t in (topics.GOAL, topics.CANCEL_GOAL, topics.PLAN, topics.EVENTS, topics.ODOM)}
        self.pubs = {
            t: node.create_publisher(table[t].msg_type, t, table[t].pub_qos)
            for t in (topics.GOAL, topics.CANCEL_GOAL, topics.PLAN)
        }
        handlers: dict[str, Callable[[Any], None]] = {
            topics.EVENTS: self._on_event,
            topics.ODOM: self._on_odom,
            topics.PLAN: self._on_plan,
        }
        for topic, handler in handlers.items():
            spec = table[topic]

            def take(msg: Any, topic: str = topic, handler: Callable[[Any], None] = handler) -> None:
                self._take(topic, handler, msg)

            node.create_subscription(spec.msg_type, topic, take, spec.sub_qos)

    def now(self) -> float:
        return self.node.get_clock().now().nanoseconds * 1e-9

    def _take(self, topic: str, handler: Callable[[Any], None], msg: Any) -> None:
        try:
            data = self.specs[topic].decode(msg)
        except ValueError as e:
            refused(self.node, topic, e)
            return
        with self.lock:
            handler(data)

    def _on_event(self, e: Any) -> None:
        if self.task is not None:
            self._publish(self.task.on_event(e, self.now()))

    def _on_odom(self, state: RobotState) -> None:
        self.robot = state
        if self.task is not None:
            self._publish(self.task.on_odom(state, self.now()))

    def _on_plan(self, poses: Sequence[Any]) -> None:
        if self.task is not None:
            self.task.on_plan(poses)

    def _publish(self, messages: Sequence[Message]) -> None:
        for m in messages:
            self.pubs[m.topic].publish(self.specs[m.topic].encode(m.data, m.stamp))

    def run(self, handle: Any, task: NavTask, feedback: Callable[[Progress], Any]) -> NavTask:
        """Carry the task out (preempting the one running), sending feedback until it ends."""
        with self.lock:
            if self.task is not None:
                self.task.preempt()
            self.task = task
            if self.robot is not None:
                task.on_odom(self.robot, self.now())  # (nothing to pass yet: no plan made)
            self._publish(task.start(self.now()))
        while True:
            with self.lock:
                if task.outcome is None and handle.is_cancel_requested:
                    self._publish(task.cancel(self.now()))
                elif task.outcome is None and stop_requested():
                    task.preempt("the Nav2 servers are shutting down")
                else:
                    self._publish(task.check_progress(self.now(), self.params.progress_timeout_s))
                if task.outcome is not None:
                    return task
                message = feedback(task.progress(self.now()))
            handle.publish_feedback(message)
            time.sleep(FEEDBACK_PERIOD_S)

    def nav_feedback(self, action: Any, p: Progress) -> Any:
        """navigate_to_pose's (and navigate_through_poses') feedback."""
        fb = action.Feedback()
        if p.pose is not None:
            fb.current_pose = conv.pose_stamped_msg(self.now(), p.pose, self.frame)
        fb.navigation_time, fb.estimated_time_remaining = conv.duration_msg(p.elapsed_s), conv.duration_msg(p.eta_s)
        fb.number_of_recoveries, fb.distance_remaining = min(p.recoveries, 32767), float(p.distance_remaining_m)
        if hasattr(fb, "number_of_poses_remaining"):
            fb.number_of_poses_remaining = p.remaining_poses
        return fb

    @staticmethod
    def missed(task: NavTask, poses: Sequence[PoseStamped]) -> list[MissedWaypoint]:
        """follow_waypoints' missed waypoints, each with the planner server's code for why."""
        return [MissedWaypoint(index=i, goal=poses[i], error_code=failure_code(f)) for i, f in task.missed]
