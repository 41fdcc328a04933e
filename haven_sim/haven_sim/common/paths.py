"""The /plan path convention: rotate / arc / straight segments carried by nav_msgs/Path poses.

  * consecutive poses at one position with changing yaw: rotate in place;
  * yaw changing while moving: arc;
  * constant yaw while moving: straight.

`classify` reads any pose list back into those segments, so the controller and the AR cues treat a
swapped-in planner's path exactly like ours.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from enum import Enum

from haven_sim.common.geometry import Pose2D, wrap_angle


class SegmentKind(Enum):
    ROTATE = "rotate"
    ARC = "arc"
    STRAIGHT = "straight"


@dataclass(frozen=True)
class Segment:
    kind: SegmentKind
    start: int  # index of the first pose
    end: int  # index of the last pose (inclusive)


def classify(poses: Sequence[Pose2D], position_eps_m: float = 1e-3, yaw_eps_rad: float = math.radians(0.5)) -> list[Segment]:
    """Rotate / arc / straight segments of any pose list (ours or another planner's)."""
    kinds: list[SegmentKind | None] = []
    for a, q in zip(poses, poses[1:]):
        moved = math.hypot(q.x - a.x, q.y - a.y) > position_eps_m
        turned = abs(wrap_angle(q.yaw - a.yaw)) > yaw_eps_rad
        if not moved:
            kinds.append(SegmentKind.ROTATE if turned else None)
        else:
            kinds.append(SegmentKind.ARC if turned else SegmentKind.STRAIGHT)
    segments: list[Segment] = []
    for i, kind in enumerate(kinds):
        if kind is None:
            continue
        if segments and segments[-1].kind is kind and segments[-1].end == i:
            segments[-1] = Segment(kind, segments[-1].start, i + 1)
        else:
            segments.append(Segment(kind, i, i + 1))
    return segments
