"""Payloads of the state topics that several components share (the wire types' core twins)."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from haven_sim.common.geometry import Pose2D, Twist2D


@dataclass(frozen=True)
class RobotState:
    """What /odom says: the pose (odometry frame) and the body-frame velocity."""

    pose: Pose2D
    twist: Twist2D = Twist2D()
    altitude_m: float = 0.0  # base frame above the floor (pose.position.z): an aerial robot's height


@dataclass(frozen=True)
class Goal:
    """What /goal_pose says: a pose and the frame it is given in. A NaN yaw means any heading."""

    pose: Pose2D
    frame: str = "map"


HumanPoses = dict[str, Pose2D]  # /humans: every person's pose by id


def name_humans(poses: Sequence[Pose2D], ids: Sequence[str]) -> HumanPoses:
    """The one place that pairs /humans poses (world-file order) with their ids. With no ids known
    (another simulator's data) they are named by their index (h0, h1, ...); with ids known, a message
    of another length is not the simulator's (ValueError: the message is skipped)."""
    if ids and len(poses) != len(ids):
        raise ValueError(f"{len(poses)} poses for {len(ids)} people")
    return {(ids[i] if i < len(ids) else f"h{i}"): p for i, p in enumerate(poses)}
