"""ROS messages -> core types: the one decoder, for any object with a message's field names. The
nodes hand it rclpy's messages (`haven_sim.nodes.conversions` re-exports these readers beside its
writers), the bag reader rosbags' (`haven_scenarios.record.bag`); neither imports ROS here.

Every reader treats its message as untrusted (it may come from any node on the graph, or a bag from
anywhere): a value the core cannot use (a NaN or 1e308 coordinate, a map whose size disagrees with
its data) raises ValueError naming the field, which the nodes turn into a throttled warning and the
bag reader into a skipped message.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from haven_sim.common.events import Event
from haven_sim.common.geometry import MAX_WIRE_COORDINATE_M, Pose2D, Twist2D, checked_pose
from haven_sim.common.state import Goal, HumanPoses, RobotState, name_humans
from haven_sim.sim.battery import BatteryReading, PowerStatus, checked_percentage
from haven_sim.sim.occupancy import OccupancyGridData

MAX_MAP_CELLS = 100_000_000  # 5 km x 5 km at 0.5 m, or 500 m x 500 m at 5 cm

# sensor_msgs/msg/BatteryState.msg (Jazzy): POWER_SUPPLY_STATUS_CHARGING = 1, _DISCHARGING = 2,
# _FULL = 4 (0 unknown and 3 not charging are read as discharging).
BATTERY_STATUS = {PowerStatus.CHARGING: 1, PowerStatus.DISCHARGING: 2, PowerStatus.FULL: 4}
_STATUS_OF = {code: status for status, code in BATTERY_STATUS.items()}


def _finite(value: float, name: str, bound: float = math.inf) -> float:
    if not math.isfinite(value) or abs(value) > bound:
        raise ValueError(
            f"{name} must be finite{'' if bound == math.inf else f' and within +-{bound:g}'}, got {value!r}"
        )
    return float(value)


def time_from_msg(msg: Any) -> float:
    """builtin_interfaces/Time in seconds."""
    return float(msg.sec + msg.nanosec * 1e-9)


def stamp_of(msg: Any) -> float:
    """A stamped message's header time in seconds."""
    return time_from_msg(msg.header.stamp)


def pose_from_msg(msg: Any) -> Pose2D:
    p, q = msg.position, msg.orientation
    return checked_pose(p.x, p.y, q.x, q.y, q.z, q.w)


def twist_from_msg(msg: Any) -> Twist2D:
    """Non-finite values pass: the mux and the simulator refuse them (and say so) themselves."""
    return Twist2D(msg.linear.x, msg.linear.y, msg.angular.z)


def odometry_from_msg(msg: Any) -> RobotState:
    return RobotState(pose_from_msg(msg.pose.pose), twist_from_msg(msg.twist.twist), msg.pose.pose.position.z)


def battery_from_msg(msg: Any) -> BatteryReading:
    status = _STATUS_OF.get(msg.power_supply_status, PowerStatus.DISCHARGING)
    return BatteryReading(
        checked_percentage(msg.percentage), status, float(msg.voltage), float(msg.charge), float(msg.capacity), math.nan
    )


def humans_from_msg(msg: Any, ids: Sequence[str] = ()) -> HumanPoses:
    return name_humans([pose_from_msg(p) for p in msg.poses], ids)


def path_from_msg(msg: Any) -> list[Pose2D]:
    return [pose_from_msg(ps.pose) for ps in msg.poses]


def pose_from_stamped(msg: Any) -> Pose2D:
    return pose_from_msg(msg.pose)


def goal_from_msg(msg: Any) -> Goal:
    return Goal(pose_from_stamped(msg), str(msg.header.frame_id))


def event_from_msg(msg: Any) -> Event:
    """Raises EventError (a ValueError) on anything that is not a valid event."""
    return Event.from_json(msg.data)


def occupancy_from_msg(msg: Any) -> OccupancyGridData:
    info = msg.info
    if not (math.isfinite(info.resolution) and 1e-3 <= info.resolution <= 100.0):
        raise ValueError(f"resolution must be within 0.001..100 m, got {info.resolution!r}")
    if not 0 < info.width * info.height <= MAX_MAP_CELLS:
        raise ValueError(f"a map of {info.width} x {info.height} cells (at most {MAX_MAP_CELLS} and at least one)")
    if len(msg.data) != info.width * info.height:
        raise ValueError(f"{len(msg.data)} cells of data for a map of {info.width} x {info.height}")
    return OccupancyGridData(
        resolution_m=info.resolution,
        width=info.width,
        height=info.height,
        origin_x=_finite(info.origin.position.x, "origin.position.x", MAX_WIRE_COORDINATE_M),
        origin_y=_finite(info.origin.position.y, "origin.position.y", MAX_WIRE_COORDINATE_M),
        data=np.asarray(msg.data, dtype=np.int8).reshape(info.height, info.width),
    )
