"""The researcher's interventions as study events (Wizard of Oz): every one is in the recording;
and the start gate: a held trial starts when every participant has pressed Start on their page.

Typing the thought bubble's text is one `intervention` event (action `thought`, with the text);
driving the robot from the console is one event when it starts (`drive`) and one when the
console's commands come back to zero (`drive_end`); skipping the questionnaires after the trial is
one (`skip_questionnaires`). The velocity mux logs the switch of its source
(`cmd_source`) as well; these say that the researcher did it.
"""

from __future__ import annotations

from haven_scenarios.record.answers import SKIP
from haven_sim.common.events import Event, EventKind, Source, event
from haven_sim.common.geometry import Twist2D

BY = "researcher"
# Longest thought text the console may show: its `intervention` event must fit the study log's
# MAX_EVENT_BYTES (64 KiB), and 1000 characters are at most 12 KB of JSON however they are written
# (\\uXXXX escapes); a thought bubble shows a sentence.
MAX_THOUGHT_CHARS = 1000


class Wizard:
    def __init__(self) -> None:
        self.driving = False

    def thought(self, text: str, now: float) -> list[Event]:
        """ValueError (naming the limit) for a text longer than MAX_THOUGHT_CHARS: it is not shown."""
        if len(text) > MAX_THOUGHT_CHARS:
            raise ValueError(f"thought text of {len(text)} characters refused: at most {MAX_THOUGHT_CHARS} (the study log's events hold 64 KiB)")
        return [event(EventKind.INTERVENTION, now, Source.WEB, action="thought", text=text, by=BY)]

    def skip_questionnaires(self, now: float) -> list[Event]:
        """The researcher ends the wait for questionnaire answers (`haven run` stops then)."""
        return [event(EventKind.INTERVENTION, now, Source.WEB, action=SKIP, by=BY)]

    def drive(self, cmd: Twist2D, now: float) -> list[Event]:
        moving = any(abs(v) > 1e-6 for v in (cmd.vx, cmd.vy, cmd.wz))
        if moving == self.driving:
            return []
        self.driving = moving
        return [event(EventKind.INTERVENTION, now, Source.WEB, action="drive" if moving else "drive_end", by=BY)]


class StartGate:
    """Participants read the instructions, then press Start; the trial begins when all have (or
    when the researcher presses Start in the console, which is the only way with `researcher_only`)."""

    def __init__(self, participants: list[str], researcher_only: bool = False) -> None:
        self.waiting_for, self.researcher_only = set(participants), researcher_only
        self.opened = False

    def ready(self, who: str, now: float) -> tuple[list[Event], bool]:
        """The event that `who` is ready, and whether the trial should start now."""
        if who not in self.waiting_for:
            return [], False
        self.waiting_for.discard(who)
        start = not self.waiting_for and not self.researcher_only and not self.opened
        self.opened |= start
        return [event(EventKind.PARTICIPANT_READY, now, Source.WEB, by=who)], start
