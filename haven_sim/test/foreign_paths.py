"""Paths shaped like Nav2's planners publish them, for tests: a straight, a 90 deg left arc of radius
0.6 m, a straight (the shape HAVEN drives as one arc), sampled as each planner samples it."""

from __future__ import annotations

import math

import numpy as np

from haven_sim.common.geometry import Pose2D
from haven_sim.nav.motion_style import MotionStyle

# read_path's style arguments, HAVEN's defaults
STYLE = (MotionStyle().arc_max_angle_rad, MotionStyle().facing_tolerance_rad)

RADIUS_M = 0.6
LEG_M = 2.0
ARC_START_M, ARC_END_M = LEG_M, LEG_M + RADIUS_M * math.pi / 2  # where the arc lies along the path
GOAL = Pose2D(LEG_M + RADIUS_M, RADIUS_M + LEG_M, math.pi / 2 + 1.5)  # a goal yaw 1.5 rad off the arrival heading


def _point(s: float) -> tuple[float, float, float]:
    """(x, y, tangent yaw) at arc length s."""
    if s <= ARC_START_M:
        return s, 0.0, 0.0
    if s <= ARC_END_M:
        t = (s - ARC_START_M) / RADIUS_M
        return LEG_M + RADIUS_M * math.sin(t), RADIUS_M - RADIUS_M * math.cos(t), t
    return LEG_M + RADIUS_M, RADIUS_M + (s - ARC_END_M), math.pi / 2


def arc_path(
    spacing_m: float = 0.05,
    orientation: str = "identity",
    yaw_jitter_deg: float = 0.0,
    seed: int = 0,
    origin=(0.0, 0.0),
) -> list[Pose2D]:
    """`orientation`: identity (NavFn: every pose but the last), tangent (Smac; with jitter).
    The last pose carries the goal yaw, as Nav2 planners give it."""
    rng = np.random.default_rng(seed)
    total = ARC_END_M + LEG_M
    out = []
    for s in np.append(np.arange(0.0, total, spacing_m), total):
        x, y, yaw = _point(float(s))
        if orientation == "identity":
            yaw = 0.0
        elif yaw_jitter_deg:
            yaw += math.radians(rng.normal(0.0, yaw_jitter_deg))
        out.append(Pose2D(x + origin[0], y + origin[1], yaw))
    out[-1] = Pose2D(out[-1].x, out[-1].y, GOAL.yaw)
    return out


def corner_path(turn_deg: float, spacing_m: float | None = 0.05, leg_m: float = 2.0) -> list[Pose2D]:
    """ThetaStar: two straight legs meeting at a sharp corner, identity orientations, densely
    interpolated (or only the corners when `spacing_m` is None)."""
    turn = math.radians(turn_deg)
    corner = (leg_m, 0.0)
    end = (leg_m + leg_m * math.cos(turn), leg_m * math.sin(turn))
    if spacing_m is None:
        points = [(0.0, 0.0), corner, end]
    else:
        n = round(leg_m / spacing_m)
        points = [(leg_m * k / n, 0.0) for k in range(n)] + [
            (corner[0] + (end[0] - corner[0]) * k / n, (end[1]) * k / n) for k in range(n + 1)
        ]
    return [Pose2D(x, y, 0.0) for x, y in points]
