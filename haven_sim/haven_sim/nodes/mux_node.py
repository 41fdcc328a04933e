"""Velocity mux node: /cmd_vel_teleop beats /cmd_vel_nav; /haven/estop (latched Bool) forces zero.

Publishes /cmd_vel on every input and at `rate_hz`, and one zero when every source has gone quiet,
so the robot stops at once instead of waiting for the simulator's watchdog. Source changes are
events on /haven/events (a teleop takeover is part of a study's record).
"""

from __future__ import annotations

import sys

from geometry_msgs.msg import Twist
from rclpy.node import Node
from std_msgs.msg import Bool, String

from haven_sim.nav.mux import IDLE, VelocityMux
from haven_sim.nodes import conversions as conv
from haven_sim.nodes import qos
from haven_sim.nodes.runner import run_node


class MuxNode(Node):
    def __init__(self) -> None:
        super().__init__("velocity_mux")
        teleop_timeout = self.declare_parameter("teleop_timeout_s", 0.5).value
        nav_timeout = self.declare_parameter("nav_timeout_s", 0.5).value
        rate_hz = self.declare_parameter("rate_hz", 20.0).value
        if not (teleop_timeout > 0 and nav_timeout > 0 and rate_hz > 0):
            raise ValueError("teleop_timeout_s, nav_timeout_s and rate_hz must be positive")
        self.mux = VelocityMux(teleop_timeout, nav_timeout)
        self._last_source = IDLE
        self.pub = self.create_publisher(Twist, "cmd_vel", qos.RELIABLE)
        self.events_pub = self.create_publisher(String, "haven/events", qos.EVENTS_PUB)
        self.create_subscription(Twist, "cmd_vel_nav", self._on_nav, qos.RELIABLE)
        self.create_subscription(Twist, "cmd_vel_teleop", self._on_teleop, qos.RELIABLE)
        self.create_subscription(Bool, "haven/estop", self._on_estop, qos.LATCHED)
        self.create_timer(1.0 / rate_hz, self._publish)

    def _now(self) -> float:
        return self.get_clock().now().nanoseconds * 1e-9

    def _on_nav(self, msg: Twist) -> None:
        self.mux.on_nav(conv.twist_from_msg(msg), self._now())
        self._publish()

    def _on_teleop(self, msg: Twist) -> None:
        self.mux.on_teleop(conv.twist_from_msg(msg), self._now())
        self._publish()

    def _on_estop(self, msg: Bool) -> None:
        self.mux.set_estop(bool(msg.data))
        self._publish()

    def _publish(self) -> None:
        now = self._now()
        out = self.mux.output(now)
        if out.source != self._last_source:
            event = {"stamp": round(now, 4), "source": "mux", "type": "cmd_source", "from": self._last_source, "to": out.source}
            self.events_pub.publish(conv.event_msg(event))
        if out.source != IDLE or self._last_source != IDLE:
            self.pub.publish(conv.twist_msg(out.twist))
        self._last_source = out.source


def main(args: list[str] | None = None) -> None:
    sys.exit(run_node(MuxNode, args))


if __name__ == "__main__":
    main()
