from haven_scenarios.teleop.keys import KeyMapper
from haven_scenarios.teleop.status import announce, joined
from haven_sim.common.events import EventKind, event
from haven_sim.common.geometry import Twist2D


def test_held_keys_combine_and_release_after_the_auto_repeat_stops():
    k = KeyMapper(speed_mps=1.0, turn_rps=1.5, hold_s=0.35)
    assert k.command(0.0) == Twist2D()
    k.press("w", 0.0)
    k.press("q", 0.1)
    assert k.command(0.2) == Twist2D(1.0, 0.0, 1.5)
    k.press("w", 0.3)  # auto-repeat of w only
    assert k.command(0.5) == Twist2D(1.0, 0.0, 0.0)
    assert k.command(0.7) == Twist2D()
    k.press("a", 1.0)
    k.press("s", 1.0)
    assert k.command(1.1) == Twist2D(-1.0, 1.0, 0.0)
    k.press(" ", 1.2)
    assert k.command(1.2) == Twist2D()


def test_a_teleoperating_participant_is_told_their_progress_and_the_end():
    assert announce(event(EventKind.GEM_COLLECTED, 3.0, "rules", gem="hg2", by="h1"), "h1") == "gem hg2 collected"
    assert announce(event(EventKind.GEM_COLLECTED, 3.0, "rules", gem="hg3", by="h2"), "h1") is None  # someone else's
    assert (
        announce(event(EventKind.TASK_DONE, 9.0, "scenario", by="h1"), "h1")
        == "your task is done: wait for the trial to end"
    )
    assert (
        announce(event(EventKind.TRIAL_END, 9.5, "scenario", reason="completed"), "h1")
        == "trial over (completed): thank you"
    )


def test_a_late_teleop_client_is_told_where_the_trial_is():
    assert joined('{"state": "running", "humans": {}}') == ("the trial is running: go!", False)
    assert joined('{"state": "held"}') == ("waiting for the trial to start", False)
    assert joined('{"state": "ended", "end_reason": "completed"}') == ("trial over (completed): thank you", True)
    assert joined("not json") == (None, False)
