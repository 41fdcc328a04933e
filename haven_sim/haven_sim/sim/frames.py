"""The robot's TF tree (REP-105), as plain data: map -> odom -> base_footprint -> base_link ->
base_scan, plus map -> human_<id> so a viewer can ride along with a participant."""

from __future__ import annotations

from collections.abc import Mapping
from typing import NamedTuple

from haven_sim.common.geometry import Pose2D
from haven_sim.robots.description import RobotDescription


class Frame(NamedTuple):
    parent: str
    child: str
    x: float
    y: float
    z: float
    yaw: float


def static_frames(
    robot: RobotDescription, map_frame: str = "map", odom_frame: str = "odom", map_to_odom: bool = True
) -> list[Frame]:
    """The fixed frames: the robot's base_link and laser where its robot file puts them (centred);
    map -> odom is the identity (odometry has no drift by default), unless `map_to_odom` is False,
    which leaves it to a localization node (AMCL, slam_toolbox)."""
    f, lidar = robot.frames, robot.lidar
    body = [
        Frame(f.base, f.base_link, 0.0, 0.0, f.base_link_height_m, 0.0),
        Frame(f.base_link, lidar.frame, 0.0, 0.0, lidar.height_m - f.base_link_height_m, 0.0),
    ]
    return ([Frame(map_frame, odom_frame, 0.0, 0.0, 0.0, 0.0)] if map_to_odom else []) + body


def robot_frame(
    odom_pose: Pose2D, odom_frame: str = "odom", base_frame: str = "base_footprint", altitude_m: float = 0.0
) -> Frame:
    """odom -> base_footprint; an aerial robot's base frame is `altitude_m` above the floor."""
    return Frame(odom_frame, base_frame, odom_pose.x, odom_pose.y, altitude_m, odom_pose.yaw)


def human_frames(humans: Mapping[str, Pose2D], map_frame: str = "map") -> list[Frame]:
    return [Frame(map_frame, f"human_{hid}", p.x, p.y, 0.0, p.yaw) for hid, p in humans.items()]
