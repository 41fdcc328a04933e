"""Visualization node: HAVEN's AR cues on /haven/ar_markers, the world on /haven/world_markers.

Subscribes /plan, /odom, /battery_state, /humans, /haven/thought and /haven/events (gems collected,
obstructions removed). At `rate_hz` it computes the cues and sends only what changed, with an
explicit DELETE for every marker that went away; everything is resent when a viewer joins and every
`refresh_period_s`, for viewers and bag replays that start late. The four cue toggles (`path_projection`,
`turn_signals`, `thought_bubble`, `battery_indicator`) are the study condition: they can be set at
run time (`ros2 param set /viz thought_bubble false`, or any SetParameters client), and every
change is an event.
"""

from __future__ import annotations

import math
import sys

from geometry_msgs.msg import PoseArray
from nav_msgs.msg import Odometry, Path
from rcl_interfaces.msg import SetParametersResult
from rclpy.node import Node
from rclpy.parameter import Parameter
from sensor_msgs.msg import BatteryState
from std_msgs.msg import String
from visualization_msgs.msg import MarkerArray

from haven_sim.common.geometry import Pose2D
from haven_sim.nodes import conversions as sim_conv
from haven_sim.nodes import qos
from haven_sim.nodes.runner import run_node
from haven_sim.sim.world import World, load_world, resolve_world_path
from haven_viz.cues import ArCues, CueParams, Toggles
from haven_viz.markers import MarkerDiff
from haven_viz.nodes.conversions import marker_array
from haven_viz.world_markers import body_markers, world_markers

TOGGLES = ("path_projection", "turn_signals", "thought_bubble", "battery_indicator")


class VizNode(Node):
    def __init__(self) -> None:
        super().__init__("viz")
        d = self.declare_parameter
        self.toggles = Toggles(**{name: d(name, True).value for name in TOGGLES})
        self.params = CueParams(
            marker_spacing_m=d("marker_spacing_m", 0.4).value,
            steps_ahead=d("steps_ahead", 0).value,
            marker_size_m=d("marker_size_m", 0.2).value,
            scheme=d("scheme", "yellow").value,
            turn_signal_threshold_rad=math.radians(d("turn_signal_threshold_deg", 11.0).value),
            thought_radius_m=d("thought_radius_m", 3.0).value,
            thought_hysteresis_m=d("thought_hysteresis_m", 0.5).value,
            thought_backdrop=d("thought_backdrop", True).value,
        )
        self.frame = d("map_frame", "map").value
        rate = d("rate_hz", 10.0).value
        self.refresh_period_s = d("refresh_period_s", 2.0).value
        world_spec = d("world", "").value
        if not (rate > 0 and self.refresh_period_s > 0):
            raise ValueError(f"rate_hz and refresh_period_s must be positive, got {rate} and {self.refresh_period_s}")
        self.world: World | None = load_world(resolve_world_path(world_spec)) if world_spec else None
        self.cues = ArCues(self.params)
        self.ar_diff = MarkerDiff()
        self.world_diff = MarkerDiff()
        self._viewers = 0
        self._last_refresh = -1e9
        self.robot: Pose2D | None = None
        self.humans: list[Pose2D] = []
        self.battery: float | None = None
        self.thought = ""
        self.collected: set[str] = set()
        self.removed: set[str] = set()
        self.ar_pub = self.create_publisher(MarkerArray, "haven/ar_markers", qos.RELIABLE)
        self.world_pub = self.create_publisher(MarkerArray, "haven/world_markers", qos.LATCHED)
        self.events_pub = self.create_publisher(String, "haven/events", qos.EVENTS_PUB)
        self.create_subscription(Path, "plan", self._on_plan, qos.LATCHED)
        self.create_subscription(Odometry, "odom", self._on_odom, qos.LATEST)
        self.create_subscription(BatteryState, "battery_state", self._on_battery, qos.LATEST)
        self.create_subscription(PoseArray, "humans", self._on_humans, qos.LATEST)
        self.create_subscription(String, "haven/thought", self._on_thought, qos.LATCHED)
        self.create_subscription(String, "haven/events", self._on_event, qos.EVENTS)
        self.add_on_set_parameters_callback(self._check_params)
        self.add_post_set_parameters_callback(self._params_set)
        self.create_timer(1.0 / rate, self._tick)
        self._publish_world()

    # -- parameters: the cue toggles are the study condition -------------------------------------
    def _check_params(self, params: list[Parameter]) -> SetParametersResult:
        for p in params:
            if p.name in TOGGLES:
                if p.type_ != Parameter.Type.BOOL:
                    return SetParametersResult(successful=False, reason=f"{p.name} must be true or false")
            elif p.name != "use_sim_time":
                return SetParametersResult(successful=False, reason=f"{p.name} is read at start-up only; restart the node to change it")
        return SetParametersResult(successful=True)

    def _params_set(self, params: list[Parameter]) -> None:
        changes = {p.name: bool(p.value) for p in params if p.name in TOGGLES}
        if not changes:
            return
        before = self.toggles
        self.toggles = Toggles(**{**vars(before), **changes})
        for name, on in changes.items():
            if getattr(before, name) != on:
                self._emit({"type": "cue_toggled", "cue": name, "on": on})
                self.get_logger().info(f"{name} {'on' if on else 'off'}")
        self._tick()

    # -- inputs ----------------------------------------------------------------------------------
    def _on_plan(self, msg: Path) -> None:
        self.cues.set_path(sim_conv.path_from_msg(msg))

    def _on_odom(self, msg: Odometry) -> None:
        self.robot = sim_conv.pose_from_msg(msg.pose.pose)

    def _on_battery(self, msg: BatteryState) -> None:
        self.battery = msg.percentage

    def _on_humans(self, msg: PoseArray) -> None:
        self.humans = sim_conv.humans_from_msg(msg)

    def _on_thought(self, msg: String) -> None:
        self.thought = msg.data

    def _on_event(self, msg: String) -> None:
        event = sim_conv.event_from_msg(msg)
        kind = event.get("type")
        if kind == "gem_collected" and "gem" in event:
            self.collected.add(str(event["gem"]))
        elif kind == "obstruction_removed" and "id" in event:
            self.removed.add(str(event["id"]))
        elif kind == "reset":
            self.collected.clear()
            self.removed.clear()
        else:
            return
        self._publish_world()

    # -- outputs ---------------------------------------------------------------------------------
    def _now(self) -> float:
        return self.get_clock().now().nanoseconds * 1e-9

    def _publish_world(self) -> None:
        if self.world is None:
            return
        markers = world_markers(self.world, self.collected, self.removed)
        # Latched with depth 1: a late viewer gets only the last message, so it carries everything.
        update = self.world_diff.update(markers, resend_all=True)
        if update:
            self.world_pub.publish(marker_array(update, self._now(), self.frame))

    def _tick(self) -> None:
        if self.robot is None:
            return
        humans_xy = [(h.x, h.y) for h in self.humans]
        markers = self.cues.markers(self.robot, humans_xy, self.battery, self.thought, self.toggles)
        names = [h.id for h in self.world.humans] if self.world is not None else []
        named = [(names[i] if i < len(names) else f"h{i}", h) for i, h in enumerate(self.humans)]
        markers += body_markers(self.robot, named)
        # A viewer (or recorder) that joins late, or plays a bag from the middle, must get the markers
        # that have not changed since: resend everything when one joins and every refresh_period_s.
        now, viewers = self._now(), self.ar_pub.get_subscription_count()
        refresh = viewers > self._viewers or now - self._last_refresh >= self.refresh_period_s
        if refresh:
            self._last_refresh = now
        self._viewers = viewers
        update = self.ar_diff.update(markers, resend_all=refresh)
        if update:
            self.ar_pub.publish(marker_array(update, self._now(), self.frame))

    def _emit(self, event: dict[str, object]) -> None:
        self.events_pub.publish(sim_conv.event_msg({"stamp": round(self._now(), 4), "source": "viz", **event}))


def main(args: list[str] | None = None) -> None:
    sys.exit(run_node(VizNode, args))


if __name__ == "__main__":
    main()
