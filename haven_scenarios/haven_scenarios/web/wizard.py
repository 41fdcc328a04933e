"""The researcher's interventions as study events (Wizard of Oz): every one is in the recording;
and the start gate: a held trial starts when every participant has pressed Start on their page.

Typing the thought bubble's text is one `intervention` event (action `thought`, with the text, how
long it is held over the robot's own thoughts and whether it shows at any distance);
driving the robot from the console is one event when it starts (`drive`) and one when the
console's commands come back to zero (`drive_end`); skipping the questionnaires after the trial is
one (`skip_questionnaires`). The velocity mux logs the switch of its source
(`cmd_source`) as well; these say that the researcher did it.
"""

from __future__ import annotations

import json

from haven_scenarios.record.answers import SKIP
from haven_sim.common.events import Event, EventKind, Source, event
from haven_sim.common.geometry import Twist2D
from haven_viz.wizard_thought import MAX_HOLD_S, WizardThought

BY = "researcher"
# Longest thought text the console may show: its `intervention` event must fit the study log's
# MAX_EVENT_BYTES (64 KiB), and 1000 characters are at most 12 KB of JSON however they are written
# (\\uXXXX escapes); a thought bubble shows a sentence.
MAX_THOUGHT_CHARS = 1000


DEFAULT_HOLD_S = 10.0  # the console's default: long enough to read a sentence twice


class Wizard:
    def __init__(self) -> None:
        self.driving = False

    def thought(self, sent: str, now: float) -> tuple[WizardThought, list[Event]]:
        """The console's {"text": ..., "hold_s": s, "everywhere": bool} as the viz's held thought and
        its event; ValueError in one line (naming the limit) for anything else: it is not shown."""
        try:
            data = json.loads(sent)
        except (json.JSONDecodeError, RecursionError):
            raise ValueError("thought: not JSON") from None
        text, hold, everywhere = (
            (data.get(k) for k in ("text", "hold_s", "everywhere")) if isinstance(data, dict) else (None, None, None)
        )
        if not isinstance(text, str):
            raise ValueError('thought: must be {"text": ..., "hold_s": seconds, "everywhere": true|false}')
        if len(text) > MAX_THOUGHT_CHARS:
            raise ValueError(
                f"thought text of {len(text)} characters refused: "
                f"at most {MAX_THOUGHT_CHARS} (the study log's events hold 64 KiB)"
            )
        hold = DEFAULT_HOLD_S if hold is None else hold
        if isinstance(hold, bool) or not isinstance(hold, (int, float)) or not 0 <= hold <= MAX_HOLD_S:
            raise ValueError(f"thought: hold_s must be 0..{MAX_HOLD_S:g} seconds, got {str(hold)[:40]}")
        everywhere = bool(everywhere)
        held = WizardThought(text, now + float(hold), everywhere)
        return held, [
            event(
                EventKind.INTERVENTION,
                now,
                Source.WEB,
                action="thought",
                text=text,
                hold_s=float(hold),
                everywhere=everywhere,
                by=BY,
            )
        ]

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
