"""Who is on the pages and what a drop-out does (study/presence.py), the simulator's pausable wall
clock (sim/pacer.py), and a drop-out in the session's validity (record/validity.py)."""

from __future__ import annotations

import json

from haven_scenarios.study.presence import MAX_AWAY_S, Act, Attendance, OnDisconnect
from haven_sim.common.events import EventKind
from haven_sim.sim.pacer import Pacer, WallClock


def kinds(result):
    events, acts = result
    return [e.kind for e in events], acts


def test_a_participant_who_leaves_and_comes_back_is_logged_with_how_long_they_were_away():
    a = Attendance(["h1", "h2"])
    assert kinds(a.opened("h1", 0.0, 0.0)) == ([], [])  # first arrival: not a reconnection
    assert kinds(a.opened("h1", 1.0, 1.0)) == ([], [])  # a second tab of the same page
    assert kinds(a.closed("h1", 2.0, 2.0, running=True)) == ([], [])  # one tab still open
    events, acts = a.closed("h1", 3.0, 3.0, running=True)
    assert (
        [e.kind for e in events] == [EventKind.PARTICIPANT_DISCONNECTED]
        and events[0]["policy"] == "keep"
        and acts == []
    )
    assert (
        a.table(10.0)["participants"]["h1"]["state"] == "away" and a.table(10.0)["participants"]["h1"]["away_s"] == 7.0
    )
    assert a.table(10.0)["participants"]["h2"]["state"] == "not yet"
    events, _ = a.opened("h1", 10.5, 4.0)
    assert [e.kind for e in events] == [EventKind.PARTICIPANT_RECONNECTED] and events[0]["away_s"] == 7.5
    assert kinds(a.closed("nobody", 11.0, 5.0, running=True)) == ([], [])


def test_pause_stands_the_trial_still_until_everyone_is_back_and_aborts_after_the_timeout():
    a = Attendance(["h1", "h2"], OnDisconnect.PAUSE, reconnect_timeout_s=30.0)
    for who in ("h1", "h2"):
        a.opened(who, 0.0, 0.0)
    # not running: no policy
    assert kinds(a.closed("h1", 1.0, 1.0, running=False)) == ([EventKind.PARTICIPANT_DISCONNECTED], [])
    a.opened("h1", 2.0, 2.0)
    assert kinds(a.closed("h1", 3.0, 3.0, running=True)) == ([EventKind.PARTICIPANT_DISCONNECTED], [Act.PAUSE])
    assert kinds(a.closed("h2", 4.0, 3.0, running=True)) == ([EventKind.PARTICIPANT_DISCONNECTED], [])  # already paused
    assert kinds(a.opened("h1", 5.0, 3.0)) == ([EventKind.PARTICIPANT_RECONNECTED], [])  # h2 still away
    assert a.table(5.0)["paused"] is True
    assert kinds(a.tick(33.0, 3.0, running=True)) == ([], [])  # h2 away 29 s
    events, acts = a.tick(34.0, 3.0, running=True)
    assert (
        [e.kind for e in events] == [EventKind.PARTICIPANT_LOST]
        and events[0]["by"] == "h2"
        and events[0]["away_s"] == 30.0
    )
    assert acts == [Act.RESUME, Act.ABORT] and not a.paused
    b = Attendance(["h1"], OnDisconnect.PAUSE)
    b.opened("h1", 0.0, 0.0)
    b.closed("h1", 1.0, 1.0, running=True)
    assert kinds(b.opened("h1", 2.0, 1.0)) == ([EventKind.PARTICIPANT_RECONNECTED], [Act.RESUME])
    b.closed("h1", 3.0, 1.0, running=True)
    assert b.release() == [Act.RESUME] and b.release() == []  # the researcher ends a paused trial


def test_abort_calls_the_trial_off_at_once():
    a = Attendance(["h1"], OnDisconnect.ABORT)
    a.opened("h1", 0.0, 0.0)
    assert kinds(a.closed("h1", 1.0, 1.0, running=True)) == ([EventKind.PARTICIPANT_DISCONNECTED], [Act.ABORT])


def test_page_reports_are_checked_and_shown():
    a = Attendance(["h1"])
    a.opened("h1", 0.0, 0.0)
    assert a.report("h1", json.dumps({"fps": 4.66, "latency_ms": 87, "input_age_s": None}), 1.0) is None
    row = a.table(3.0)["participants"]["h1"]
    assert (row["fps"], row["latency_ms"], row["input_age_s"], row["report_age_s"]) == (4.7, 87.0, None, 2.0)
    assert a.report("h2", "{}", 1.0) == "h2 is not a participant of this trial"
    assert a.report("h1", "not json", 1.0) == "a page report that is not JSON"
    assert a.report("h1", "[]", 1.0) == "a page report that is not a JSON object"
    assert a.report("h1", '{"fps": -1}', 1.0) == "a page report with a value that is not a number >= 0"
    assert a.report("h1", '{"fps": true}', 1.0) == "a page report with a value that is not a number >= 0"
    assert "at most 512" in (a.report("h1", json.dumps({"x": "y" * 600}), 1.0) or "")
    a.closed("h1", 4.0, 4.0, running=True)
    assert a.table(5.0)["participants"]["h1"]["fps"] is None  # away: nothing its page said counts as now


def test_a_paused_wall_clock_stands_still_and_pacing_does_not_catch_up_after():
    t = [100.0]
    clock = WallClock(lambda: t[0])
    pacer = Pacer(0.02, 1.0)
    assert pacer.due_steps(clock.now()) == 0
    t[0] += 0.1
    assert pacer.due_steps(clock.now()) == 5
    assert clock.pause() and not clock.pause()
    t[0] += 30.0
    assert pacer.due_steps(clock.now()) == 0  # no step while paused
    assert clock.resume() == 30.0 and clock.resume() is None
    t[0] += 0.1
    assert pacer.due_steps(clock.now()) == 5  # and no burst after: the pause is taken out


def test_a_participant_away_longer_than_the_limit_makes_the_session_not_valid():
    from haven_scenarios.record.timeline import Recording
    from haven_scenarios.record.validity import _away
    from haven_sim.common.events import Source, event

    def rec(*events):
        return Recording(events=list(events))

    short = rec(
        event(EventKind.PARTICIPANT_DISCONNECTED, 10.0, Source.WEB, by="h1", policy="keep"),
        event(EventKind.PARTICIPANT_RECONNECTED, 12.0, Source.WEB, by="h1", away_s=2.0),
    )
    assert _away(short, (5.0, 60.0)) == []  # a reload
    long = rec(
        event(EventKind.PARTICIPANT_DISCONNECTED, 10.0, Source.WEB, by="h1", policy="keep"),
        event(EventKind.PARTICIPANT_RECONNECTED, 24.0, Source.WEB, by="h1", away_s=MAX_AWAY_S + 4),
    )
    assert _away(long, (5.0, 60.0)) == [
        f"participant h1: away {MAX_AWAY_S + 4:g} s from 5.0 s into the trial (its page disconnected)"
    ]
    paused = rec(
        event(EventKind.PARTICIPANT_DISCONNECTED, 10.0, Source.WEB, by="h1", policy="pause"),
        event(EventKind.PARTICIPANT_RECONNECTED, 10.0, Source.WEB, by="h1", away_s=MAX_AWAY_S + 4),
    )
    assert _away(paused, (5.0, 60.0)) == []  # the trial stood still while they were away
    gone = rec(event(EventKind.PARTICIPANT_DISCONNECTED, 40.0, Source.WEB, by="h2", policy="keep"))
    assert _away(gone, (5.0, 60.0)) == [
        "participant h2: away from 35.0 s into the trial to its end (its page disconnected)"
    ]
    before = rec(event(EventKind.PARTICIPANT_DISCONNECTED, 1.0, Source.WEB, by="h2", policy="keep"))
    assert _away(before, (5.0, 60.0)) == []  # before the trial began
