"""Metrics on synthetic logs with known answers."""

import math

import pytest

from haven_scenarios.record.log import TrialLog
from haven_scenarios.record.metrics import compute, signal_lead_times
from haven_sim.common.events import EventKind, Source, event


def straight_log(n=51, dt=0.1):
    """The robot drives along x at 1 m/s for 5 s; a person stands still at (2.5, 1.0)."""
    log = TrialLog()
    for i in range(n):
        t = i * dt
        log.sample(t, (t, 0.0, 0.0, 0.0), {"h1": (2.5, 1.0)}, 1.0 - 0.01 * t, bubble=t < 1.0, signal=0)
    log.events = [
        event(EventKind.TRIAL_START, 0.0, Source.SCENARIO),
        event(EventKind.WAITING, 1.0, Source.PLANNER, reason="x"),
        event(EventKind.RESUMED, 1.5, Source.PLANNER),
        event(EventKind.GEM_COLLECTED, 2.0, Source.SCENARIO, gem="g1", by="robot"),
        event(EventKind.GEM_COLLECTED, 3.0, Source.SCENARIO, gem="g2", by="h1"),
        event(EventKind.TASK_DONE, 4.0, Source.MISSION, by="robot"),
        event(EventKind.CONTACT_BEGIN, 4.5, Source.SIM, other="wall"),
    ]
    return log


def test_known_answers_on_a_straight_drive_past_a_person():
    m = compute(straight_log(), "synthetic", "completed")
    assert m["duration_s"] == 5.0 and m["robot_time_to_finish_s"] == 4.0
    assert m["robot_path_length_m"] == pytest.approx(5.0)
    assert m["min_human_distance_m"] == pytest.approx(1.0)  # passing abeam at x = 2.5
    assert m["h1_personal_intrusions"] == 1  # inside 1.2 m once: |x - 2.5| < sqrt(1.2^2 - 1)
    assert m["h1_personal_intrusion_s"] == pytest.approx(2 * math.sqrt(1.2**2 - 1.0), abs=0.11)
    assert m["h1_intimate_intrusion_s"] == 0.0
    assert (m["waits"], m["wait_time_s"]) == (1, 0.5)
    assert (m["gems_robot"], m["gems_human"], m["robot_gem_order"]) == (1, 1, "g1")
    assert (m["human_contacts"], m["wall_contacts"]) == (0, 1)
    assert m["battery_used"] == pytest.approx(0.05)
    assert m["thought_bubble_shown_s"] == pytest.approx(1.0)


def test_turn_signal_lead_is_how_long_the_matching_side_was_lit_before_the_turn():
    t = [0.1 * i for i in range(10)]
    wz = [0.0] * 5 + [0.8] * 5  # a left turn from t = 0.5
    signal = [0, 0, 1, 1, 1, 1, 1, 0, 0, 0]  # left lit from 0.2
    assert signal_lead_times(t, wz, signal) == [pytest.approx(0.3)]
    assert signal_lead_times(t, [-v for v in wz], signal) == [0.0]  # a right turn the signal did not announce
