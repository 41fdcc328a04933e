"""What a teleoperating participant is told in their terminal: their own progress and the end.

Read from the study log (/haven/events); one line per event that concerns them, None for the rest.
A client that starts late learns where the trial is from the latched /haven/trial_status.
"""

from __future__ import annotations

import json

from haven_scenarios.study.rules import TrialState
from haven_sim.common.events import Event, EventKind


def announce(e: Event, human: str) -> str | None:
    """The line to show `human` for event `e`, if it concerns them."""
    if e.kind is EventKind.TRIAL_START:
        return "trial started: go!"
    if e.kind is EventKind.TRIAL_END:
        return f"trial over ({e.get('reason', '?')}): thank you"
    if e.get("by") != human:
        return None
    if e.kind is EventKind.GEM_COLLECTED:
        return f"gem {e.get('gem')} collected"
    if e.kind is EventKind.ROOM_REACHED:
        return f"room {e.get('room')} reached"
    if e.kind is EventKind.DWELL_STARTED:
        return "standing in a gem: stay there"
    if e.kind is EventKind.DWELL_RESET:
        return "left the gem too early: go back and stand still"
    if e.kind is EventKind.TASK_DONE:
        return "your task is done: wait for the trial to end"
    return None


def joined(status_text: str) -> tuple[str | None, bool]:
    """What a client that joins now is told of the trial's status, and whether it is over."""
    try:
        status = json.loads(status_text)
        state = TrialState(status["state"])
    except (ValueError, KeyError, TypeError):
        return None, False
    if state is TrialState.RUNNING:
        return "the trial is running: go!", False
    if state is TrialState.ENDED:
        return f"trial over ({status.get('end_reason')}): thank you", True
    return "waiting for the trial to start", False
