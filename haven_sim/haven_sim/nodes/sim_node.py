"""Simulator node: steps the core Simulation at real_time_factor x wall time and publishes its state.

Publishes /clock, /map (latched), /odom (every physics step, 50 Hz) with odom -> base_footprint on
/tf, the fixed frames on /tf_static, /scan, /battery_state, /humans (and map -> human_<id> on /tf)
and /haven/events; subscribes /cmd_vel, /humans/<id>/cmd_vel and /haven/events (obstructions a
scenario clears); serves /haven/reset.
"""

from __future__ import annotations

import math
import sys
import time

from geometry_msgs.msg import PoseArray, Twist
from nav_msgs.msg import OccupancyGrid, Odometry
from rclpy.clock import Clock, ClockType
from rclpy.node import Node
from rosgraph_msgs.msg import Clock as ClockMsg
from sensor_msgs.msg import BatteryState, LaserScan
from std_msgs.msg import String
from std_srvs.srv import Trigger

from haven_sim.sim.battery import BatteryParams
from haven_sim.sim.frames import human_frames, robot_frame, static_frames
from haven_sim.sim.commands import CommandStatus, VelocityLimits
from haven_sim.nodes import conversions as conv
from haven_sim.nodes import qos
from haven_sim.nodes.runner import run_node
from haven_sim.sim.odometry import OdometryNoise
from haven_sim.sim.pacer import Pacer
from haven_sim.sim.scan import ScanParams
from haven_sim.sim.simulation import SimConfig, Simulation
from haven_sim.sim.world import load_world, resolve_world_path

try:  # not on PyPI: the pip setup builds it with colcon (scripts/build_interfaces.py)
    from tf2_msgs.msg import TFMessage
except ImportError:  # pragma: no cover - depends on the machine
    TFMessage = None


class SimNode(Node):
    def __init__(self) -> None:
        super().__init__("sim_node")
        p = {
            name: self.declare_parameter(name, default).value
            for name, default in [
                ("world", "small_test"),
                ("real_time_factor", 1.0),
                ("physics_rate_hz", 50.0),
                ("scan_rate_hz", 10.0),
                ("scan_beams", 360),
                ("scan_range_min_m", 0.12),
                ("scan_range_max_m", 3.5),
                ("scan_noise_std_m", 0.0),
                ("battery_rate_hz", 5.0),
                ("humans_rate_hz", 20.0),
                ("map_resolution_m", 0.05),
                ("max_linear_speed_mps", 0.7),
                ("max_angular_speed_rps", math.pi),
                ("max_linear_accel_mps2", 0.5),
                ("max_angular_accel_rps2", 3.5),
                ("human_max_speed_mps", 1.5),
                ("cmd_timeout_s", 0.5),
                ("battery_capacity_m", 100.0),
                ("battery_drain_per_rad", 0.0),
                ("battery_idle_drain_per_s", 0.0),
                ("battery_charge_rate_per_s", 0.05),
                ("battery_initial_level", 1.0),
                ("odom_noise_linear", 0.0),
                ("odom_noise_angular", 0.0),
                ("seed", 0),
                ("map_frame", "map"),
                ("odom_frame", "odom"),
                ("base_frame", "base_footprint"),
                ("scan_frame", "base_scan"),
            ]
        }
        self.p = p
        world = load_world(resolve_world_path(p["world"]))
        for name in ("physics_rate_hz", "scan_rate_hz", "battery_rate_hz", "humans_rate_hz"):
            if not p[name] > 0:
                raise ValueError(f"parameter {name} must be positive, got {p[name]}")
        base_radius = world.charging_base.radius if world.charging_base else 0.5
        config = SimConfig(
            step_s=1.0 / p["physics_rate_hz"],
            robot_limits=VelocityLimits(
                max_linear_mps=p["max_linear_speed_mps"],
                max_angular_rps=p["max_angular_speed_rps"],
                max_linear_accel_mps2=p["max_linear_accel_mps2"],
                max_angular_accel_rps2=p["max_angular_accel_rps2"],
            ),
            human_limits=VelocityLimits.human(p["human_max_speed_mps"]),
            cmd_timeout_s=p["cmd_timeout_s"],
            scan=ScanParams(
                beams=p["scan_beams"],
                range_min_m=p["scan_range_min_m"],
                range_max_m=p["scan_range_max_m"],
                rate_hz=p["scan_rate_hz"],
                noise_std_m=p["scan_noise_std_m"],
            ),
            battery=BatteryParams(
                capacity_m=p["battery_capacity_m"],
                drain_per_rad=p["battery_drain_per_rad"],
                idle_drain_per_s=p["battery_idle_drain_per_s"],
                charge_rate_per_s=p["battery_charge_rate_per_s"],
                initial_level=p["battery_initial_level"],
                base_radius_m=base_radius,
            ),
            odom_noise=OdometryNoise(p["odom_noise_linear"], p["odom_noise_angular"]),
            seed=p["seed"],
        )
        self.sim = Simulation(world, config)
        self.pacer = Pacer(config.step_s, p["real_time_factor"])
        rate = p["physics_rate_hz"]
        self._scan_every = max(1, round(rate / p["scan_rate_hz"]))
        self._battery_every = max(1, round(rate / p["battery_rate_hz"]))
        self._humans_every = max(1, round(rate / p["humans_rate_hz"]))
        self._step_count = 0

        self.clock_pub = self.create_publisher(ClockMsg, "/clock", qos.CLOCK)
        self.map_pub = self.create_publisher(OccupancyGrid, "map", qos.LATCHED)
        self.odom_pub = self.create_publisher(Odometry, "odom", qos.RELIABLE)
        self.scan_pub = self.create_publisher(LaserScan, "scan", qos.SENSOR)
        self.battery_pub = self.create_publisher(BatteryState, "battery_state", qos.RELIABLE)
        self.humans_pub = self.create_publisher(PoseArray, "humans", qos.RELIABLE)
        self.events_pub = self.create_publisher(String, "haven/events", qos.EVENTS_PUB)
        self.create_subscription(Twist, "cmd_vel", self._on_cmd_vel, qos.RELIABLE)
        for h in world.humans:
            self.create_subscription(
                Twist, f"humans/{h.id}/cmd_vel", lambda msg, hid=h.id: self._on_human_cmd(hid, msg), qos.RELIABLE
            )
        self.tf_pub = self.tf_static_pub = None
        if TFMessage is not None:
            self.tf_pub = self.create_publisher(TFMessage, "/tf", qos.TF)
            self.tf_static_pub = self.create_publisher(TFMessage, "/tf_static", qos.LATCHED)
            frames = static_frames(p["map_frame"], p["odom_frame"], p["base_frame"], p["scan_frame"])
            self.tf_static_pub.publish(TFMessage(transforms=[conv.transform_msg(0.0, f) for f in frames]))
        else:
            self.get_logger().warning("tf2_msgs is not installed: no /tf or /tf_static (run scripts/build_interfaces.py)")
        self.create_service(Trigger, "haven/reset", self._on_reset)
        # A scenario rule clears an obstruction (e.g. when a participant reaches a room first).
        self.create_subscription(String, "haven/events", self._on_event, qos.EVENTS)
        self._publish_map()
        # Wall-clock timer: this node is the clock, so it must not wait on /clock itself.
        steady = Clock(clock_type=ClockType.STEADY_TIME)
        self.create_timer(self.pacer.tick_period_s, self._tick, clock=steady)
        self.get_logger().info(
            f"world '{world.name}' from {world.source}: {len(world.humans)} human(s), "
            f"{rate:g} Hz physics at {p['real_time_factor']:g}x real time"
        )

    # -- inputs ----------------------------------------------------------------------------------
    def _on_cmd_vel(self, msg: Twist) -> None:
        self._check(self.sim.command_robot(conv.twist_from_msg(msg)), "/cmd_vel")

    def _on_human_cmd(self, human_id: str, msg: Twist) -> None:
        self._check(self.sim.command_human(human_id, conv.twist_from_msg(msg)), f"/humans/{human_id}/cmd_vel")

    def _check(self, status: CommandStatus, topic: str) -> None:
        if status is CommandStatus.REJECTED:
            self.get_logger().warning(f"dropped a non-finite command on {topic}", throttle_duration_sec=2.0)

    def _on_event(self, msg: String) -> None:
        event = conv.event_from_msg(msg)
        if event.get("type") == "obstruction_cleared" and event.get("id") not in self.sim.removed:
            try:
                self.sim.remove_obstruction(str(event.get("id")))
            except KeyError:
                self.get_logger().warning(f"no obstruction '{event.get('id')}' in this world")
                return
            self._publish_events()

    def _on_reset(self, request: Trigger.Request, response: Trigger.Response) -> Trigger.Response:
        self.sim.reset()
        self._publish_map()
        self._publish_events()
        response.success = True
        response.message = f"world '{self.sim.world.name}' reset at t={self.sim.time:.2f} s"
        return response

    # -- outputs ---------------------------------------------------------------------------------
    def _tick(self) -> None:
        for _ in range(self.pacer.due_steps(time.monotonic())):
            self._step()

    def _step(self) -> None:
        sim = self.sim
        sim.step()
        self._step_count += 1
        now = sim.time
        p = self.p
        self.clock_pub.publish(conv.clock_msg(now))
        self.odom_pub.publish(
            conv.odometry_msg(now, sim.odometry_pose(), sim.robot_twist(), p["odom_frame"], p["base_frame"])
        )
        n = self._step_count
        if self.tf_pub is not None:
            frames = [robot_frame(sim.odometry_pose(), p["odom_frame"], p["base_frame"])]
            if n % self._humans_every == 0:
                frames += human_frames(sim.human_poses(), p["map_frame"])
            self.tf_pub.publish(TFMessage(transforms=[conv.transform_msg(now, f) for f in frames]))
        if n % self._scan_every == 0:
            period = self._scan_every * sim.config.step_s
            self.scan_pub.publish(conv.scan_msg(now, sim.scan(), sim.config.scan, period, p["scan_frame"]))
        if n % self._humans_every == 0:
            self.humans_pub.publish(conv.humans_msg(now, sim.human_poses(), p["map_frame"]))
        if n % self._battery_every == 0:
            self.battery_pub.publish(conv.battery_msg(now, sim.battery_reading()))
        self._publish_events()

    def _publish_events(self) -> None:
        for event in self.sim.pop_events():
            if event.type.startswith("obstruction"):
                self._publish_map()
            self.events_pub.publish(conv.event_msg(event.as_dict()))

    def _publish_map(self) -> None:
        grid = self.sim.occupancy(self.p["map_resolution_m"])
        self.map_pub.publish(conv.occupancy_msg(self.sim.time, grid, self.p["map_frame"]))


def main(args: list[str] | None = None) -> None:
    sys.exit(run_node(SimNode, args))


if __name__ == "__main__":
    main()
