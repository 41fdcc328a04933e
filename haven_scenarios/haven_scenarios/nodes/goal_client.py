"""Sends one goal on /goal_pose (as RViz's "2D Goal Pose" does) and reports what became of it.

Exits 0 when the controller reports `goal_reached`, 1 when the planner refuses the goal, the
timeout (sim seconds) passes, or (wall seconds) nobody reads goals or sim time stops; prints the planner's and
controller's events as they come.
"""

from __future__ import annotations

import sys
import time

from geometry_msgs.msg import PoseStamped
from rclpy.clock import Clock, ClockType
from rclpy.node import Node
from std_msgs.msg import String

from haven_sim.common.events import EventKind
from haven_sim.common.geometry import Pose2D
from haven_sim.nodes import conversions as conv, qos
from haven_sim.nodes.runner import run_node

SHOWN = {
    EventKind.PLAN_MADE,
    EventKind.PLAN_REFUSED,
    EventKind.WAITING,
    EventKind.RESUMED,
    EventKind.REPLANNED,
    EventKind.REVERTED,
    EventKind.GOAL_REACHED,
}


RESEND_S = 2.0  # wall seconds without an answer from the planner before the goal is sent again
STALL_S = 15.0  # wall seconds without a planner, or without sim time moving, before giving up


class GoalClient(Node):
    def __init__(self) -> None:
        super().__init__("goal_client")
        d = self.declare_parameter
        self.goal = Pose2D(d("x", 0.0).value, d("y", 0.0).value, d("yaw", 0.0).value)
        self.timeout_s = d("timeout_s", 120.0).value
        self.pub = self.create_publisher(PoseStamped, "goal_pose", qos.RELIABLE)
        self.create_subscription(String, "haven/events", self._on_event, qos.EVENTS)
        self.sent_at: float | None = None
        self.sent_wall, self.answered = 0.0, False
        # Wall-clock timer and watchdog: with sim time, a simulator that stopped would stop a
        # sim-time timer too, and the client would wait for ever.
        self.started = time.monotonic()
        self.last_time, self.last_change = self._now(), time.monotonic()
        self.create_timer(0.1, self._tick, clock=Clock(clock_type=ClockType.STEADY_TIME))

    def _now(self) -> float:
        return self.get_clock().now().nanoseconds * 1e-9

    def _stalled(self) -> str | None:
        """Why the client cannot go on (nobody reads goals; sim time stands still), if so."""
        now, wall = self._now(), time.monotonic()
        if now != self.last_time:
            self.last_time, self.last_change = now, wall
        if self.sent_at is None and wall - self.started > STALL_S:
            return f"nobody reads /goal_pose after {STALL_S:g} s (is a suite running on this ROS_DOMAIN_ID?)"
        if self.sent_at is not None and wall - self.last_change > STALL_S:
            return f"the clock stood still for {STALL_S:g} s at t={now:.2f} (did the simulator stop?)"
        return None

    def _tick(self) -> None:
        stalled = self._stalled()
        if stalled:
            print(f"goto: {stalled}", flush=True)
            raise SystemExit(1)
        if self.sent_at is None or (not self.answered and time.monotonic() - self.sent_wall > RESEND_S):
            # (re-sent until the planner answers: a reader that matched after the send, while
            # another one, a recorder or a bridge, was already there, never saw it)
            if self.pub.get_subscription_count() == 0:
                return  # wait for a reader
            msg = PoseStamped()
            msg.header.frame_id = "map"
            msg.header.stamp = conv.time_msg(self._now())
            msg.pose = conv.pose_msg(self.goal)
            self.pub.publish(msg)
            if self.sent_at is None:
                print(f"goto: sent goal ({self.goal.x:.2f}, {self.goal.y:.2f}, yaw {self.goal.yaw:.2f})", flush=True)
            self.sent_at, self.sent_wall = self._now(), time.monotonic()
        elif self._now() - self.sent_at > self.timeout_s:
            print(f"goto: no arrival within {self.timeout_s:g} s", flush=True)
            raise SystemExit(1)

    def _on_event(self, msg: String) -> None:
        try:
            event = conv.event_from_msg(msg)
        except ValueError:
            return
        if self.sent_at is None or event.kind not in SHOWN or event.stamp < self.sent_at - 1e-6:
            return  # (the events publisher keeps its last ones for late joiners: older ones are not ours)
        self.answered = True
        detail = ", ".join(f"{k}={v}" for k, v in event.data.items())
        print(f"goto: {event.kind} at t={round(event.stamp, 4)} {detail}", flush=True)
        if event.kind is EventKind.GOAL_REACHED:
            raise SystemExit(0)
        if event.kind is EventKind.PLAN_REFUSED:
            raise SystemExit(1)


def main(args: list[str] | None = None) -> None:
    sys.exit(run_node(GoalClient, args))


if __name__ == "__main__":
    main()
