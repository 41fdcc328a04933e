"""Core types <-> ROS messages. The only place in haven_sim that builds or reads messages.

Every reader treats its message as untrusted (it may come from any node on the graph): a value
the core cannot use (a NaN or 1e308 coordinate, a map whose size disagrees with its data) raises
ValueError naming the field, which the nodes turn into a throttled warning.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np
from builtin_interfaces.msg import Duration, Time
from geometry_msgs.msg import Pose, PoseArray, PoseStamped, Quaternion, TransformStamped, Twist, TwistStamped
from nav_msgs.msg import OccupancyGrid, Odometry, Path
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import BatteryState, LaserScan
from std_msgs.msg import String

from haven_sim.common.events import Event
from haven_sim.common.geometry import MAX_WIRE_COORDINATE_M, Pose2D, Twist2D, checked_pose, stamp_parts, yaw_to_quaternion
from haven_sim.common.state import Goal, HumanPoses, RobotState, name_humans
from haven_sim.sim.battery import BatteryReading, PowerStatus, checked_percentage
from haven_sim.sim.frames import Frame
from haven_sim.sim.occupancy import OccupancyGridData
from haven_sim.sim.simulator import ScanData


def time_msg(t: float) -> Time:
    sec, nanosec = stamp_parts(t)
    return Time(sec=sec, nanosec=nanosec)


def duration_msg(seconds: float) -> Duration:
    """A span of time (never negative) as builtin_interfaces/Duration."""
    sec, nanosec = stamp_parts(max(0.0, seconds))
    return Duration(sec=sec, nanosec=nanosec)


MAX_MAP_CELLS = 100_000_000  # 5 km x 5 km at 0.5 m, or 500 m x 500 m at 5 cm


def _finite(value: float, name: str, bound: float = math.inf) -> float:
    if not math.isfinite(value) or abs(value) > bound:
        raise ValueError(f"{name} must be finite{'' if bound == math.inf else f' and within +-{bound:g}'}, got {value!r}")
    return float(value)


def time_from_msg(msg: Time) -> float:
    return msg.sec + msg.nanosec * 1e-9


def clock_msg(t: float) -> Clock:
    return Clock(clock=time_msg(t))


def quaternion_msg(yaw: float) -> Quaternion:
    """A NaN yaw ("any heading", e.g. of a goal) becomes the all-zero quaternion, and back."""
    if math.isnan(yaw):
        return Quaternion(x=0.0, y=0.0, z=0.0, w=0.0)
    x, y, z, w = yaw_to_quaternion(yaw)
    return Quaternion(x=x, y=y, z=z, w=w)


def pose_msg(p: Pose2D) -> Pose:
    msg = Pose()
    msg.position.x, msg.position.y = p.x, p.y
    msg.orientation = quaternion_msg(p.yaw)
    return msg


def pose_from_msg(msg: Pose) -> Pose2D:
    p, q = msg.position, msg.orientation
    return checked_pose(p.x, p.y, q.x, q.y, q.z, q.w)


def twist_from_msg(msg: Twist) -> Twist2D:
    """Non-finite values pass: the mux and the simulator refuse them (and say so) themselves."""
    return Twist2D(msg.linear.x, msg.linear.y, msg.angular.z)


def twist_msg(t: Twist2D) -> Twist:
    msg = Twist()
    msg.linear.x, msg.linear.y, msg.angular.z = t.vx, t.vy, t.wz
    return msg


def twist_stamped_msg(t: Twist2D, stamp: float, frame_id: str = "base_footprint") -> TwistStamped:
    """As Nav2 Jazzy stamps its velocity commands: the body frame and the command's time."""
    msg = TwistStamped()
    msg.header.stamp = time_msg(stamp)
    msg.header.frame_id = frame_id
    msg.twist = twist_msg(t)
    return msg


def odometry_msg(stamp: float, state: RobotState, frame_id: str = "odom", child_frame_id: str = "base_footprint") -> Odometry:
    msg = Odometry()
    msg.header.stamp = time_msg(stamp)
    msg.header.frame_id = frame_id
    msg.child_frame_id = child_frame_id
    msg.pose.pose = pose_msg(state.pose)
    msg.pose.pose.position.z = float(state.altitude_m)
    msg.twist.twist = twist_msg(state.twist)
    # Small fixed covariances (x, y, yaw) so consumers that require them (e.g. robot_localization) accept the message.
    cov = [0.0] * 36
    cov[0] = cov[7] = 1e-4
    cov[35] = 1e-3
    for c in (14, 21, 28):
        cov[c] = 1e6  # z, roll, pitch are not measured
    msg.pose.covariance = cov
    msg.twist.covariance = cov
    return msg


def odometry_from_msg(msg: Odometry) -> RobotState:
    return RobotState(pose_from_msg(msg.pose.pose), twist_from_msg(msg.twist.twist), msg.pose.pose.position.z)


def scan_msg(stamp: float, scan: ScanData, frame_id: str = "base_scan") -> LaserScan:
    msg = LaserScan()
    msg.header.stamp = time_msg(stamp)
    msg.header.frame_id = frame_id
    p = scan.params
    msg.angle_min = p.angle_min
    msg.angle_max = p.angle_max
    msg.angle_increment = p.angle_increment
    msg.time_increment = 0.0
    msg.scan_time = scan.period_s
    msg.range_min = p.range_min_m
    msg.range_max = p.range_max_m
    msg.ranges = np.asarray(scan.ranges, dtype=np.float32)
    return msg


_STATUS = {
    PowerStatus.CHARGING: BatteryState.POWER_SUPPLY_STATUS_CHARGING,
    PowerStatus.DISCHARGING: BatteryState.POWER_SUPPLY_STATUS_DISCHARGING,
    PowerStatus.FULL: BatteryState.POWER_SUPPLY_STATUS_FULL,
}


def battery_msg(stamp: float, r: BatteryReading, frame_id: str = "base_link") -> BatteryState:
    msg = BatteryState()
    msg.header.stamp = time_msg(stamp)
    msg.header.frame_id = frame_id
    msg.voltage = r.voltage_v
    msg.temperature = math.nan
    msg.current = math.nan
    msg.charge = r.charge_ah
    msg.capacity = r.capacity_ah
    msg.design_capacity = r.capacity_ah
    msg.percentage = r.level
    msg.power_supply_status = _STATUS[r.status]
    msg.power_supply_health = BatteryState.POWER_SUPPLY_HEALTH_GOOD
    msg.power_supply_technology = BatteryState.POWER_SUPPLY_TECHNOLOGY_LION
    msg.present = True
    return msg


def battery_from_msg(msg: BatteryState) -> BatteryReading:
    status = {v: k for k, v in _STATUS.items()}.get(msg.power_supply_status, PowerStatus.DISCHARGING)
    return BatteryReading(checked_percentage(msg.percentage), status, float(msg.voltage), float(msg.charge), float(msg.capacity), math.nan)


def humans_msg(stamp: float, poses: HumanPoses, frame_id: str = "map") -> PoseArray:
    """Humans in id order (the order of the world file's `humans`)."""
    msg = PoseArray()
    msg.header.stamp = time_msg(stamp)
    msg.header.frame_id = frame_id
    msg.poses = [pose_msg(p) for p in poses.values()]
    return msg


def occupancy_msg(stamp: float, grid: OccupancyGridData, frame_id: str = "map") -> OccupancyGrid:
    msg = OccupancyGrid()
    msg.header.stamp = time_msg(stamp)
    msg.header.frame_id = frame_id
    msg.info.map_load_time = time_msg(stamp)
    msg.info.resolution = grid.resolution_m
    msg.info.width = grid.width
    msg.info.height = grid.height
    msg.info.origin.position.x = grid.origin_x
    msg.info.origin.position.y = grid.origin_y
    msg.info.origin.orientation.w = 1.0
    msg.data = grid.data.reshape(-1).astype(np.int8).tolist()
    return msg


def occupancy_from_msg(msg: OccupancyGrid) -> OccupancyGridData:
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


def event_msg(event: Event) -> String:
    return String(data=event.to_json())


def event_from_msg(msg: String) -> Event:
    """Raises EventError (a ValueError) on anything that is not a valid event."""
    return Event.from_json(msg.data)


def pose_stamped_msg(stamp: float, pose: Pose2D, frame_id: str = "map") -> PoseStamped:
    msg = PoseStamped()
    msg.header.stamp = time_msg(stamp)
    msg.header.frame_id = frame_id
    msg.pose = pose_msg(pose)
    return msg


def pose_from_stamped(msg: PoseStamped) -> Pose2D:
    return pose_from_msg(msg.pose)


def goal_msg(stamp: float, goal: Goal) -> PoseStamped:
    return pose_stamped_msg(stamp, goal.pose, goal.frame)


def goal_from_msg(msg: PoseStamped) -> Goal:
    return Goal(pose_from_stamped(msg), msg.header.frame_id)


def path_msg(stamp: float, poses: Sequence[Pose2D], frame_id: str = "map") -> Path:
    msg = Path()
    msg.header.stamp = time_msg(stamp)
    msg.header.frame_id = frame_id
    for p in poses:
        ps = PoseStamped()
        ps.header = msg.header
        ps.pose = pose_msg(p)
        msg.poses.append(ps)
    return msg


def path_from_msg(msg: Path) -> list[Pose2D]:
    return [pose_from_msg(ps.pose) for ps in msg.poses]


def humans_from_msg(msg: PoseArray, ids: Sequence[str] = ()) -> HumanPoses:
    return name_humans([pose_from_msg(p) for p in msg.poses], ids)


def transform_msg(stamp: float, f: Frame) -> TransformStamped:
    msg = TransformStamped()
    msg.header.stamp = time_msg(stamp)
    msg.header.frame_id = f.parent
    msg.child_frame_id = f.child
    msg.transform.translation.x, msg.transform.translation.y, msg.transform.translation.z = f.x, f.y, f.z
    msg.transform.rotation = quaternion_msg(f.yaw)
    return msg


def tf_msg(stamp: float, frames: Sequence[Frame]) -> Any:
    """tf2_msgs/TFMessage (imported here: in the pip setup it exists only once built)."""
    from tf2_msgs.msg import TFMessage

    return TFMessage(transforms=[transform_msg(stamp, f) for f in frames])
