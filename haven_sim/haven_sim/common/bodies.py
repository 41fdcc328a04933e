"""Body sizes: a person's, written once, and the shape the physics gives any body (a robot's comes
from its robot file: `RobotDescription.body()`), used by the physics, the planner's inflation, the
navigator's "person on the path" test, the markers and the metrics."""

from __future__ import annotations

from dataclasses import dataclass

from haven_sim.common.geometry import Point


@dataclass(frozen=True)
class BodySpec:
    radius_m: float  # a circle, or the circle about the origin holding `polygon`
    height_m: float
    mass_kg: float
    max_force_n: float  # how hard the physics may push the body to follow its command
    max_torque_nm: float
    polygon: tuple[Point, ...] = ()  # a convex outline in the body frame, when not a circle


# A person seen from above: radius ~0.25 m, 1.7 m tall; strong enough to shove a TurtleBot2 aside.
HUMAN_BODY = BodySpec(radius_m=0.25, height_m=1.7, mass_kg=70.0, max_force_n=600.0, max_torque_nm=200.0)
# A participant's eyes (the first-person view) sit this high above the floor.
EYE_HEIGHT_M = 1.6
