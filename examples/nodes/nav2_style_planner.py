"""An example planner node, written as a Nav2 user would: it plans on each /goal_pose and publishes
/plan the way Nav2's planner_server does (nav_msgs/Path, reliable, volatile, depth 1), shaped like
NavFn's paths: poses every 5 cm, identity orientations, the goal's yaw on the last pose.

Its path (examples/nav2_style_path.py, no ROS there) is a turn of radius `turn_radius_m` from the
robot's heading until it faces the goal, then a straight line; this node only translates. HAVEN
reads the path from its geometry: cubes on the arc, spheres on the straight, a rotation to the goal
yaw at the end.

    haven sim --without planner &
    python examples/nodes/nav2_style_planner.py
    haven goto 2.2 4.2 2.6              # or RViz's "2D Goal Pose"
"""

from __future__ import annotations

import math
import pathlib
import sys

import rclpy
from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import Odometry, Path
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.qos import QoSProfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))  # examples/: the path, without ROS
from nav2_style_path import turn_then_straight


def yaw_of(q) -> float:
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


class Nav2StylePlanner(Node):
    def __init__(self) -> None:
        super().__init__("nav2_style_planner")
        self.radius = float(self.declare_parameter("turn_radius_m", 0.6).value)
        self.odom: Odometry | None = None
        self.pending: PoseStamped | None = None  # a goal that came before /odom or before anyone read /plan
        self.create_subscription(Odometry, "odom", lambda m: setattr(self, "odom", m), 10)
        self.create_subscription(PoseStamped, "goal_pose", self.on_goal, 10)
        self.plan = self.create_publisher(Path, "plan", QoSProfile(depth=1))  # planner_server's QoS
        self.current: Path | None = None
        self.readers = 0
        self.create_timer(0.5, self.retry)

    def retry(self) -> None:
        """A goal still waiting is planned; the current plan goes again to readers that matched
        since it went out (the topic is volatile: they would not get it otherwise)."""
        if self.pending is not None:
            goal, self.pending = self.pending, None
            self.on_goal(goal)
        readers = self.plan.get_subscription_count()
        if self.current is not None and readers > self.readers:
            self.plan.publish(self.current)
        self.readers = readers

    def on_goal(self, goal: PoseStamped) -> None:
        if self.odom is None or self.plan.get_subscription_count() == 0:
            self.pending = goal  # planned once the robot's pose is known and a controller listens
            return
        # (the suite's map -> odom is the identity; a real planner would look the pose up in TF)
        p = self.odom.pose.pose
        points = turn_then_straight(
            p.position.x, p.position.y, yaw_of(p.orientation), goal.pose.position.x, goal.pose.position.y, self.radius
        )
        path = Path()
        path.header.frame_id = "map"
        path.header.stamp = self.get_clock().now().to_msg()
        for px, py in points:
            pose = PoseStamped()
            pose.header = path.header
            pose.pose.position.x, pose.pose.position.y = px, py
            pose.pose.orientation.w = 1.0  # identity, as NavFn leaves them
            path.poses.append(pose)
        path.poses[-1].pose.orientation = goal.pose.orientation  # the goal yaw on the last pose
        self.plan.publish(path)
        self.current, self.readers = path, self.plan.get_subscription_count()
        self.get_logger().info(
            f"plan: {len(path.poses)} poses to ({goal.pose.position.x:.2f}, {goal.pose.position.y:.2f})"
        )


def main() -> None:
    rclpy.init(args=sys.argv)
    node = Nav2StylePlanner()
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):  # Ctrl-C, or a stop signal rclpy turned into a shutdown
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    main()
