"""The example planner's path on its own (no ROS): NavFn's 5 cm spacing, a turn toward the goal,
then straight to it; the suite reads it as an arc, then a straight."""

import math
import sys
from pathlib import Path

from haven_sim.common.geometry import Pose2D
from haven_sim.common.paths import SegmentKind, read_path
from haven_sim.nav.motion_style import MotionStyle

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "examples"))
import itertools

from nav2_style_path import STEP_M, turn_then_straight


def test_the_example_path_turns_toward_the_goal_then_runs_straight_to_it():
    points = turn_then_straight(1.0, 2.5, 0.0, 2.2, 4.2, 0.6)
    steps = [math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in itertools.pairwise(points)]
    assert points[-1] == (2.2, 4.2) and max(steps) <= STEP_M + 1e-9
    style = MotionStyle()
    reading = read_path([Pose2D(x, y, 0.0) for x, y in points], style.arc_max_angle_rad, style.facing_tolerance_rad)
    assert [s.kind for s in reading.segments][:2] == [SegmentKind.ARC, SegmentKind.STRAIGHT]
