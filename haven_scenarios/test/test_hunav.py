"""HuNavSim's evaluator formulas (record/hunav.py) on hand-made samples with answers worked out from
its source (robotics-upo/hunav_sim@afa9743, hunav_evaluator/hunav_evaluator/hunav_metrics.py),
quirks included; our own variants beside them (wrapped heading changes, per-person standing)."""

import math

import numpy as np
import pytest
from test_metrics import drive, events, stand

from haven_scenarios.record import hunav
from haven_scenarios.record.hunav import Samples, columns, sample
from haven_scenarios.record.metric_kind import compute
from haven_scenarios.record.metric_table import HUNAV_METRICS, documented
from haven_scenarios.record.metrics import _heading_change
from haven_scenarios.record.timeline import Recording
from haven_sim.common import topics
from haven_sim.common.bodies import HUMAN_BODY
from haven_sim.common.component import Message
from haven_sim.common.events import EventKind, Source, event
from haven_sim.common.geometry import Pose2D, Twist2D
from haven_sim.common.state import RobotState
from haven_sim.robots.fields import DEFAULT as ROBOT_BODY

RADII = ROBOT_BODY.radius_m + HUMAN_BODY.radius_m


def samples(robot, people, dt=0.05):
    """Samples from rows (x, y, yaw, v, w) and {id: rows (x, y, yaw, v) or None for absent}."""
    n = len(robot)
    tracks = {
        h: np.array([r if r is not None else (math.nan,) * 4 for r in rows], dtype=float) for h, rows in people.items()
    }
    return Samples(dt * np.arange(n), np.array(robot, dtype=float), tracks)


def test_distances_are_between_surfaces_clamped_at_zero_and_the_maximum_subtracts_the_robot_only():
    # The robot stands at the origin; the person at 0.3 m (overlapping: surface -0.127), then 2.0 m.
    s = samples([(0, 0, 0, 0, 0)] * 2, {"h1": [(0.3, 0, 0, 0), (2.0, 0, 0, 0)]})
    m = columns(s)
    assert m["hunav_minimum_distance_to_people_m"] == 0.0
    assert m["hunav_avg_distance_to_closest_person_m"] == pytest.approx((0.0 + 2.0 - RADII) / 2, abs=1e-4)
    assert m["hunav_maximum_distance_to_people_m"] == pytest.approx(2.0 - ROBOT_BODY.radius_m, abs=1e-4)
    assert m["hunav_intimate_space_intrusions_pct"] == 50.0  # 0 (clamped) is in [0, 0.45)
    assert m["hunav_social_space_intrusions_pct"] == 50.0  # 2.0 - 0.427 = 1.573 in [1.2, 3.6)


def test_the_closest_person_averages_over_all_samples_including_those_without_anyone():
    s = samples(
        [(0, 0, 0, 0, 0)] * 4, {"h1": [(1.0, 0, 0, 0), None, None, None], "h2": [(3.0, 0, 0, 0), None, None, None]}
    )
    m = columns(s)
    assert m["hunav_avg_distance_to_closest_person_m"] == pytest.approx((1.0 - RADII) / 4, abs=1e-4)
    assert m["hunav_personal_space_intrusions_pct"] == 25.0  # 0.573 m: the other three samples are "public"


def test_heading_changes_wrap_across_pi_in_theirs_and_ours():
    yaws = [3.1, -3.1, 3.1]
    s = samples([(0, 0, y, 0, 0) for y in yaws], {})
    expected = 2 * (2 * math.pi - 6.2)
    assert columns(s)["hunav_cumulative_heading_changes_rad"] == pytest.approx(expected, abs=1e-4)
    assert _heading_change(np.array(yaws)) == pytest.approx(expected)
    assert hunav.normalize_angle(math.pi) == pytest.approx(math.pi) and hunav.normalize_angle(
        -math.pi
    ) == pytest.approx(math.pi)
    assert hunav.normalize_angle(5 * math.pi / 2) == pytest.approx(math.pi / 2)


def test_time_not_moving_compares_signed_velocities_as_published():
    # abs(r.angular_vel < 0.02): reversing and turning clockwise count as "not moving"; turning
    # counter-clockwise does not. 4 samples 0.05 s apart: total 0.15 s, 0.0375 s per sample.
    s = samples([(0, 0, 0, -0.5, 0), (0, 0, 0, 0, -1.0), (0, 0, 0, 0, 1.0), (0, 0, 0, 0.3, 0)], {})
    assert columns(s)["hunav_time_not_moving_s"] == pytest.approx(0.15 / 4 * 2)


def test_speeds_and_accelerations_divide_by_all_samples():
    s = samples([(0, 0, 0, 0.0, -0.2), (0, 0, 0, 0.1, 0.2), (0, 0, 0, 0.1, 0.2), (0, 0, 0, -0.1, 0.0)], {})
    m = columns(s)
    assert m["hunav_avg_robot_linear_speed_mps"] == pytest.approx(0.1 / 4)  # signed
    assert m["hunav_avg_robot_angular_speed_rps"] == pytest.approx(0.6 / 4)
    assert m["hunav_avg_acceleration_mps2"] == pytest.approx((2.0 + 0.0 + 4.0) / 4)  # |dv|/0.05
    assert m["hunav_avg_overacceleration"] == pytest.approx((2.0 + 0.0 + 4.0) / 0.05 / 4)  # |dv/dt|/dt, not a jerk


def test_collisions_are_counted_per_sample_and_attributed_by_the_published_rule():
    # The robot drives (0.5 m/s, yaw 0) into the back of a person 0.4 m ahead facing away, 3 samples:
    # alpha = atan2(0, -0.4) = pi, alpha2 = atan2(nrx=0.4, nry=0) = pi/2 (arguments as published),
    # |alpha| > |alpha2| and the robot faster: "person on robot", 3 times (one per sample).
    s = samples([(0, 0, 0, 0.5, 0)] * 3 + [(0, 0, 0, 0.5, 0)], {"h1": [(0.4, 0, 0, 0.0)] * 3 + [(2.0, 0, 0, 0.0)]})
    m = columns(s)
    assert (m["hunav_robot_on_person_collisions"], m["hunav_person_on_robot_collisions"]) == (0, 3)
    # The person walks (1 m/s) at the standing robot, facing it: alpha ~ 0 < alpha2 = pi/2, "robot on person".
    s = samples([(0, 0, 0, 0.0, 0)] * 2, {"h1": [(0.4, 0, math.pi, 1.0)] * 2})
    m = columns(s)
    assert (m["hunav_robot_on_person_collisions"], m["hunav_person_on_robot_collisions"]) == (2, 0)


def test_pedestrian_velocity_divides_by_the_people_of_the_first_sample():
    s = samples([(0, 0, 0, 0, 0)] * 2, {"h1": [(5, 0, 0, 1.0), (5, 0, 0, 1.0)], "h2": [(6, 0, 0, 0.5), None]})
    assert columns(s)["hunav_avg_pedestrian_velocity_mps"] == pytest.approx(2.5 / (2 * 2))


def test_sampling_holds_the_newest_messages_at_20_hz_from_trial_start_and_every_column_is_documented():
    rec = Recording()
    drive(rec, 0.0, 2.0)  # /odom at 50 Hz, x = t
    for i in range(0, 41):  # /humans at 20 Hz, 0.013 s late, walking at 0.5 m/s
        t = 0.013 + 0.05 * i
        rec.add(Message(topics.HUMANS, {"h1": Pose2D(5.0 - 0.5 * t, 1.0, math.pi)}, t))
    s = sample(rec, 0.02, 1.97)
    # Ticks 0.02, 0.07, ... 1.97 (40); the first has no /humans yet (first at 0.013: it has).
    assert len(s.t) == 40 and s.t[0] == 0.0 and s.t[-1] == pytest.approx(1.95)
    assert s.robot[1, 0] == pytest.approx(0.06)  # the /odom at 0.06 is the newest at 0.07
    assert s.people["h1"][1, 0] == pytest.approx(5.0 - 0.5 * 0.063)  # the /humans at 0.063
    assert s.people["h1"][1, 3] == pytest.approx(0.5)  # its speed from the message before
    late = sample(rec, -0.5, 1.0)  # ticks before either topic's first message are not samples
    assert late.t[0] == pytest.approx(0.55)  # the first tick after /humans' first message (0.013)
    m = columns(s)
    assert list(m) == [row[0] for row in HUNAV_METRICS] and all(documented(k, ["h1"]) for k in m)


def test_a_person_stands_only_until_their_own_task_is_done():
    rec = Recording()
    drive(rec, 0.0, 5.0)
    stand(rec, 0.0, 5.0, {"h1": (2.5, 3.0)})
    rec.add(Message(topics.ODOM, RobotState(Pose2D(5.0, 0.0, 0.0), Twist2D(0.0, 0.0, 0.0)), 5.0))
    finish = event(EventKind.TASK_DONE, 2.0, Source.MISSION, by="h1")
    events(
        rec,
        event(EventKind.TRIAL_START, 0.0, Source.SCENARIO),
        finish,
        event(EventKind.TRIAL_END, 5.0, Source.SCENARIO, reason="completed"),
    )
    assert compute(rec)["h1_time_not_moving_s"] == pytest.approx(2.0, abs=0.021)
    rec.events.remove(finish)  # no task_done: the trial's end
    assert compute(rec)["h1_time_not_moving_s"] == pytest.approx(5.0, abs=0.021)
