"""The simulator core: world + physics + sensors + battery, advanced in fixed steps of sim time.

Used the same way by the ROS simulator node (one step per pacer tick) and by batch mode (a plain
loop). Sim time is a whole number of steps (no drift from adding floats); commands are stamped with
it, so the 0.5 s watchdog is in sim time too.
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

from haven_sim.common.bodies import HUMAN_BODY
from haven_sim.common.component import NS_PER_S
from haven_sim.common.events import Event, EventKind, Source, event
from haven_sim.common.geometry import FloatArray, Pose2D, Twist2D, wrap_angle
from haven_sim.common.params import POSITIVE, config, group, param
from haven_sim.robots.fields import Robot, from_robot
from haven_sim.sim.battery import Battery, BatteryParams, BatteryReading
from haven_sim.sim.commands import CommandGate, CommandStatus, VelocityLimits
from haven_sim.sim.flight import Altitude, FlightPhase, clear_height, pad_of, start_pose
from haven_sim.sim.occupancy import OccupancyGridData, rasterise
from haven_sim.sim.odometry import Odometry, OdometryNoise
from haven_sim.sim.physics import Physics
from haven_sim.sim.scan import LaserScanner, ScanParams
from haven_sim.sim.world import World


@config
class SimConfig:
    physics_rate_hz: float = param(
        50.0, "physics steps per second of sim time (/odom is published every step)", POSITIVE
    )
    robot: Robot = from_robot()  # the robot's body, limits and flight (its `robot` parameter names it)
    human_max_speed_mps: float = param(1.5, "a person's top walking speed", POSITIVE)
    cmd_timeout_s: float = param(0.5, "no command for this long (sim time) stops a body", POSITIVE)
    scan: ScanParams = group(ScanParams, prefix="scan_")
    battery: BatteryParams = group(BatteryParams, prefix="battery_")
    odom_noise: OdometryNoise = group(OdometryNoise, prefix="odom_noise_")
    seed: int = param(0, "seed of the scan and odometry noise")

    def __post_init__(self) -> None:
        if NS_PER_S % round(NS_PER_S / self.physics_rate_hz):
            raise ValueError(
                "physics_rate_hz must divide a second into whole nanoseconds "
                f"(25, 50, 100, 200...), got {self.physics_rate_hz}"
            )

    @property
    def step_ns(self) -> int:
        return round(NS_PER_S / self.physics_rate_hz)

    @property
    def step_s(self) -> float:
        return self.step_ns / NS_PER_S

    @property
    def robot_limits(self) -> VelocityLimits:
        return VelocityLimits.of(self.robot.limits)

    @property
    def human_limits(self) -> VelocityLimits:
        return VelocityLimits.human(self.human_max_speed_mps)


class UnknownHumanError(KeyError):
    pass


class Simulation:
    def __init__(self, world: World, config: SimConfig | None = None) -> None:
        self.world = world
        self.config = config or SimConfig()
        base = world.charging_base
        if base is not None and self.config.battery.base_radius_m != base.radius:
            self.config = replace(self.config, battery=replace(self.config.battery, base_radius_m=base.radius))
        self.steps = 0
        self._step_ns, self._step_s = self.config.step_ns, self.config.step_s  # config is frozen: read per step
        self.robot_gate = CommandGate(self.config.robot_limits, self.config.cmd_timeout_s)
        self.human_gates = {
            h.id: CommandGate(self.config.human_limits, self.config.cmd_timeout_s) for h in world.humans
        }
        self.battery = Battery(self.config.battery)
        robot = self.config.robot
        self.start = start_pose(world, robot)  # an aerial robot starts on its pad
        self.altitude = Altitude(robot.flight, pad_of(world, self.config.battery.base_radius_m))
        self.below = clear_height(robot)  # an aerial robot flies over the obstacles lower than this
        self.odometry = Odometry(self.start, self.config.odom_noise, seed=self.config.seed)
        self._events: list[Event] = []
        self.removed: set[str] = set()
        self._build()

    def _build(self) -> None:
        w = self.world
        # An aerial robot: no low obstacles in its physics, its scan (the lidar at flight height) or
        # its map; walls, obstructions and people stay solid (at cruise height it is below a head).
        self.physics = Physics(
            w.edges(obstructions=False, below=self.below),
            self.start,
            {h.id: h.start for h in w.humans},
            self.config.robot.body(),
        )
        for o in w.obstructions:  # kept apart so that each can be removed
            self.physics.add_obstruction(o.id, o.shape.edges())
        self.scanner = LaserScanner(self.config.scan, w.edges(below=self.below), seed=self.config.seed)
        self.removed = set()
        self._battery_was_empty = self.battery.empty
        self._robot_pose = self.physics.robot.pose()

    # -- inputs --------------------------------------------------------------------------------
    def command_robot(self, cmd: Twist2D) -> CommandStatus:
        return self.robot_gate.command(cmd, self.time)

    def command_human(self, human_id: str, cmd: Twist2D) -> CommandStatus:
        gate = self.human_gates.get(human_id)
        if gate is None:
            raise UnknownHumanError(human_id)
        return gate.command(cmd, self.time)

    def remove_obstruction(self, obstruction_id: str) -> None:
        if obstruction_id in self.removed:
            return
        if obstruction_id not in {o.id for o in self.world.obstructions}:
            raise KeyError(obstruction_id)
        self.removed.add(obstruction_id)
        self.physics.remove_obstruction(obstruction_id)
        self.scanner.set_edges(self.world.edges(frozenset(self.removed), below=self.below))
        self._emit(EventKind.OBSTRUCTION_REMOVED, id=obstruction_id)

    def reset(self) -> None:
        """Back to the world's start state; sim time keeps running (a /clock never goes backwards)."""
        self.robot_gate.reset()
        for g in self.human_gates.values():
            g.reset()
        self.battery.reset()
        self.altitude.reset()
        self.odometry.reset(self.start)
        self._build()
        self._emit(EventKind.RESET)

    # -- stepping ------------------------------------------------------------------------------
    @property
    def time(self) -> float:
        """Sim seconds since the start."""
        return self.steps * self._step_ns / NS_PER_S

    def step(self) -> None:
        dt = self._step_s
        now = self.time
        free, flight_events = self.altitude.step(self.robot_gate.target(now), self._robot_pose, dt)
        robot_cmd = self.robot_gate.update(now, dt, enabled=free and not self.battery.empty)
        human_cmds = {hid: g.update(now, dt) for hid, g in self.human_gates.items()}
        before = self._robot_pose
        self.physics.step(robot_cmd, human_cmds, dt)
        self.steps += 1
        after = self._robot_pose = self.physics.robot.pose()
        dist = math.hypot(after.x - before.x, after.y - before.y)
        base = self.world.charging_base
        to_base = math.hypot(after.x - base.position[0], after.y - base.position[1]) if base else math.inf
        if self.altitude.flight is not None and self.altitude.phase is not FlightPhase.LANDED:
            to_base = math.inf  # an aerial robot charges only when landed on its pad
        self.battery.update(dt, dist, wrap_angle(after.yaw - before.yaw), dist / dt, to_base, self.altitude.airborne)
        self.odometry.update(after)
        for kind in flight_events:
            self._emit(kind)
        for e in self.physics.events:
            self._emit(e.kind, other=e.other)
        self.physics.events.clear()
        if self.battery.empty and not self._battery_was_empty:
            self._emit(EventKind.BATTERY_EMPTY)
        self._battery_was_empty = self.battery.empty

    def run(self, duration_s: float) -> None:
        for _ in range(round(duration_s / self.config.step_s)):
            self.step()

    def _emit(self, kind: EventKind, **data: Any) -> None:
        self._events.append(event(kind, self.time, Source.SIM, **data))

    def pop_events(self) -> list[Event]:
        out, self._events = self._events, []
        return out

    # -- outputs -------------------------------------------------------------------------------
    def robot_pose(self) -> Pose2D:
        """Ground truth in `map`."""
        return self._robot_pose

    def robot_twist(self) -> Twist2D:
        return self.physics.robot.body_twist()

    def odometry_pose(self) -> Pose2D:
        return self.odometry.pose

    def human_poses(self) -> dict[str, Pose2D]:
        return self.physics.human_poses()

    def human_circles(self) -> list[tuple[float, float, float]]:
        r = HUMAN_BODY.radius_m
        return [(p.x, p.y, r) for p in self.physics.human_poses().values()]

    def scan(self) -> FloatArray:
        return self.scanner.scan(self.robot_pose(), self.human_circles())

    def battery_reading(self) -> BatteryReading:
        return self.battery.reading()

    def contacts(self) -> list[str]:
        return self.physics.in_contact()

    def occupancy(self, resolution_m: float = 0.05) -> OccupancyGridData:
        return rasterise(self.world, resolution_m, removed=frozenset(self.removed), below=self.below)
