"""Drives the robot around a square through /cmd_vel_teleop and prints a summary when done.

Shows the pattern for teleoperating HAVEN's robot from any node: publish geometry_msgs/Twist on
/cmd_vel_teleop (it overrides navigation in the velocity mux), read /odom.
"""

from __future__ import annotations

import json
import statistics
import sys

from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rclpy.node import Node
from sensor_msgs.msg import BatteryState
from std_msgs.msg import String

from haven_scenarios.teleop.square_drive import SquareDriver
from haven_sim.common.events import EventKind
from haven_sim.common.geometry import Pose2D
from haven_sim.nodes import conversions as conv, qos
from haven_sim.nodes.runner import declare, run_node


class DemoDriver(Node):
    def __init__(self) -> None:
        super().__init__("demo_driver")
        side = declare(self, "side_m", 1.5)
        laps = declare(self, "laps", 1)
        self.driver = SquareDriver(side_m=side, laps=laps)
        self.pose: Pose2D | None = None
        self.last_odom_t: float | None = None
        self.odom_gaps: list[float] = []  # sim time between consecutive /odom stamps
        self.battery = None
        self.contacts = 0
        self.touched: list[str] = []  # what each contact was with ("wall", "human:h1")
        self.pub = self.create_publisher(Twist, "cmd_vel_teleop", qos.RELIABLE)
        self.create_subscription(Odometry, "odom", self._on_odom, qos.RELIABLE)
        self.create_subscription(BatteryState, "battery_state", self._on_battery, qos.RELIABLE)
        self.create_subscription(String, "haven/events", self._on_event, qos.EVENTS)
        self.create_timer(0.05, self._tick)

    def _on_odom(self, msg: Odometry) -> None:
        self.pose = conv.pose_from_msg(msg.pose.pose)
        t = conv.time_from_msg(msg.header.stamp)
        if self.last_odom_t is not None:
            self.odom_gaps.append(t - self.last_odom_t)
        self.last_odom_t = t

    def _on_battery(self, msg: BatteryState) -> None:
        self.battery = msg.percentage

    def _on_event(self, msg: String) -> None:
        try:
            e = conv.event_from_msg(msg)
            if e.kind is EventKind.CONTACT_BEGIN:
                self.contacts += 1
                self.touched.append(str(e["other"]))
        except ValueError:
            pass

    def _tick(self) -> None:
        if self.pose is None:
            return
        self.pub.publish(conv.twist_msg(self.driver.command(self.pose)))
        if self.driver.done:
            gap = statistics.median(self.odom_gaps) if self.odom_gaps else 0.0
            summary = {
                "legs": self.driver.legs_done,
                "distance_m": round(self.driver.distance_m, 3),
                "final_pose": [round(v, 3) for v in self.pose],
                "battery": None if self.battery is None else round(self.battery, 4),
                "contacts": self.contacts,
                "contacts_with": self.touched,
                "odom_rate_hz_sim": round(1.0 / gap, 2) if gap > 0 else None,  # from the stamps: one per physics step
            }
            battery = "n/a" if self.battery is None else f"{100 * self.battery:.1f} %"
            print(
                f"demo: drove {summary['legs']} legs, {summary['distance_m']:.2f} m, battery {battery}, "
                f"{self.contacts} contact(s), /odom at {summary['odom_rate_hz_sim']} Hz of sim time",
                flush=True,
            )
            print(json.dumps(summary), flush=True)
            raise SystemExit(0)


def main(args: list[str] | None = None) -> None:
    sys.exit(run_node(DemoDriver, args))


if __name__ == "__main__":
    main()
