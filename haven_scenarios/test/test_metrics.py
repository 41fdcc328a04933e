"""Metrics on synthetic recordings with known answers, one case per defect the outside evaluation
found (each failed with the index-paired, receive-stamped metrics of the first version)."""

import math
from dataclasses import replace

import numpy as np
import pytest

from haven_scenarios.record.metric_kind import compute
from haven_scenarios.record.metric_table import METRICS, documented, markdown
from haven_scenarios.record.metrics import signal_lead_times
from haven_scenarios.record.outsiders import Declared, PublisherLog, open_topics
from haven_scenarios.record.timeline import Recording
from haven_scenarios.record.validity import _stream
from haven_sim.common import topics
from haven_sim.common.component import Message
from haven_sim.common.events import Event, EventKind, Source, event
from haven_sim.common.geometry import Pose2D, Twist2D
from haven_sim.common.state import Goal, RobotState
from haven_viz.cues import CueState, Toggles

ALL = Toggles()


def drive(rec, t0, t1, x0=0.0, v=1.0, dt=0.02, y=0.0):
    """/odom every dt: the robot along x at speed v from x0 at t0."""
    n = round((t1 - t0) / dt)
    for i in range(n + 1):
        t = t0 + i * dt
        rec.add(Message(topics.ODOM, RobotState(Pose2D(x0 + v * (t - t0), y, 0.0), Twist2D(v, 0.0, 0.0)), t))


def stand(rec, t0, t1, poses, dt=0.05):
    """/humans every dt with fixed positions {id: (x, y)}."""
    n = round((t1 - t0) / dt)
    for i in range(n + 1):
        rec.add(Message(topics.HUMANS, {h: Pose2D(x, y, 0.0) for h, (x, y) in poses.items()}, t0 + i * dt))


def events(rec, *evs):
    for e in evs:
        rec.add(Message(topics.EVENTS, e, e.stamp))


def cue(rec, t, thought="", signal=0, toggles=ALL):
    rec.add(
        Message(
            topics.CUE_STATE,
            CueState(toggles, {"path_markers": 3, "turn_signal": signal, "thought": thought, "battery_level": 1.0}),
            t,
        )
    )


def straight():
    """The robot drives along x at 1 m/s for 5 s; a person stands at (2.5, 1.0)."""
    rec = Recording()
    drive(rec, 0.0, 5.0)
    stand(rec, 0.0, 5.0, {"h1": (2.5, 1.0)})
    cue(rec, 0.0, thought="gem g1")
    cue(rec, 1.0)
    events(
        rec,
        event(EventKind.TRIAL_START, 0.0, Source.SCENARIO),
        event(EventKind.WAITING, 1.0, Source.PLANNER, reason="x"),
        event(EventKind.RESUMED, 1.5, Source.PLANNER),
        event(EventKind.GEM_COLLECTED, 2.0, Source.SCENARIO, gem="g1", by="robot"),
        event(EventKind.GEM_COLLECTED, 3.0, Source.SCENARIO, gem="g2", by="h1"),
        event(EventKind.TASK_DONE, 4.0, Source.MISSION, by="robot"),
        event(EventKind.CONTACT_BEGIN, 4.5, Source.SIM, other="wall"),
        event(EventKind.CONTACT_END, 4.6, Source.SIM, other="wall"),
        event(EventKind.TRIAL_END, 5.0, Source.SCENARIO, reason="completed"),
    )
    return rec


def test_known_answers_on_a_straight_drive_past_a_person():
    m = compute(straight(), "synthetic", "completed")
    assert m["duration_s"] == 5.0 and m["robot_time_to_finish_s"] == 4.0
    assert m["robot_path_length_m"] == pytest.approx(5.0)
    assert m["min_human_centre_distance_m"] == pytest.approx(1.0)  # passing abeam at x = 2.5
    assert m["min_human_surface_distance_m"] == pytest.approx(1.0 - 0.177 - 0.25)
    assert m["h1_personal_centre_intrusions"] == 1  # inside 1.2 m once: |x - 2.5| < sqrt(1.2^2 - 1)
    assert m["h1_personal_centre_intrusion_s"] == pytest.approx(2 * math.sqrt(1.2**2 - 1.0), abs=0.03)
    assert m["h1_intimate_centre_intrusion_s"] == 0.0
    assert m["h1_personal_centre_band_s"] == m["h1_personal_centre_intrusion_s"]  # nothing nearer than 0.45 m
    assert m["h1_social_centre_band_s"] == pytest.approx(
        m["h1_social_centre_intrusion_s"] - m["h1_personal_centre_intrusion_s"], abs=0.011
    )
    assert (m["waits"], m["wait_time_s"]) == (1, 0.5)
    assert (m["gems_robot"], m["gems_human"], m["robot_gem_order"]) == (1, 1, "g1")
    assert (m["human_contacts"], m["wall_contacts"]) == (0, 1)
    assert m["thought_bubble_shown_s"] == pytest.approx(1.0)
    assert m["robot_speed_mean_mps"] == pytest.approx(1.0) and m["robot_time_not_moving_s"] == 0.0
    assert m["valid"] is True, m["invalid_reasons"]


def test_every_metric_is_in_the_table_and_the_table_in_the_readme():
    m = compute(straight(), "synthetic", "completed")
    undocumented = [k for k in m if not documented(k, ["h1"])]
    assert undocumented == []
    assert len({name for name, *_ in METRICS}) == len(METRICS)
    from pathlib import Path

    # The docs' codebook is this table, written by docs/conf.py at every build (one source).
    docs = Path(__file__).resolve().parents[2] / "docs"
    assert "_generated/metric_table.part.md" in (docs / "reference" / "sessions.md").read_text()
    assert "markdown(plugins=False)" in (docs / "conf.py").read_text() and markdown().startswith(
        "| metric | unit | definition | source |"
    )


def test_people_are_paired_with_the_robot_by_time_not_by_index():
    """Defect: robot[: len(h)] paired the n-th /odom with the n-th /humans message; /humans starts
    later (0.18 s) and comes at 20 Hz against 50 Hz, so the series were shifted in time."""
    rec = Recording()
    drive(rec, 0.0, 6.0)  # robot at x = t
    stand(rec, 0.18, 6.0, {"h1": (3.0, 0.6)})  # a person beside the track at x = 3
    events(
        rec,
        event(EventKind.TRIAL_START, 0.0, Source.SCENARIO),
        event(EventKind.TRIAL_END, 6.0, Source.SCENARIO, reason="completed"),
    )
    m = compute(rec)
    assert m["min_human_centre_distance_m"] == pytest.approx(0.6, abs=0.005)
    assert m["h1_min_centre_distance_m"] == pytest.approx(0.6, abs=0.005)


def test_people_moving_are_interpolated_between_their_samples():
    """A person walking toward the robot, sampled at 20 Hz with jittered stamps: the distance on the
    grid comes from interpolation at each grid time."""
    rec = Recording()
    for i in range(301):  # robot stands at the origin
        rec.add(Message(topics.ODOM, RobotState(Pose2D(0.0, 0.0, 0.0), Twist2D()), i * 0.02))
    for i in range(121):
        t = i * 0.05 + (0.013 if i % 3 == 1 else 0.0)
        rec.add(Message(topics.HUMANS, {"h1": Pose2D(5.0 - 0.5 * t, 0.0, math.pi)}, t))
    events(
        rec,
        event(EventKind.TRIAL_START, 0.0, Source.SCENARIO),
        event(EventKind.TRIAL_END, 6.0, Source.SCENARIO, reason="completed"),
    )
    m = compute(rec)
    assert m["min_human_centre_distance_m"] == pytest.approx(5.0 - 0.5 * 6.0, abs=0.01)


def test_nothing_after_trial_end_counts():
    """Defect: duration and every integral ran on 1.6-2.2 s past trial_end (the nodes were still up)."""
    rec = straight()
    drive(rec, 5.02, 7.0, x0=5.02)  # the robot keeps going after the end
    cue(rec, 5.5, thought="charging")
    m = compute(rec)
    assert m["duration_s"] == 5.0 and m["robot_path_length_m"] == pytest.approx(5.0)
    assert m["thought_bubble_shown_s"] == pytest.approx(1.0)


def test_contact_flicker_is_one_attributed_episode_per_person():
    """Defect: one 0.42 s touch counted 3 (raw contact_begin flicker), and not who hit whom. Here a
    person walks into the stopped robot: one episode, person on robot."""
    rec = Recording()
    for i in range(251):
        rec.add(Message(topics.ODOM, RobotState(Pose2D(0.0, 0.0, 0.0), Twist2D()), i * 0.02))
    for i in range(101):
        t = i * 0.05
        rec.add(
            Message(topics.HUMANS, {"h1": Pose2D(max(3.0 - t, 0.42), 0.0, math.pi), "h2": Pose2D(0.0, 3.0, 0.0)}, t)
        )
    flicker = [(2.58, 2.7), (2.75, 2.8), (2.86, 3.0)]
    for a, b in flicker:
        events(
            rec,
            event(EventKind.CONTACT_BEGIN, a, Source.SIM, other="human:h1"),
            event(EventKind.CONTACT_END, b, Source.SIM, other="human:h1"),
        )
    events(
        rec,
        event(EventKind.TRIAL_START, 0.0, Source.SCENARIO),
        event(EventKind.TRIAL_END, 5.0, Source.SCENARIO, reason="completed"),
    )
    m = compute(rec)
    assert (
        m["human_contacts"] == 1
        and m["human_contacts_person_on_robot"] == 1
        and m["human_contacts_robot_on_person"] == 0
    )
    assert (m["h1_contacts"], m["h2_contacts"]) == (1, 0)


def test_robot_driving_into_a_standing_person_is_robot_on_person():
    rec = Recording()
    drive(rec, 0.0, 3.0, v=0.5)
    stand(rec, 0.0, 3.0, {"h1": (1.4, 0.0)})
    events(
        rec,
        event(EventKind.TRIAL_START, 0.0, Source.SCENARIO),
        event(EventKind.CONTACT_BEGIN, 2.0, Source.SIM, other="human:h1"),
        event(EventKind.CONTACT_END, 2.3, Source.SIM, other="human:h1"),
        event(EventKind.TRIAL_END, 3.0, Source.SCENARIO, reason="contact"),
    )
    m = compute(rec)
    assert (m["human_contacts"], m["human_contacts_robot_on_person"]) == (1, 1)


def test_each_person_finishes_at_their_own_last_gem():
    """Defect: with 2+ humans every human got the time the shared pool emptied."""
    rec = Recording()
    drive(rec, 0.0, 20.0, v=0.0)
    stand(rec, 0.0, 20.0, {"h1": (2.0, 2.0), "h2": (4.0, 4.0)})
    gems = [("a", "h1", 3.0), ("b", "h2", 5.0), ("c", "h1", 6.0), ("d", "h2", 9.0), ("e", "h2", 12.0)]
    events(
        rec,
        event(EventKind.TRIAL_START, 0.0, Source.SCENARIO),
        *[event(EventKind.GEM_COLLECTED, t, Source.SCENARIO, gem=g, by=h) for g, h, t in gems],
        event(EventKind.TASK_DONE, 12.0, Source.SCENARIO, by="h1"),
        event(EventKind.TASK_DONE, 12.0, Source.SCENARIO, by="h2"),
        event(EventKind.TRIAL_END, 20.0, Source.SCENARIO, reason="completed"),
    )
    m = compute(rec)
    assert (m["h1_gems"], m["h2_gems"]) == (2, 3)
    assert (m["h1_time_to_finish_s"], m["h2_time_to_finish_s"]) == (6.0, 12.0)


def test_cue_exposure_comes_from_the_published_cue_state_per_condition_segment():
    """Defect: exposure was inferred from marker adds and deletes, and a lost delete left the bubble
    'shown' for the rest of the trial (83.7 s against 16.9 s). Now the viz node's cue state is the
    source, and a condition change mid-trial splits the exposure into segments."""
    rec = Recording()
    drive(rec, 0.0, 10.0, v=0.1)
    cue(rec, 0.0, thought="gem g1", signal=1)
    cue(rec, 2.0, thought="", signal=0)
    cue(rec, 4.0, thought="charging", toggles=Toggles(True, True, True, False))
    cue(rec, 7.0, thought="", toggles=Toggles(True, True, True, False))
    events(
        rec,
        event(EventKind.TRIAL_START, 0.0, Source.SCENARIO),
        event(EventKind.TRIAL_END, 10.0, Source.SCENARIO, reason="completed"),
    )
    m = compute(rec)
    assert m["thought_bubble_shown_s"] == pytest.approx(5.0)
    assert m["turn_signal_shown_s"] == pytest.approx(2.0)
    segments = m["condition_segments"]
    assert [(s["start_s"], s["end_s"]) for s in segments] == [(0.0, 3.98), (4.0, 10.0)]
    assert segments[0]["thought_bubble_shown_s"] == pytest.approx(2.0) and segments[1][
        "thought_bubble_shown_s"
    ] == pytest.approx(3.0)
    assert "battery_indicator" not in segments[1]["cues_on"]


def test_a_recording_with_lost_messages_is_flagged_not_valid():
    rec = straight()
    rec.odom = [s for s in rec.odom if not 2.0 <= s[0] <= 2.5]  # 0.5 s of /odom lost
    numbered, count = [], {}
    for e in sorted(rec.events, key=lambda e: e.stamp):
        count[e.source] = count.get(e.source, 0) + 1
        numbered.append(event(e.kind, e.stamp, e.source, **e.data, seq=count[e.source]))
    rec.events = [e for e in numbered if e.kind is not EventKind.WAITING]  # the planner's first event lost
    rec.lost = {"/battery_state": 2, "/clock": 40}  # as the recorder reported them
    m = compute(rec)
    assert m["valid"] is False
    assert any("/odom" in r and "gap" in r for r in m["invalid_reasons"])
    assert "events: 1 of planner's missing" in m["invalid_reasons"]
    assert "/battery_state: 2 message(s) lost before the recorder read them" in m["invalid_reasons"]
    assert not any("/clock" in r for r in m["invalid_reasons"])  # no metric reads /clock


def test_a_plan_or_a_goal_the_log_names_but_the_recording_lacks_is_flagged_and_pre_trial_gaps_are_not():
    rec = straight()
    plan = [Pose2D(0.0, 0.0, 0.0), Pose2D(5.0, 0.0, 0.0)]
    events(
        rec,
        event(EventKind.PLAN_MADE, 0.2, Source.PLANNER, plan_poses=2),
        event(EventKind.GOAL_SENT, 0.1, Source.SCENARIO, goal=[5.0, 0.0]),
    )
    rec.plans, rec.goals = [(0.2, plan)], [(0.1, Goal(Pose2D(5.0, 0.0, 0.0)))]
    assert compute(rec)["valid"] is True
    rec.plans, rec.goals = [], []
    m = compute(rec)
    assert "/plan: 1 of the planner's plans not recorded" in m["invalid_reasons"]
    assert "/goal_pose: 1 of the scenario's goals not recorded" in m["invalid_reasons"]
    # Events the scenario numbered before trial_start went missing (a storm outgrew the history a late
    # recorder catches up on): not the trial's. One missing inside the trial is.
    early = straight()
    mine = sorted((e for e in early.events if e.source == Source.SCENARIO), key=lambda e: e.stamp)
    early.events = [e for e in early.events if e.source != Source.SCENARIO] + [
        replace(e, data={**e.data, "seq": 30 + k}) for k, e in enumerate(mine)
    ]
    assert compute(early)["valid"] is True
    early.events = [e for e in early.events if e.kind is not EventKind.GEM_COLLECTED or e["gem"] != "g2"]
    assert any(r.startswith("events: ") and "scenario's missing" in r for r in compute(early)["invalid_reasons"])


def test_a_plugin_that_failed_makes_a_session_not_valid_by_one_rule_and_so_does_an_older_recordings_cue_failed():
    rec = straight()
    assert compute(rec)["valid"]
    events(
        rec,
        Event(
            EventKind.PLUGIN_FAILED,
            2.0,
            "scenario",
            {"kind": "participants", "name": "shy", "error": "ValueError: broke"},
        ),
    )
    assert compute(rec)["invalid_reasons"] == ["participant model shy failed (ValueError: broke)"]
    old = straight()
    events(old, event(EventKind.CUE_FAILED, 2.0, "viz", cue="floor_arrows", error="ValueError: broke"))
    assert compute(old)["invalid_reasons"] == ["cue floor_arrows failed (ValueError: broke)"]


def test_a_message_the_lockstep_clock_never_got_and_an_outside_publisher_make_a_session_not_valid():
    rec = straight()
    events(rec, event(EventKind.INPUT_LOST, 2.0, "controller", topic="/plan", messages=1))
    assert (
        "/plan: 1 of the suite's message(s) never reached controller on the lockstep clock"
        in compute(rec)["invalid_reasons"]
    )
    rec = straight()
    rec.publishers = PublisherLog()
    suite = {"/odom": "sim_node", "/goal_pose": "scenario", "/plan": "planner"}
    for topic, node in suite.items():
        rec.publishers.observe(topic, [(node, f"gid-{node}")], 0.0)
    rec.publishers.observe("/goal_pose", [("rviz", "gid-rviz")], 2.0)
    rec.publishers.observe("/odom", [("sim_node", "gid-second-suite")], 6.0)  # after the trial: not the trial's
    nodes = frozenset({"recorder", "sim_node", "velocity_mux", "planner", "controller", "viz", "scenario"})
    free = compute(rec, declared=Declared(nodes))
    assert free["valid"] is False and free["invalid_reasons"] == [
        "/goal_pose: published by rviz from outside the suite"
    ]
    lockstep = compute(rec, declared=Declared(nodes, lockstep=True))  # ignored there: noted, still valid
    assert lockstep["valid"] is True and lockstep["outside_publishers"].startswith("/goal_pose: published by rviz")
    opened = compute(rec, declared=Declared(nodes, open_topics(allow=["/goal_pose"])))
    assert opened["valid"] is True and opened["outside_publishers"].endswith(
        "from outside the suite, on a topic the run opened to it"
    )
    # a second suite's simulator during the trial
    rec.publishers.observe("/odom", [("sim_node", "gid-another-suite")], 3.0)
    m = compute(rec, declared=Declared(nodes, lockstep=True))
    assert m["valid"] is False and "another HAVEN suite on this ROS domain?" in m["invalid_reasons"][0]


def test_a_trial_without_trial_end_is_scored_to_the_last_sample_and_flagged():
    rec = straight()
    rec.events = [e for e in rec.events if e.kind is not EventKind.TRIAL_END]
    m = compute(rec, end_reason="interrupted")
    assert m["duration_s"] == 5.0 and m["valid"] is False and "no trial_end recorded" in m["invalid_reasons"]


def test_turn_signal_lead_is_how_long_the_matching_side_was_lit_before_the_turn():
    t = [0.1 * i for i in range(10)]
    wz = [0.0] * 5 + [0.8] * 5  # a left turn from t = 0.5
    signal = [0, 0, 1, 1, 1, 1, 1, 0, 0, 0]  # left lit from 0.2
    assert signal_lead_times(t, wz, signal) == [pytest.approx(0.3)]
    assert signal_lead_times(t, [-v for v in wz], signal) == [0.0]  # a right turn the signal did not announce


def test_a_stream_flooded_by_a_second_publisher_with_one_stamp_is_flagged_not_a_crash():
    """Another node's /odom at 1 kHz, every message stamped 0: the stamps repeat (no period to read)."""
    stamps = [0.02 * i for i in range(250)] + [0.0] * 10_000
    assert _stream("/odom", stamps, (0.0, 4.98)) == [
        "/odom: 10000 message(s) with the stamp of another (a second publisher?)"
    ]


def test_a_complete_20_hz_stream_on_50_hz_physics_is_complete_however_short():
    """Gaps of 0.06 and 0.04 s: a stream that ends on its short gap is not a lost message."""
    stamps = [0.1 * i + d for i in range(8) for d in (0.0, 0.06)][:-1]  # 0.0, 0.06, 0.1, ... 0.7
    assert _stream("/humans", stamps, (0.0, 0.7)) == []
    assert _stream("/humans", stamps[:5] + stamps[7:], (0.0, 0.7)) != []  # two missing


def test_a_stream_recorded_only_from_after_trial_start_is_not_complete():
    """The recorder subscribed late: every message from then on, but the start of the trial missing."""
    stamps = [0.02 * i for i in range(115, 950)]  # 2.3 s to 19 s, no gap
    assert _stream("/odom", stamps, (0.0, 19.0)) == ["/odom: recorded only from 2.30 s into the trial"]
    assert _stream("/odom", [0.02 * i for i in range(2, 950)], (0.0, 19.0)) == []  # (0.04 s late: within a step or two)


def test_a_metric_plugin_adds_its_columns_and_a_failing_one_says_why_in_its_own(monkeypatch):
    """Ours are plugins of kind `metrics` like a lab's (record/metrics.py); a lab's columns follow ours."""
    from fake_plugins import Entry

    from haven_sim.common import plugins

    def seconds_near(d):
        near = np.zeros(len(d.tl.t), dtype=bool)
        for xy in d.tl.humans.values():
            near |= np.hypot(*(xy - d.tl.robot_xy).T) < 2.0
        return {"seconds_within_2m": round(float(d.tl.dt[near].sum()), 2)}

    seconds_near.columns = [("seconds_within_2m", "s", "time a person was within 2 m of the robot", "a lab")]

    def broken(d):
        raise RuntimeError("no data\nmore")

    ours = [
        Entry(p.name, p.target, p.package, p.value.compute)
        for p in plugins.registry("metrics")
        if p.package == "haven_scenarios"
    ]
    lab = plugins.load(
        "metrics",
        [
            *ours,
            Entry("near", "lab.m:near", "lab_m", seconds_near),
            Entry("broken", "lab.m:broken", "lab_m", broken),
            Entry("thief", "lab.m:thief", "lab_m", lambda d: {"duration_s": 0}),
            Entry(
                "badcols", "lab.m:bad", "lab_m", type("M", (), {"columns": [("x",)], "__call__": lambda self, d: {}})()
            ),
        ],
    )
    assert lab.problems == [
        "haven.metrics badcols (lab.m:bad, from lab_m): columns: must be (name, unit, definition, source) rows of text"
    ]
    monkeypatch.setattr(plugins, "registry", lambda kind: lab)
    before = compute(straight(), "synthetic", "completed")
    only_ours = plugins.load("metrics", ours)
    monkeypatch.setattr(plugins, "registry", lambda kind: only_ours)
    alone = compute(straight(), "synthetic", "completed")
    keys = list(before)
    assert keys[: len(alone) - 3] == list(alone)[: len(alone) - 3]  # ours first, in our order (validity last)
    assert before["broken_error"] == "RuntimeError: no data" and before["thief_error"] == "would overwrite duration_s"
    # (the thief: its column only)
    assert before["valid"] is False and before["invalid_reasons"] == ["metric broken failed (RuntimeError: no data)"]
    assert before["seconds_within_2m"] >= 0 and before["duration_s"] == alone["duration_s"]
