"""What a trip through the ROS messages does to payload values, applied in batch mode too.

A yaw travels as a quaternion, a battery level and a map resolution as 32-bit floats, an event as
JSON with its stamp rounded: small changes, but a decision at a threshold (a dwell timer, a planner's
cell count) can flip on them. Batch mode passes every message through the same transformation the
nodes' conversions apply (`haven_sim.nodes.conversions` is tested against it), so both modes compute
with identical numbers.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace
from typing import Any

import numpy as np

from haven_sim.common import topics
from haven_sim.common.events import Event
from haven_sim.common.geometry import Pose2D, quaternion_to_yaw, yaw_to_quaternion
from haven_sim.common.state import Goal, RobotState
from haven_sim.sim.battery import BatteryReading
from haven_sim.sim.occupancy import OccupancyGridData


def f32(value: float) -> float:
    return float(np.float32(value))


def wire_yaw(yaw: float) -> float:
    """A yaw through a geometry_msgs/Quaternion and back (NaN, "any heading", stays NaN)."""
    return math.nan if math.isnan(yaw) else quaternion_to_yaw(*yaw_to_quaternion(yaw))


def wire_pose(p: Pose2D) -> Pose2D:
    return Pose2D(p.x, p.y, wire_yaw(p.yaw))


def _battery(r: BatteryReading) -> BatteryReading:
    return replace(
        r, level=f32(r.level), voltage_v=f32(r.voltage_v), charge_ah=f32(r.charge_ah), capacity_ah=f32(r.capacity_ah)
    )


WIRE: dict[str, Callable[[Any], Any]] = {
    topics.ODOM: lambda s: RobotState(wire_pose(s.pose), s.twist, s.altitude_m),
    topics.HUMANS: lambda h: {hid: wire_pose(p) for hid, p in h.items()},
    topics.PLAN: lambda poses: [wire_pose(p) for p in poses],
    topics.GOAL: lambda g: Goal(wire_pose(g.pose), g.frame),
    topics.BATTERY: _battery,
    topics.MAP: lambda g: replace(g, resolution_m=f32(g.resolution_m)) if isinstance(g, OccupancyGridData) else g,
    topics.EVENTS: lambda e: Event.from_json(e.to_json()),
}


def on_the_wire(topic: str, data: Any) -> Any:
    """`data` as a subscriber of `topic` receives it."""
    convert = WIRE.get(topic)
    return data if convert is None else convert(data)
