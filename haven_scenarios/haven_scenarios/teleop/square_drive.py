"""A closed-loop square for `haven demo`: drive a leg, turn 90 degrees left, repeat.

The smallest useful example of driving the robot from another node through /cmd_vel_teleop (the
velocity mux gives teleop priority over navigation); the demo driver node wraps it.
"""

from __future__ import annotations

import math

from haven_sim.common.geometry import Pose2D, Twist2D, wrap_angle


class SquareDriver:
    def __init__(self, side_m: float = 1.5, laps: int = 1, speed_mps: float = 0.4, turn_rps: float = 1.0) -> None:
        if side_m <= 0 or laps < 1 or speed_mps <= 0 or turn_rps <= 0:
            raise ValueError("square needs side_m > 0, laps >= 1, speed_mps > 0 and turn_rps > 0")
        self.side_m, self.speed_mps, self.turn_rps = side_m, speed_mps, turn_rps
        self.legs_total = 4 * laps
        self.legs_done = 0
        self._leg_start: Pose2D | None = None
        self._turn_goal: float | None = None
        self._heading: float | None = None  # the ideal heading of the current leg
        self.distance_m = 0.0
        self._last: Pose2D | None = None

    @property
    def done(self) -> bool:
        return self.legs_done >= self.legs_total

    def command(self, pose: Pose2D) -> Twist2D:
        """Velocity for the current pose; zero once every leg is driven."""
        if self._last is not None:
            self.distance_m += pose.distance_to(self._last)
        self._last = pose
        if self.done:
            return Twist2D()
        if self._turn_goal is not None:
            err = wrap_angle(self._turn_goal - pose.yaw)
            if abs(err) < math.radians(1.0):
                self._heading = self._turn_goal
                self._turn_goal = None
                self._leg_start = pose
            else:
                return Twist2D(0.0, 0.0, math.copysign(min(self.turn_rps, 2.0 * abs(err) + 0.1), err))
        if self._leg_start is None:
            self._leg_start = pose
        if self._heading is None:
            self._heading = pose.yaw
        left = self.side_m - pose.distance_to(self._leg_start)
        if left <= 0.01:
            self.legs_done += 1
            self._turn_goal = wrap_angle(self._heading + math.pi / 2.0)
            self._leg_start = None
            return Twist2D()
        heading_err = wrap_angle(self._heading - pose.yaw)
        # Slow down in time for the 0.5 m/s^2 deceleration of the TurtleBot2.
        speed = min(self.speed_mps, math.sqrt(2.0 * 0.4 * left) + 0.02)
        return Twist2D(speed, 0.0, 2.0 * heading_err)
