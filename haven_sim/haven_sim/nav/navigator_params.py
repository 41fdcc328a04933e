"""The navigator's parameters: when and how the robot passes a person, and when it waits."""

from __future__ import annotations

from dataclasses import dataclass

from haven_sim.common.params import param


@dataclass(frozen=True)
class NavigatorParams:
    pass_start_m: float = param(
        4.0,
        "start passing a person on the path this far ahead, along it (about the far edge of Hall's social zone, 3.6 m, plus the robot's reaction)",
    )
    pass_start_s: float = param(
        6.0, "... or this long before meeting them, for a person coming toward the robot (closing speed estimated from /humans)"
    )
    pass_clearance_m: float = param(0.3, "preferred gap between the robot's and the person's bodies when passing")
    min_pass_clearance_m: float = param(0.15, "passing needs at least this gap; otherwise the robot waits")
    pass_angle_deg: float = param(30.0, "heading change of the curve out to the passing line and back")
    signal_lead_m: float = param(0.6, "straight driven before the curve so that the turn signal shows first")
    wait_gap_m: float = param(
        1.2, "a person who cannot be passed makes the robot brake this close ahead along the path (Hall's personal zone; it rests a little nearer)"
    )
    path_clearance_m: float = param(0.1, "a person within body radii + this of the upcoming path blocks it")
    diverge_m: float = param(0.15, "off the route by more than this, the robot is on a detour")
    goal_tolerance_m: float = param(0.1, "the goal counts as reached this close")
    use_goal_yaw: bool = param(True, "rotate to the goal's orientation at the end")

    def __post_init__(self) -> None:
        for name in (
            "pass_start_m",
            "pass_clearance_m",
            "min_pass_clearance_m",
            "signal_lead_m",
            "wait_gap_m",
            "path_clearance_m",
            "diverge_m",
            "goal_tolerance_m",
        ):
            if getattr(self, name) < 0:
                raise ValueError(f"{name} must not be negative, got {getattr(self, name)}")
        if not 5.0 <= self.pass_angle_deg <= 60.0:
            raise ValueError(f"pass_angle_deg must be within [5, 60] (beyond 60 the robot rotates in place), got {self.pass_angle_deg}")
        if self.min_pass_clearance_m > self.pass_clearance_m:
            raise ValueError("min_pass_clearance_m must not exceed pass_clearance_m")
