"""HAVEN's turning rule, owned here and nowhere else: when the robot stops and rotates in place.

Before a leg (planning a corner, or finding itself facing away from the path while driving), the
robot rotates on the spot when the heading change exceeds `arc_max_angle_deg` (60 deg) or the leg
ahead is shorter than `too_close_distance_m`; otherwise it drives an arc. A rotation runs at
`rotate_speed_deg_s` (50 deg/s) until within `facing_tolerance_deg` (5 deg). The planner shapes its
paths with this rule and the controller follows them with it; both nodes take the same parameters
(the shared section of haven.yaml).
"""

from __future__ import annotations

import math

from haven_sim.common.params import NOT_NEGATIVE, POSITIVE, Bounds, config, param
from haven_sim.robots.fields import from_robot


@config
class MotionStyle:
    arc_max_angle_deg: float = param(
        60.0,
        "HAVEN: heading changes beyond this stop the robot and rotate it in place",
        Bounds(0.0, 180.0, low_open=True),
    )
    too_close_distance_m: float = param(
        0.5, "HAVEN: a leg shorter than this also starts with a rotation in place", NOT_NEGATIVE
    )
    facing_tolerance_deg: float = param(
        5.0, "HAVEN: a rotation in place ends within this", Bounds(0.0, 90.0, low_open=True, high_open=True)
    )
    rotate_speed_deg_s: float = param(50.0, "HAVEN's rate of rotating in place", POSITIVE)
    rotate_in_place: bool = from_robot("motion.rotate_in_place")  # a holonomic robot turns while it moves instead

    @property
    def arc_max_angle_rad(self) -> float:
        return math.radians(self.arc_max_angle_deg)

    @property
    def facing_tolerance_rad(self) -> float:
        return math.radians(self.facing_tolerance_deg)

    @property
    def rotate_speed_rps(self) -> float:
        return math.radians(self.rotate_speed_deg_s)

    def rotates_in_place(self, turn_rad: float, leg_m: float = math.inf) -> bool:
        """HAVEN's rule: rotate on the spot (True) or drive an arc (False) for this heading change
        before a leg of length `leg_m`."""
        return self.rotate_in_place and (abs(turn_rad) > self.arc_max_angle_rad or leg_m < self.too_close_distance_m)

    def facing(self, error_rad: float) -> bool:
        """A rotation in place is done."""
        return abs(error_rad) <= self.facing_tolerance_rad
