"""The example planner's path, without ROS: a turn toward the goal, then a straight line to it,
sampled as NavFn samples its paths (every 5 cm). It does not avoid obstacles: the example shows
the interface, not a planning method. (The node that publishes it: nodes/nav2_style_planner.py.)"""

from __future__ import annotations

import math

STEP_M = 0.05  # NavFn's pose spacing on a 5 cm map


def turn_then_straight(
    x: float, y: float, yaw: float, gx: float, gy: float, radius: float
) -> list[tuple[float, float]]:
    """Points every STEP_M from (x, y) heading `yaw`: an arc of `radius` toward the goal until
    facing it, then straight to (gx, gy)."""
    points = [(x, y)]
    for _ in range(int(2 * math.pi * radius / STEP_M) + 1):  # at most a full circle
        bearing = math.atan2(gy - y, gx - x)
        error = math.atan2(math.sin(bearing - yaw), math.cos(bearing - yaw))
        if abs(error) < STEP_M / radius or math.hypot(gx - x, gy - y) < radius:
            break
        yaw += math.copysign(STEP_M / radius, error)
        x, y = x + STEP_M * math.cos(yaw), y + STEP_M * math.sin(yaw)
        points.append((x, y))
    n = max(1, math.ceil(math.hypot(gx - x, gy - y) / STEP_M))
    points += [(x + (gx - x) * k / n, y + (gy - y) * k / n) for k in range(1, n + 1)]
    return points
