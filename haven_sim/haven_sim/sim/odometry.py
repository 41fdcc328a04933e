"""Wheel odometry from the simulated motion, with optional drift noise (off by default).

Without noise the odometry pose equals the true pose, so `map -> odom` is the identity. With noise,
each step's body-frame increment is scaled by (1 + N(0, std)), which makes the estimate drift the way
wheel slip does.
"""

from __future__ import annotations

import math

import numpy as np

from haven_sim.common.geometry import Pose2D, wrap_angle
from haven_sim.common.params import NOT_NEGATIVE, config, param


@config
class OdometryNoise:
    linear: float = param(0.0, "relative std of each step's distance (wheel slip)", NOT_NEGATIVE)
    angular: float = param(0.0, "relative std of each step's rotation", NOT_NEGATIVE)


class Odometry:
    def __init__(self, start: Pose2D, noise: OdometryNoise | None = None, seed: int | None = None) -> None:
        self.noise = noise or OdometryNoise()
        self._rng = np.random.default_rng(seed)
        self.reset(start)

    def reset(self, start: Pose2D) -> None:
        self.pose = start
        self._last_true = start

    def update(self, true_pose: Pose2D) -> Pose2D:
        last = self._last_true
        self._last_true = true_pose
        if self.noise.linear == 0.0 and self.noise.angular == 0.0:
            self.pose = true_pose
            return self.pose
        c, s = math.cos(last.yaw), math.sin(last.yaw)
        gx, gy = true_pose.x - last.x, true_pose.y - last.y
        fx, fy = c * gx + s * gy, -s * gx + c * gy  # increment in the old body frame
        dth = wrap_angle(true_pose.yaw - last.yaw)
        k_lin = 1.0 + self._rng.normal(0.0, self.noise.linear) if self.noise.linear else 1.0
        k_ang = 1.0 + self._rng.normal(0.0, self.noise.angular) if self.noise.angular else 1.0
        fx, fy, dth = fx * k_lin, fy * k_lin, dth * k_ang
        p = self.pose
        c, s = math.cos(p.yaw), math.sin(p.yaw)
        self.pose = Pose2D(p.x + c * fx - s * fy, p.y + s * fx + c * fy, wrap_angle(p.yaw + dth))
        return self.pose
