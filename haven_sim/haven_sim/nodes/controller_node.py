"""Controller node: follows any nav_msgs/Path on /plan in HAVEN's motion style -> /cmd_vel_nav.

Holds still while /haven/wait (latched Bool) is true or the path is empty; reports arrival once as
a `goal_reached` event.
"""

from __future__ import annotations

import math
import sys

from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry, Path
from rclpy.node import Node
from std_msgs.msg import Bool, String

from haven_sim.nav.follower import ControllerParams, PathFollower, Status
from haven_sim.common.geometry import Pose2D
from haven_sim.nodes import conversions as conv
from haven_sim.nodes import qos
from haven_sim.nodes.runner import run_node


class ControllerNode(Node):
    def __init__(self) -> None:
        super().__init__("controller")
        d = self.declare_parameter
        params = ControllerParams(
            linear_speed_mps=d("linear_speed_mps", 0.4).value,
            rotate_speed_rps=math.radians(d("rotate_speed_deg_s", 50.0).value),
            facing_tolerance_rad=math.radians(d("facing_tolerance_deg", 5.0).value),
            arc_max_angle_rad=math.radians(d("arc_max_angle_deg", 60.0).value),
            goal_tolerance_m=d("goal_tolerance_m", 0.1).value,
            lookahead_m=d("lookahead_m", 0.35).value,
        )
        rate = d("rate_hz", 20.0).value
        if not rate > 0:
            raise ValueError(f"rate_hz must be positive, got {rate}")
        self.follower = PathFollower(params)
        self.robot: Pose2D | None = None
        self._last_status = self.follower.status
        self.pub = self.create_publisher(Twist, "cmd_vel_nav", qos.RELIABLE)
        self.events_pub = self.create_publisher(String, "haven/events", qos.EVENTS_PUB)
        self.create_subscription(Path, "plan", self._on_plan, qos.LATCHED)
        self.create_subscription(Odometry, "odom", self._on_odom, qos.LATEST)
        self.create_subscription(Bool, "haven/wait", self._on_wait, qos.LATCHED)
        self.create_timer(1.0 / rate, self._tick)

    def _on_plan(self, msg: Path) -> None:
        self.follower.set_path(conv.path_from_msg(msg))
        if not msg.poses:
            self.pub.publish(Twist())

    def _on_odom(self, msg: Odometry) -> None:
        self.robot = conv.pose_from_msg(msg.pose.pose)

    def _on_wait(self, msg: Bool) -> None:
        self.follower.waiting = bool(msg.data)

    def _tick(self) -> None:
        if self.robot is None:
            return
        before = self.follower.status
        cmd = self.follower.command(self.robot)
        status = self.follower.status
        if status in (Status.DRIVING, Status.ROTATING) or before in (Status.DRIVING, Status.ROTATING) or status is Status.WAITING:
            self.pub.publish(conv.twist_msg(cmd))
        if status is Status.ARRIVED and self._last_status is not Status.ARRIVED and self.follower.goal is not None:
            g = self.follower.goal
            now = round(self.get_clock().now().nanoseconds * 1e-9, 4)
            self.events_pub.publish(conv.event_msg({
                "stamp": now, "source": "controller", "type": "goal_reached",
                "goal": [round(g.x, 3), round(g.y, 3)], "pose": [round(v, 3) for v in self.robot],
            }))
        self._last_status = status


def main(args: list[str] | None = None) -> None:
    sys.exit(run_node(ControllerNode, args))


if __name__ == "__main__":
    main()
