"""Core types <-> ROS messages: the nodes' one place for them. It builds the messages here and
reads them with the shared decoder (`haven_sim.runtime.decode`, re-exported here), which the bag
reader uses too.
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
from haven_sim.common.geometry import Pose2D, Twist2D, stamp_parts, yaw_to_quaternion
from haven_sim.common.state import Goal, HumanPoses, RobotState
from haven_sim.runtime.decode import (  # (the readers, re-exported for the nodes)
    BATTERY_STATUS as BATTERY_STATUS,
    MAX_MAP_CELLS as MAX_MAP_CELLS,
    battery_from_msg as battery_from_msg,
    event_from_msg as event_from_msg,
    goal_from_msg as goal_from_msg,
    humans_from_msg as humans_from_msg,
    occupancy_from_msg as occupancy_from_msg,
    odometry_from_msg as odometry_from_msg,
    path_from_msg as path_from_msg,
    pose_from_msg as pose_from_msg,
    pose_from_stamped as pose_from_stamped,
    time_from_msg as time_from_msg,
    twist_from_msg as twist_from_msg,
)
from haven_sim.sim.battery import BatteryReading
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


def odometry_msg(
    stamp: float, state: RobotState, frame_id: str = "odom", child_frame_id: str = "base_footprint"
) -> Odometry:
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
    msg.power_supply_status = BATTERY_STATUS[r.status]
    msg.power_supply_health = BatteryState.POWER_SUPPLY_HEALTH_GOOD
    msg.power_supply_technology = BatteryState.POWER_SUPPLY_TECHNOLOGY_LION
    msg.present = True
    return msg


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


def event_msg(event: Event) -> String:
    return String(data=event.to_json())


def pose_stamped_msg(stamp: float, pose: Pose2D, frame_id: str = "map") -> PoseStamped:
    msg = PoseStamped()
    msg.header.stamp = time_msg(stamp)
    msg.header.frame_id = frame_id
    msg.pose = pose_msg(pose)
    return msg


def goal_msg(stamp: float, goal: Goal) -> PoseStamped:
    return pose_stamped_msg(stamp, goal.pose, goal.frame)


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
