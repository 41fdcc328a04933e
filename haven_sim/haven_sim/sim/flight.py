"""An aerial robot's height: it starts landed on its pad, takes off when commanded to move, cruises
at its flight's cruise height and lands when it stays stopped on its pad.

Plain state, stepped by the simulation: `step` takes the command the robot is given and says
whether the body may move (not until it is near cruise height, not while it lands: the command
gate then holds it at rest, so it starts within its acceleration limits), with the events
`took_off` / `landed`. A ground robot (no flight) is always on the floor and always free to move.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import Enum

from haven_sim.common.events import EventKind
from haven_sim.common.geometry import Point, Pose2D, Twist2D
from haven_sim.robots.description import Flight, RobotDescription
from haven_sim.sim.world import World

CRUISE_TOLERANCE_M = 0.05  # horizontal motion starts this close below cruise height
LAND_AFTER_S = 1.0  # stopped on its pad this long, it lands
MOVING = 1e-6  # a command component above this (m/s, rad/s) asks it to move


class FlightPhase(Enum):
    LANDED = "landed"
    CLIMBING = "climbing"
    CRUISING = "cruising"
    DESCENDING = "descending"


@dataclass(frozen=True)
class Pad:
    """Where an aerial robot takes off and lands: the world's charging base, else its start."""

    position: Point
    radius_m: float


def pad_of(world: World, default_radius_m: float) -> Pad:
    base = world.charging_base
    if base is not None:
        return Pad(base.position, base.radius)
    return Pad((world.robot_start.x, world.robot_start.y), default_radius_m)


def start_pose(world: World, robot: RobotDescription) -> Pose2D:
    """Where the robot starts: an aerial robot on its pad (facing the world's start heading)."""
    if not robot.aerial or world.charging_base is None:
        return world.robot_start
    x, y = world.charging_base.position
    return Pose2D(x, y, world.robot_start.yaw)


def clear_height(robot: RobotDescription) -> float | None:
    """An aerial robot flies over obstacles lower than this (cruise height less its clearance);
    None for a ground robot (every obstacle is in its way)."""
    f = robot.flight
    return None if f is None else f.cruise_height_m - f.clearance_m


class Altitude:
    """The robot's height above the floor and its flight phase."""

    def __init__(self, flight: Flight | None, pad: Pad) -> None:
        self.flight = flight
        self.pad = pad
        self.reset()

    def reset(self) -> None:
        self.altitude_m = 0.0
        self.phase = FlightPhase.LANDED
        self._stopped_s = 0.0

    @property
    def airborne(self) -> bool:
        """In the air (a ground robot: always 'switched on', so its idle drain always applies)."""
        return self.flight is None or self.phase is not FlightPhase.LANDED

    def on_pad(self, pose: Pose2D) -> bool:
        return math.hypot(pose.x - self.pad.position[0], pose.y - self.pad.position[1]) <= self.pad.radius_m

    def step(self, cmd: Twist2D, pose: Pose2D, dt: float) -> tuple[bool, list[EventKind]]:
        """One step, given the robot's command: whether it may move, and the events of the step."""
        f = self.flight
        if f is None:
            return True, []
        moving = max(abs(cmd.vx), abs(cmd.vy), abs(cmd.wz)) > MOVING
        self._stopped_s = 0.0 if moving else self._stopped_s + dt
        events: list[EventKind] = []
        if moving and self.phase in (FlightPhase.LANDED, FlightPhase.DESCENDING):
            if self.phase is FlightPhase.LANDED:
                events.append(EventKind.TOOK_OFF)
            self.phase = FlightPhase.CLIMBING
        elif self.phase is FlightPhase.CRUISING and self._stopped_s >= LAND_AFTER_S and self.on_pad(pose):
            self.phase = FlightPhase.DESCENDING
        rise = f.climb_rate_mps * dt
        if self.phase is FlightPhase.CLIMBING:
            self.altitude_m = min(f.cruise_height_m, self.altitude_m + rise)
            if self.altitude_m >= f.cruise_height_m - CRUISE_TOLERANCE_M:
                self.phase = FlightPhase.CRUISING
        elif self.phase is FlightPhase.DESCENDING:
            self.altitude_m = max(0.0, self.altitude_m - rise)
            if self.altitude_m <= 0.0:
                self.phase = FlightPhase.LANDED
                events.append(EventKind.LANDED)
        elif self.phase is FlightPhase.CRUISING and self.altitude_m < f.cruise_height_m:
            self.altitude_m = min(f.cruise_height_m, self.altitude_m + rise)
        return self.phase is FlightPhase.CRUISING, events
