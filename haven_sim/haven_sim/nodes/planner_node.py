"""Planner node: /goal_pose in, /plan out (HAVEN's rotate / arc / straight path), human-aware.

Plans on whatever /map holds (ours or any nav_msgs/OccupancyGrid), from the robot's /odom pose.
Watches /humans at `check_rate_hz`: a human on the upcoming path makes the robot wait (latched
/haven/wait = true, the controller holds still) or re-plans a detour; every decision is an event.
"""

from __future__ import annotations

import math
import sys

from geometry_msgs.msg import PoseArray, PoseStamped
from nav_msgs.msg import OccupancyGrid, Odometry, Path
from rclpy.node import Node
from std_msgs.msg import Bool, String

from haven_sim.common.geometry import Pose2D
from haven_sim.nav.navigator import Navigator, NavigatorParams, NavOutput
from haven_sim.nodes import conversions as conv
from haven_sim.nodes import qos
from haven_sim.nodes.runner import run_node
from haven_sim.nav.path_style import StyleParams
from haven_sim.nav.planner import PlannerParams


class PlannerNode(Node):
    def __init__(self) -> None:
        super().__init__("planner")
        d = self.declare_parameter
        self.planner_params = PlannerParams(
            robot_radius_m=d("robot_radius_m", 0.177).value,
            safety_margin_m=d("safety_margin_m", 0.05).value,
            snap_radius_m=d("snap_radius_m", 0.3).value,
        )
        self.style = StyleParams(
            arc_max_angle_rad=math.radians(d("arc_max_angle_deg", 60.0).value),
            too_close_distance_m=d("too_close_distance_m", 0.5).value,
            marker_spacing_m=d("marker_spacing_m", 0.4).value,
            rotate_step_rad=math.radians(d("rotate_step_deg", 15.0).value),
            max_arc_radius_m=d("max_arc_radius_m", 1.0).value,
        )
        self.style.validate()
        self.nav_params = NavigatorParams(
            wait_distance_m=d("wait_distance_m", 2.0).value,
            human_radius_m=d("human_radius_m", 0.25).value,
            path_clearance_m=d("path_clearance_m", 0.1).value,
            goal_tolerance_m=d("goal_tolerance_m", 0.1).value,
            use_goal_yaw=d("use_goal_yaw", True).value,
        )
        self.map_frame = d("map_frame", "map").value
        rate = d("check_rate_hz", 5.0).value
        if not rate > 0:
            raise ValueError(f"check_rate_hz must be positive, got {rate}")
        self.nav: Navigator | None = None
        self.robot: Pose2D | None = None
        self.humans: list[tuple[float, float]] = []
        self.pending: Pose2D | None = None
        self.plan_pub = self.create_publisher(Path, "plan", qos.LATCHED)
        self.wait_pub = self.create_publisher(Bool, "haven/wait", qos.LATCHED)
        self.events_pub = self.create_publisher(String, "haven/events", qos.EVENTS_PUB)
        self.create_subscription(OccupancyGrid, "map", self._on_map, qos.LATCHED)
        self.create_subscription(Odometry, "odom", self._on_odom, qos.LATEST)
        self.create_subscription(PoseArray, "humans", self._on_humans, qos.LATEST)
        self.create_subscription(PoseStamped, "goal_pose", self._on_goal, qos.RELIABLE)
        self.create_timer(1.0 / rate, self._check)

    def _now(self) -> float:
        return self.get_clock().now().nanoseconds * 1e-9

    def _on_map(self, msg: OccupancyGrid) -> None:
        grid = conv.occupancy_from_msg(msg)
        if self.nav is None:
            self.nav = Navigator(grid, self.planner_params, self.style, self.nav_params)
        else:
            self.nav.set_map(grid)
        self.get_logger().info(f"map {grid.width} x {grid.height} at {grid.resolution_m:g} m: {len(self.nav.planner.nodes)} corner nodes")
        self._try_pending()

    def _on_odom(self, msg: Odometry) -> None:
        self.robot = conv.pose_from_msg(msg.pose.pose)
        self._try_pending()

    def _on_humans(self, msg: PoseArray) -> None:
        self.humans = [(p.x, p.y) for p in conv.humans_from_msg(msg)]

    def _on_goal(self, msg: PoseStamped) -> None:
        goal = conv.pose_from_msg(msg.pose)
        frame = msg.header.frame_id or self.map_frame
        reason = None
        if frame not in (self.map_frame, "odom"):  # odom coincides with map here (no drift by default)
            reason = f"goal frame '{frame}' is not '{self.map_frame}'"
        elif not (math.isfinite(goal.x) and math.isfinite(goal.y)):
            reason = "goal position is not finite"
        if reason is not None:
            self._emit({"type": "plan_refused", "reason": reason})
            self.get_logger().warning(f"refused goal: {reason}")
            return
        self.pending = goal
        self._try_pending()

    def _try_pending(self) -> None:
        if self.pending is None or self.nav is None or self.robot is None:
            return
        goal, self.pending = self.pending, None
        out = self.nav.set_goal(self.robot, goal)
        for e in out.events:
            if e["type"] == "plan_refused":
                self.get_logger().warning(f"refused goal ({goal.x:.2f}, {goal.y:.2f}): {e['reason']}")
        self._apply(out)

    def _check(self) -> None:
        if self.nav is not None and self.robot is not None:
            self._apply(self.nav.update(self.robot, self.humans))

    def _apply(self, out: NavOutput) -> None:
        now = self._now()
        if out.path is not None:
            self.plan_pub.publish(conv.path_msg(now, out.path, self.map_frame))
        if out.waiting is not None:
            self.wait_pub.publish(Bool(data=out.waiting))
        for e in out.events:
            self._emit(e)

    def _emit(self, event: dict[str, object]) -> None:
        self.events_pub.publish(conv.event_msg({"stamp": round(self._now(), 4), "source": "planner", **event}))


def main(args: list[str] | None = None) -> None:
    sys.exit(run_node(PlannerNode, args))


if __name__ == "__main__":
    main()
