"""The simulator as a component: the `sim_node`'s behaviour without ROS.

It owns the `Simulation` and decides what is published when: at every physics step the clock,
/odom and `odom -> base_footprint` on /tf; /humans (and `map -> human_<id>` on /tf) at
`humans_rate_hz`, /scan at `scan_rate_hz`, /battery_state at `battery_rate_hz`; the map and the
static frames at start and whenever the world changes; the simulator's events as they happen. It
takes velocity commands for the robot and each person, and obstruction removals. It also reads the
e-stop (/haven/estop) as the velocity mux does: while it is on, the robot is commanded to stop
whatever arrives on /cmd_vel, so no publisher beside the mux (teleop_twist_keyboard's default
/cmd_vel) moves it.
"""

from __future__ import annotations

import functools
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from haven_sim.common import nodes, topics
from haven_sim.common.component import Handler, Message, due, period_ns
from haven_sim.common.events import EventKind
from haven_sim.common.geometry import ZERO_TWIST, FloatArray, Twist2D
from haven_sim.common.params import NOT_NEGATIVE, POSITIVE, config, group, param
from haven_sim.common.state import RobotState
from haven_sim.robots.fields import RobotChoice, from_robot
from haven_sim.sim.commands import CommandStatus
from haven_sim.sim.estop import ESTOP_HOLD_S, EStopLatch
from haven_sim.sim.frames import human_frames, robot_frame, static_frames
from haven_sim.sim.scan import ScanParams
from haven_sim.sim.simulation import SimConfig, Simulation
from haven_sim.sim.world import World


@config
class SimulatorConfig:
    robot: RobotChoice = group(RobotChoice)
    sim: SimConfig = group(SimConfig)
    world: str = param("small_test", "a packaged world name or a path to a world YAML")
    real_time_factor: float = param(1.0, "1.0 live; higher runs faster than real time", POSITIVE)
    humans_rate_hz: float = param(20.0, "/humans and the humans' TF frames (sim time)", POSITIVE)
    battery_rate_hz: float = param(5.0, "/battery_state (sim time)", POSITIVE)
    map_resolution_m: float = param(0.05, "cell size of /map", POSITIVE)
    map_frame: str = param("map", "fixed frame")
    odom_frame: str = param("odom", "odometry frame")
    publish_map_to_odom: bool = param(
        True, "the identity map -> odom on /tf_static; false leaves it to a localization node (AMCL, slam_toolbox)"
    )
    base_frame: str = from_robot("frames.base")  # the robot's frames, from its robot file
    scan_frame: str = from_robot("lidar.frame")
    lockstep_participants: tuple[str, ...] = param((), "with lockstep: the nodes that act on the clock's ticks")
    lockstep_observers: tuple[str, ...] = param(
        (), "with lockstep: participants nobody reads during a tick, not waited for"
    )
    lockstep_wait_for: tuple[str, ...] = param(
        (), "with lockstep: nodes that must listen before the first step (the recorder)"
    )
    reset_allowed: bool = param(
        True, "/haven/reset resets the world (haven run turns it off: a recorded trial refuses it, as an event)"
    )
    estop_hold_s: float = param(
        ESTOP_HOLD_S,
        "as the mux's: a false on /haven/estop releases the stop only when no true has come for this long",
        POSITIVE,
    )
    control_lag_s: float = param(
        0.1,
        "free-running clock: sim time runs at most this far (and two control ticks) "
        "ahead of the sim time the controller has acted at, slowing below real_time_factor "
        "when it falls behind (a clock_held event says how much); 0: never held",
        NOT_NEGATIVE,
    )


@dataclass(frozen=True)
class ScanData:
    """One /scan: ranges (REP-117) and how they were taken."""

    ranges: FloatArray
    params: ScanParams
    period_s: float


class SimulatorComponent:
    name = nodes.SIM.name
    unread: frozenset[str] = frozenset()
    period_s = None  # stepped by its owner (the pacer in ROS mode, the loop in batch mode)

    def __init__(self, world: World, config: SimulatorConfig | None = None) -> None:
        self.config = c = config or SimulatorConfig()
        self.sim = Simulation(world, c.sim)
        self._step_ns = c.sim.step_ns
        self._scan_ns, self._humans_ns, self._battery_ns = (
            period_ns(r) for r in (c.sim.scan.rate_hz, c.humans_rate_hz, c.battery_rate_hz)
        )
        self._map_due = self._static_due = True  # both go out with the first sense()
        self.estop = EStopLatch(c.estop_hold_s)
        self.warnings: list[str] = []

    @property
    def world(self) -> World:
        return self.sim.world

    # -- inputs ----------------------------------------------------------------------------------
    def handlers(self) -> Mapping[str, Handler]:
        out: dict[str, Handler] = {
            topics.CMD_VEL: self.on_cmd_vel,
            topics.REMOVE_OBSTRUCTION: self.on_remove_obstruction,
            topics.ESTOP: self.on_estop,
        }
        for h in self.world.humans:
            out[topics.human_cmd_vel(h.id)] = functools.partial(self.on_human_cmd, h.id)
        return out

    def outputs(self) -> Sequence[str]:
        fixed = (
            topics.CLOCK,
            topics.MAP,
            topics.ODOM,
            topics.TF,
            topics.TF_STATIC,
            topics.SCAN,
            topics.BATTERY,
            topics.HUMANS,
            topics.EVENTS,
        )
        return (*fixed, *(topics.human_pose(h.id) for h in self.world.humans))

    def on_cmd_vel(self, cmd: Twist2D, now: float) -> list[Message]:
        self._check(self.sim.command_robot(ZERO_TWIST if self.estop.engaged(now) else cmd), topics.CMD_VEL)
        return []

    def on_estop(self, engaged: bool, now: float) -> list[Message]:
        self.estop.said(engaged, now)
        if engaged:
            self.sim.command_robot(ZERO_TWIST)
        return []

    def on_human_cmd(self, human_id: str, cmd: Twist2D, now: float) -> list[Message]:
        self._check(self.sim.command_human(human_id, cmd), topics.human_cmd_vel(human_id))
        return []

    def on_remove_obstruction(self, obstruction_id: str, now: float) -> list[Message]:
        try:
            self.sim.remove_obstruction(obstruction_id)
        except KeyError:
            self.warnings.append(f"no obstruction {obstruction_id!r} in world '{self.world.name}'")
        return []

    def _check(self, status: CommandStatus, topic: str) -> None:
        if status is CommandStatus.REJECTED:
            self.warnings.append(f"dropped a non-finite command on /{topic.lstrip('/')}")

    def reset(self) -> None:
        self.sim.reset()
        self._map_due = self._static_due = True

    def tick(self, now: float) -> list[Message]:
        return []

    # -- stepping and outputs --------------------------------------------------------------------
    def advance(self) -> None:
        self.sim.step()

    def sense(self) -> list[Message]:
        """What is published for the current step (state at `sim.time`)."""
        sim, c = self.sim, self.config
        now, k = sim.time, sim.steps
        skip = self.unread
        out = [Message(topics.CLOCK, now, now)] if topics.CLOCK not in skip else []
        events = sim.pop_events()
        if self._static_due:
            self._static_due = False
            out.append(
                Message(
                    topics.TF_STATIC, static_frames(c.sim.robot, c.map_frame, c.odom_frame, c.publish_map_to_odom), now
                )
            )
        if self._map_due or (events and any(e.kind is EventKind.OBSTRUCTION_REMOVED for e in events)):
            self._map_due = False
            out.append(Message(topics.MAP, sim.occupancy(c.map_resolution_m), now))
        odom = sim.odometry_pose()
        altitude = sim.altitude.altitude_m
        out.append(Message(topics.ODOM, RobotState(odom, sim.robot_twist(), altitude), now))
        tf = topics.TF not in skip
        frames = [robot_frame(odom, c.odom_frame, c.base_frame, altitude)] if tf else []
        if due(k, self._step_ns, self._humans_ns):
            humans = sim.human_poses()
            frames += human_frames(humans, c.map_frame) if tf else []
            out.append(Message(topics.HUMANS, humans, now))
            poses = ((topics.human_pose(hid), pose) for hid, pose in humans.items())
            out += [Message(topic, pose, now) for topic, pose in poses if topic not in skip]
        if tf:
            out.append(Message(topics.TF, frames, now))
        if due(k, self._step_ns, self._scan_ns) and topics.SCAN not in skip:
            out.append(Message(topics.SCAN, ScanData(sim.scan(), c.sim.scan, 1.0 / c.sim.scan.rate_hz), now))
        if due(k, self._step_ns, self._battery_ns):
            out.append(Message(topics.BATTERY, sim.battery_reading(), now))
        out += [Message(topics.EVENTS, e, now) for e in events]
        return out
