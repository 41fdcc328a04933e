"""The robot's TF tree (REP-105), as plain data: map -> odom -> base_footprint -> base_link ->
base_scan, plus map -> human_<id> so a viewer can ride along with a participant."""

from __future__ import annotations

from collections.abc import Mapping
from typing import NamedTuple

from haven_sim.common.geometry import Pose2D


class Frame(NamedTuple):
    parent: str
    child: str
    x: float
    y: float
    z: float
    yaw: float


# TurtleBot2: base_link sits 1 cm above the floor; the laser (a stand-in for its depth camera's
# scan) about 0.35 m up, centred. map -> odom is the identity: odometry has no drift by default.
BASE_LINK_Z_M = 0.0102
SCAN_Z_M = 0.35


def static_frames(
    map_frame: str = "map", odom_frame: str = "odom", base_frame: str = "base_footprint", scan_frame: str = "base_scan", map_to_odom: bool = True
) -> list[Frame]:
    """The fixed frames; `map_to_odom` False leaves map -> odom to a localization node (AMCL, slam_toolbox)."""
    body = [Frame(base_frame, "base_link", 0.0, 0.0, BASE_LINK_Z_M, 0.0), Frame("base_link", scan_frame, 0.0, 0.0, SCAN_Z_M - BASE_LINK_Z_M, 0.0)]
    return ([Frame(map_frame, odom_frame, 0.0, 0.0, 0.0, 0.0)] if map_to_odom else []) + body


def robot_frame(odom_pose: Pose2D, odom_frame: str = "odom", base_frame: str = "base_footprint") -> Frame:
    return Frame(odom_frame, base_frame, odom_pose.x, odom_pose.y, 0.0, odom_pose.yaw)


def human_frames(humans: Mapping[str, Pose2D], map_frame: str = "map") -> list[Frame]:
    return [Frame(map_frame, f"human_{hid}", p.x, p.y, 0.0, p.yaw) for hid, p in humans.items()]
