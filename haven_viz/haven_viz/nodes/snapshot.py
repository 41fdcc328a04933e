"""Saves what the viewers show right now as a top-down PNG: listens to /haven/world_markers and
/haven/ar_markers until the viz node's next full refresh, then renders them with the world's walls.
With no suite there (nothing on /haven/world_markers within `timeout_s` of wall time) it says so
and exits with code 1."""

from __future__ import annotations

import os
import sys

from rclpy.clock import Clock, ClockType
from rclpy.node import Node
from visualization_msgs.msg import Marker, MarkerArray

from haven_sim.nodes import qos
from haven_sim.nodes.runner import declare, run_node
from haven_sim.sim.world import resolve_world_path
from haven_sim.sim.world_file import load_world
from haven_viz.markers import MarkerSpec
from haven_viz.nodes.conversions import spec_from_msg
from haven_viz.render import render_scene


class Snapshot(Node):
    def __init__(self) -> None:
        super().__init__("snapshot")
        self.world = load_world(resolve_world_path(declare(self, "world", "small_test")))
        self.out = declare(self, "output", "haven_snapshot.png")
        self.wait_s = declare(self, "wait_s", 2.5)  # one refresh period of the viz node, and a bit
        self.live: dict[tuple[str, int], MarkerSpec] = {}
        self.have_world = False
        self.start: float | None = None
        self.create_subscription(MarkerArray, "haven/world_markers", self._on_world, qos.LATCHED)
        self.create_subscription(MarkerArray, "haven/ar_markers", self._on_ar, qos.RELIABLE)
        self.timeout_s = float(declare(self, "timeout_s", 10.0))
        self.create_timer(0.1, self._tick)
        self.create_timer(self.timeout_s, self._give_up, clock=Clock(clock_type=ClockType.STEADY_TIME))

    def _give_up(self) -> None:
        if not self.have_world:
            print(
                "snapshot: error: no HAVEN suite here: nothing on /haven/world_markers within "
                f"{self.timeout_s:g} s (ROS_DOMAIN_ID {os.environ.get('ROS_DOMAIN_ID', '0')}; "
                "is `haven sim` or `haven run` running with the same --domain-id?)",
                file=sys.stderr,
                flush=True,
            )
            raise SystemExit(1)

    def _apply(self, msg: MarkerArray) -> None:
        for m in msg.markers:
            if m.action == Marker.DELETE:
                self.live.pop((m.ns, m.id), None)
            elif m.action == Marker.ADD:
                self.live[(m.ns, m.id)] = spec_from_msg(m)

    def _on_world(self, msg: MarkerArray) -> None:
        self.have_world = True
        self._apply(msg)

    def _on_ar(self, msg: MarkerArray) -> None:
        self._apply(msg)

    def _tick(self) -> None:
        now = self.get_clock().now().nanoseconds * 1e-9
        if self.start is None:
            self.start = now
        if not self.have_world or now - self.start < self.wait_s:
            return
        path = render_scene(self.world, list(self.live.values()), self.out, title=f"{self.world.name} (live snapshot)")
        print(f"snapshot: wrote {path} ({len(self.live)} markers)", flush=True)
        raise SystemExit(0)


def main(args: list[str] | None = None) -> None:
    sys.exit(run_node(Snapshot, args))


if __name__ == "__main__":
    main()
