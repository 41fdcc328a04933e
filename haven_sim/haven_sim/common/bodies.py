"""Body sizes of the TurtleBot2 and of a person: written once, used by the physics, the planner's
inflation, the navigator's "person on the path" test, the markers and the metrics."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class BodySpec:
    radius_m: float
    height_m: float
    mass_kg: float
    max_force_n: float  # how hard the physics may push the body to follow its command
    max_torque_nm: float


# Kobuki base with the TurtleBot2 stack: 0.354 m diameter, ~0.4 m tall with the stack, ~6.3 kg.
ROBOT_BODY = BodySpec(radius_m=0.177, height_m=0.4, mass_kg=6.3, max_force_n=40.0, max_torque_nm=10.0)
# A person seen from above: radius ~0.25 m, 1.7 m tall; strong enough to shove a TurtleBot2 aside.
HUMAN_BODY = BodySpec(radius_m=0.25, height_m=1.7, mass_kg=70.0, max_force_n=600.0, max_torque_nm=200.0)
# A participant's eyes (the first-person view) sit this high above the floor.
EYE_HEIGHT_M = 1.6


def contact_distance_m() -> float:
    """Centre-to-centre distance at which the robot and a person touch."""
    return ROBOT_BODY.radius_m + HUMAN_BODY.radius_m
