"""Battery as range: a full charge is `capacity_m` metres of travel (HAVEN's 100 units ~ 100 m).

It drains per metre travelled, optionally per radian turned and per second of idling, and charges
at `charge_rate_per_s` (fraction of full per second) while the robot sits on the charging base.
The level never goes below 0, and at 0 the robot cannot drive. Voltage and charge are derived from
the level so the published sensor_msgs/BatteryState is self-consistent.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum

from haven_sim.common.params import FRACTION, NOT_NEGATIVE, POSITIVE, config, internal, param
from haven_sim.robots.fields import from_robot

# Kobuki 4S Li-ion pack: 2.2 Ah, 16.8 V full, 13.2 V empty (kobuki_node's thresholds).
DESIGN_CAPACITY_AH = 2.2
VOLTAGE_FULL_V = 16.8
VOLTAGE_EMPTY_V = 13.2


@config
class BatteryParams:
    # The robot's battery (robot file: battery; a scenario's robot.battery.capacity_m sets the pack):
    # metres of travel on a full charge, fractions of full per radian turned, per second switched on
    # (in the air, for an aerial robot) and per second on the base.
    capacity_m: float = from_robot("battery.capacity_m", POSITIVE)
    drain_per_rad: float = from_robot("battery.drain_per_rad", NOT_NEGATIVE)
    idle_drain_per_s: float = from_robot("battery.idle_drain_per_s", NOT_NEGATIVE)
    charge_rate_per_s: float = from_robot("battery.charge_rate_per_s", NOT_NEGATIVE)
    pack_m: float = param(
        0.0, "the pack as metres of travel (0: the robot's own; haven run sets the scenario's)", NOT_NEGATIVE
    )
    charge_max_speed_mps: float = param(0.02, "the robot charges only while (nearly) stopped on the base", NOT_NEGATIVE)
    initial_level: float = param(1.0, "level at start, 0..1", FRACTION)
    base_radius_m: float = internal(0.5, POSITIVE)  # from the world's charging base

    @property
    def full_range_m(self) -> float:
        """Metres of travel on a full charge: the pack, else the robot's capacity."""
        return self.pack_m or self.capacity_m


class PowerStatus(Enum):
    CHARGING = "charging"
    DISCHARGING = "discharging"
    FULL = "full"


@dataclass(frozen=True)
class BatteryReading:
    level: float  # 0..1
    status: PowerStatus
    voltage_v: float
    charge_ah: float
    capacity_ah: float
    range_m: float  # metres of travel left


class Battery:
    def __init__(self, params: BatteryParams | None = None) -> None:
        self.params = params or BatteryParams()
        self.level = self.params.initial_level
        self.charging = False

    def reset(self) -> None:
        self.level = self.params.initial_level
        self.charging = False

    @property
    def empty(self) -> bool:
        return self.level <= 0.0

    @property
    def range_m(self) -> float:
        return self.level * self.params.full_range_m

    def update(
        self,
        dt: float,
        distance_m: float,
        rotation_rad: float,
        speed_mps: float,
        distance_to_base_m: float,
        idle: bool = True,
    ) -> None:
        """Account for one step: what the robot did during dt and where it is now; `idle` False
        leaves out the idle drain (an aerial robot on the ground)."""
        p = self.params
        on_base = distance_to_base_m <= p.base_radius_m and speed_mps <= p.charge_max_speed_mps
        drain = (
            distance_m / p.full_range_m
            + abs(rotation_rad) * p.drain_per_rad
            + (dt * p.idle_drain_per_s if idle else 0.0)
        )
        self.charging = on_base and self.level < 1.0
        gain = p.charge_rate_per_s * dt if on_base else 0.0
        self.level = min(1.0, max(0.0, self.level - drain + gain))

    def reading(self) -> BatteryReading:
        if self.level >= 1.0:
            status = PowerStatus.FULL
        elif self.charging:
            status = PowerStatus.CHARGING
        else:
            status = PowerStatus.DISCHARGING
        return BatteryReading(
            level=self.level,
            status=status,
            voltage_v=VOLTAGE_EMPTY_V + self.level * (VOLTAGE_FULL_V - VOLTAGE_EMPTY_V),
            charge_ah=self.level * DESIGN_CAPACITY_AH,
            capacity_ah=DESIGN_CAPACITY_AH,
            range_m=self.range_m,
        )


def checked_percentage(value: float) -> float:
    """A BatteryState percentage read from a message or a bag: ValueError unless within 0..1 (NaN,
    "not measured", is no use to the mission or the metrics either)."""
    if not 0.0 <= value <= 1.0:
        raise ValueError(f"percentage must be within 0..1, got {value!r}")
    return float(value)
