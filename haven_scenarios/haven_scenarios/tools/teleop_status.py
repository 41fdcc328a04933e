"""What a teleoperating participant is told in their terminal: their own progress and the end.

Read from the study log (/haven/events); one line per event that concerns them, None for the rest.
"""

from __future__ import annotations

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
