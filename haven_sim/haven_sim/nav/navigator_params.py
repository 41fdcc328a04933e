"""The navigator's parameters: when and how the robot passes a person, and when it waits."""

from __future__ import annotations

from haven_sim.common.bodies import HUMAN_BODY
from haven_sim.common.params import NOT_NEGATIVE, Bounds, config, param
from haven_sim.robots.fields import Robot, from_robot

WAIT_MARGIN_M = 0.3  # a wide robot brakes this far beyond arm's length (it rests a little nearer)


@config
class NavigatorParams:
    pass_start_m: float = param(
        4.0,
        "start passing a person on the path this far ahead, along it (about "
        "the far edge of Hall's social zone, 3.6 m, plus the robot's reaction)",
        NOT_NEGATIVE,
    )
    pass_start_s: float = param(
        6.0,
        "... or this long before meeting them, for a person coming "
        "toward the robot (closing speed estimated from /humans)",
    )
    pass_clearance_m: float = param(
        0.3, "preferred gap between the robot's and the person's bodies when passing", NOT_NEGATIVE
    )
    min_pass_clearance_m: float = param(
        0.15, "passing needs at least this gap; otherwise the robot waits", NOT_NEGATIVE
    )
    pass_angle_deg: float = param(
        30.0, "heading change of the curve out to the passing line and back", Bounds(5.0, 60.0)
    )
    signal_lead_m: float = param(
        0.6, "straight driven before the curve so that the turn signal shows first", NOT_NEGATIVE
    )
    wait_gap_m: float = param(
        1.2,
        "a person who cannot be passed makes the robot brake this close "
        "ahead along the path (Hall's personal zone; it rests a little nearer)",
        NOT_NEGATIVE,
    )
    path_clearance_m: float = param(
        0.1, "a person within body radii + this of the upcoming path blocks it", NOT_NEGATIVE
    )
    diverge_m: float = param(0.15, "off the route by more than this, the robot is on a detour", NOT_NEGATIVE)
    goal_tolerance_m: float = param(0.1, "the goal counts as reached this close", NOT_NEGATIVE)
    use_goal_yaw: bool = param(True, "rotate to the goal's orientation at the end")
    robot: Robot = from_robot()  # an aerial robot keeps its flight's distance from people

    @property
    def person_distance_m(self) -> float:
        """The least gap the robot keeps from a person's body: its flight's (0 on the ground)."""
        flight = self.robot.flight
        return 0.0 if flight is None else flight.person_distance_m

    # The gaps the navigator works with: the parameters, the passing ones widened to the robot's
    # person distance. The "on the path" test keeps path_clearance_m: widened as well, a person
    # anywhere in a 2 m hallway is "on the path" of a drone keeping 0.8 m, and it waits for ever
    # (hallway, the catalogue quadrotor: every trial timed out).
    @property
    def pass_gap_m(self) -> float:
        return max(self.pass_clearance_m, self.person_distance_m)

    @property
    def min_pass_gap_m(self) -> float:
        return max(self.min_pass_clearance_m, self.person_distance_m)

    @property
    def path_gap_m(self) -> float:
        return self.path_clearance_m

    @property
    def wait_distance_m(self) -> float:
        """How far ahead of a person it cannot pass the robot brakes: `wait_gap_m`, or farther for a
        robot that keeps a wide distance (a drone): beyond the arm's length (bodies + pass_gap_m)
        within which the navigator does not re-plan round a person, else it would wait for ever."""
        return max(self.wait_gap_m, HUMAN_BODY.radius_m + self.robot.radius_m + self.pass_gap_m + WAIT_MARGIN_M)

        if self.min_pass_clearance_m > self.pass_clearance_m:
            raise ValueError("min_pass_clearance_m must not exceed pass_clearance_m")
