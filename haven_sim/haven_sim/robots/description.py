"""A robot as the suite uses it: one frozen description, read from a robot file (`robot_file.py`),
that every part of the suite takes its figures from: the physics (footprint, mass, limits), the
planner's inflation and the navigator's passing clearances (footprint), the controller (cruise speed,
turn rate, whether it rotates in place), the battery, the lidar, the TF frames, where the cues sit,
the metrics' contact distance, the simulated people's perception and the pages' look.

Plain data, no ROS: a robot file a lab writes and one a plugin registers end up as this.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from enum import StrEnum
from typing import Any

from haven_sim.common.bodies import HUMAN_BODY, BodySpec
from haven_sim.common.geometry import Point


class Kinematics(StrEnum):
    DIFF_DRIVE = "diff_drive"  # drives forward and turns; rotates in place for sharp turns (HAVEN's TurtleBot2)
    OMNI = "omni"  # moves in any direction and turns while it moves: never rotates in place
    AERIAL = "aerial"  # flies holonomically at its cruise height; takes off from and lands on its pad


@dataclass(frozen=True)
class Footprint:
    """The robot seen from above, in its base frame: a circle (`radius_m`) or a convex polygon."""

    radius_m: float = 0.0
    polygon: tuple[Point, ...] = ()

    @property
    def circumradius_m(self) -> float:
        """The radius of the smallest circle about the base frame's origin holding the footprint:
        what the planner inflates by and the contact distance is measured from."""
        if self.polygon:
            return max(math.hypot(x, y) for x, y in self.polygon)
        return self.radius_m

    @property
    def width_m(self) -> float:
        """Across, side to side (y)."""
        if self.polygon:
            ys = [y for _, y in self.polygon]
            return max(ys) - min(ys)
        return 2.0 * self.radius_m


@dataclass(frozen=True)
class Limits:
    max_linear_speed_mps: float
    max_angular_speed_rps: float
    max_linear_accel_mps2: float
    max_angular_accel_rps2: float
    max_lateral_speed_mps: float = 0.0  # 0 for a differential drive


@dataclass(frozen=True)
class Motion:
    """How the suite drives it."""

    cruise_speed_mps: float  # along arcs and straights
    max_turn_rate_rps: float  # while driving
    rotate_in_place: bool  # sharp turns start with a rotation on the spot (HAVEN's rule); only a diff drive needs it


@dataclass(frozen=True)
class Battery:
    """In HAVEN's units: the pack as metres of travel, drains and charging as fractions of a full charge."""

    capacity_m: float
    idle_drain_per_s: float = 0.0  # always while it is switched on (an aerial robot: while it is in the air)
    drain_per_rad: float = 0.0
    charge_rate_per_s: float = 0.05


@dataclass(frozen=True)
class Lidar:
    beams: int
    range_min_m: float
    range_max_m: float
    rate_hz: float
    height_m: float  # above the floor (above base_footprint)
    frame: str = "base_scan"


@dataclass(frozen=True)
class Frames:
    base: str = "base_footprint"
    base_link: str = "base_link"
    base_link_height_m: float = 0.0102


@dataclass(frozen=True)
class CueMounts:
    """Where the robot's own cues sit, above its base frame (the body's top unless a file says)."""

    signal_height_m: float  # the turn-signal arrows
    signal_offset_m: float  # ... this far out to the side of the centre
    gauge_height_m: float  # the battery gauge
    bubble_height_m: float  # the thought bubble's centre


@dataclass(frozen=True)
class Primitive:
    """One part of the look: a box (size x, y, z), cylinder (radius, radius, height; its axis up),
    sphere (radius), cone (radius, radius, height, pointing up) or torus (radius, tube, -), at a
    position in the base frame, turned by roll-pitch-yaw, in a colour; `spin` turns it about its
    axis while the robot moves (rotors, wheels)."""

    shape: str
    size: tuple[float, float, float]
    at: tuple[float, float, float] = (0.0, 0.0, 0.0)
    rpy: tuple[float, float, float] = (0.0, 0.0, 0.0)
    colour: str = "#808080"
    spin: bool = False


@dataclass(frozen=True)
class Look:
    """How pages draw it: primitives, or a glTF/GLB model (a file beside the robot file, scaled to
    the footprint), with the primitives as the fallback."""

    primitives: tuple[Primitive, ...] = ()
    model: str = ""  # absolute path, resolved when read


@dataclass(frozen=True)
class Flight:
    """An aerial robot's flight: at `cruise_height_m` above the floor once airborne."""

    cruise_height_m: float
    climb_rate_mps: float
    clearance_m: float  # flies over obstacles at least this much lower than itself
    # the gap it plans and passes people with (a person who walks up to it may come nearer; never under it)
    person_distance_m: float


@dataclass(frozen=True)
class DriveForce:
    """How hard the physics may push the body to follow its command (a simulation figure)."""

    max_force_n: float
    max_torque_nm: float


@dataclass(frozen=True)
class RobotDescription:
    name: str
    title: str
    kinematics: Kinematics
    footprint: Footprint
    height_m: float
    mass_kg: float
    limits: Limits
    motion: Motion
    battery: Battery
    lidar: Lidar
    cues: CueMounts
    drive: DriveForce
    frames: Frames = Frames()
    look: Look = Look()
    flight: Flight | None = None
    sources: Mapping[str, str] = field(default_factory=dict)  # figure -> where it comes from
    source_file: str = field(default="", compare=False)

    @property
    def radius_m(self) -> float:
        return self.footprint.circumradius_m

    @property
    def aerial(self) -> bool:
        return self.kinematics is Kinematics.AERIAL

    @property
    def holonomic(self) -> bool:
        return self.kinematics is not Kinematics.DIFF_DRIVE

    def body(self) -> BodySpec:
        """The body the physics simulates."""
        fp = self.footprint
        return BodySpec(
            fp.circumradius_m, self.height_m, self.mass_kg, self.drive.max_force_n, self.drive.max_torque_nm, fp.polygon
        )

    def contact_distance_m(self) -> float:
        """Centre-to-centre distance within which the robot may touch a person (the footprint's
        enclosing circle: exact for a round robot)."""
        return self.radius_m + HUMAN_BODY.radius_m

    def value_at(self, path: str) -> Any:
        """A figure by its dotted path (`limits.max_linear_speed_mps`, `radius_m`)."""
        value: Any = self
        for part in path.split("."):
            value = getattr(value, part)
        return value

    def key_figures(self) -> str:
        """One line for `haven robots`."""
        fp = self.footprint
        size = f"⌀{2 * fp.radius_m:.2f} m" if not fp.polygon else f"{_extent(fp.polygon, 0):.2f}×{fp.width_m:.2f} m"
        line = (
            f"{self.kinematics.value:<10} {size:<12} {self.height_m:.2f} m tall  {self.mass_kg:g} kg  "
            f"≤{self.limits.max_linear_speed_mps:g} m/s  cruise {self.motion.cruise_speed_mps:g} m/s  "
            f"lidar {self.lidar.range_max_m:g} m"
        )
        if self.flight is not None:
            line += f"  flies at {self.flight.cruise_height_m:g} m"
        return line


def _extent(polygon: tuple[Point, ...], axis: int) -> float:
    values = [p[axis] for p in polygon]
    return max(values) - min(values)
