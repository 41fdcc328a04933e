"""Who is on the study's pages, and what a participant's drop-out during a trial does.

The front door sees each page's WebSocket open and close (a closed tab, a lost network, a reload);
each participant page reports every 2 s what the researcher checks a slow machine by (its frame
rate, its latest key-to-pose latency: a key pressed to the moved view drawn, and how long since its
last key or stick input). `Attendance`
turns that into the study log's `participant_disconnected` / `participant_reconnected` /
`participant_lost` events, the console's table (`/haven/participants`), and the study's policy for
a drop-out while the trial runs:
- `keep`: the trial goes on without them (the robot and the others do not wait);
- `pause`: simulated time stands still until every participant is back; after `reconnect_timeout_s`
  away the participant is lost and the trial aborted;
- `abort`: the trial is called off at once.
Durations are wall time (a paused trial's simulated time stands still). No ROS here: the web node
acts on what it returns.
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from dataclasses import dataclass, field
from enum import StrEnum
from typing import Any

from haven_sim.common.events import Event, EventKind, Source, event


class OnDisconnect(StrEnum):
    KEEP = "keep"
    PAUSE = "pause"
    ABORT = "abort"


REPORTED = ("fps", "latency_ms", "input_age_s")  # frame rate, key-to-pose latency, time since the last input
# A participant away longer than this while the trial ran on without them (`keep`) missed part of
# it: the session is not valid (record/validity.py). Long enough for a page reload on a loaded
# machine (test_web_dropout.py measures one), short against a trial's minutes.
MAX_AWAY_S = 10.0
DEFAULT_RECONNECT_TIMEOUT_S = 60.0  # with `pause`: how long a trial waits for a participant to come back
MAX_REPORT_BYTES = 512


class Act(StrEnum):
    """What the web node must do besides logging the events."""

    PAUSE = "pause"
    RESUME = "resume"
    ABORT = "abort"


@dataclass
class Presence:
    """One participant's connection as the door and their page tell it."""

    sockets: int = 0  # their page's open WebSockets (two tabs of one page count as one presence)
    seen: bool = False  # connected at least once
    away_since: float | None = None  # wall time they left (None: here, or never came)
    report: dict[str, float | None] = field(default_factory=dict)  # their page's last (REPORTED)
    reported_at: float | None = None  # wall time of it


@dataclass
class Attendance:
    participants: Sequence[str]
    on_disconnect: OnDisconnect = OnDisconnect.KEEP
    reconnect_timeout_s: float = DEFAULT_RECONNECT_TIMEOUT_S
    people: dict[str, Presence] = field(default_factory=dict)
    paused: bool = False

    def __post_init__(self) -> None:
        self.people = {p: Presence() for p in self.participants}

    def opened(self, who: str, wall: float, sim_now: float) -> tuple[list[Event], list[Act]]:
        """A page's socket opened: a participant back after a drop-out is `participant_reconnected`
        (with how long they were away); the last one back ends a pause."""
        p = self.people.get(who)
        if p is None:
            return [], []
        p.sockets += 1
        if p.sockets > 1 or not p.seen:
            p.seen = True
            return [], []
        away = wall - p.away_since if p.away_since is not None else 0.0
        p.away_since = None
        events = [event(EventKind.PARTICIPANT_RECONNECTED, sim_now, Source.WEB, by=who, away_s=round(away, 2))]
        if self.paused and not self.away():
            self.paused = False
            return events, [Act.RESUME]
        return events, []

    def closed(self, who: str, wall: float, sim_now: float, running: bool) -> tuple[list[Event], list[Act]]:
        """A page's socket closed; with no other open, the participant is away: the policy acts if
        the trial is running."""
        p = self.people.get(who)
        if p is None or p.sockets == 0:
            return [], []
        p.sockets -= 1
        if p.sockets:
            return [], []
        p.away_since = wall
        events = [
            event(EventKind.PARTICIPANT_DISCONNECTED, sim_now, Source.WEB, by=who, policy=str(self.on_disconnect))
        ]
        if not running:
            return events, []
        if self.on_disconnect is OnDisconnect.ABORT:
            return events, [Act.ABORT]
        if self.on_disconnect is OnDisconnect.PAUSE and not self.paused:
            self.paused = True
            return events, [Act.PAUSE]
        return events, []

    def tick(self, wall: float, sim_now: float, running: bool) -> tuple[list[Event], list[Act]]:
        """With `pause`: a participant away longer than the timeout is lost, and the trial aborted."""
        if not (self.paused and running):
            return [], []
        lost = [
            w
            for w, p in self.people.items()
            if p.away_since is not None and wall - p.away_since >= self.reconnect_timeout_s
        ]
        if not lost:
            return [], []
        self.paused = False
        events = [
            event(
                EventKind.PARTICIPANT_LOST,
                sim_now,
                Source.WEB,
                by=w,
                away_s=round(wall - (self.people[w].away_since or wall), 2),
            )
            for w in lost
        ]
        return events, [Act.RESUME, Act.ABORT]

    def release(self) -> list[Act]:
        """The researcher ends the trial while it is paused: it must run again to end."""
        if not self.paused:
            return []
        self.paused = False
        return [Act.RESUME]

    def away(self) -> list[str]:
        return [w for w, p in self.people.items() if p.away_since is not None]

    def report(self, who: str, text: str, wall: float) -> str | None:
        """A page's report (a JSON object of REPORTED, each a number >= 0 or null); None if taken,
        else the one-line reason it is not."""
        p = self.people.get(who)
        if p is None:
            return f"{who} is not a participant of this trial"
        if len(text.encode()) > MAX_REPORT_BYTES:
            return f"a page report of {len(text.encode())} bytes (at most {MAX_REPORT_BYTES})"
        try:
            data = json.loads(text)
        except (json.JSONDecodeError, RecursionError):
            return "a page report that is not JSON"
        if not isinstance(data, dict):
            return "a page report that is not a JSON object"
        values = {k: data.get(k) for k in REPORTED}
        if any(
            v is not None and (isinstance(v, bool) or not isinstance(v, (int, float)) or not 0 <= v < 1e9)
            for v in values.values()
        ):
            return "a page report with a value that is not a number >= 0"
        p.report = {k: None if v is None else round(float(v), 1) for k, v in values.items()}
        p.reported_at = wall
        return None

    def table(self, wall: float) -> dict[str, Any]:
        """The console's view (`/haven/participants`): per participant, connected or for how long
        away, and what their page last reported (and how long ago)."""
        rows = {}
        for who, p in self.people.items():
            state = "connected" if p.sockets else ("away" if p.seen else "not yet")
            rows[who] = {
                "state": state,
                "away_s": round(wall - p.away_since, 1) if p.away_since is not None else None,
                **{k: p.report.get(k) if p.sockets else None for k in REPORTED},  # (an away page reports nothing)
                "report_age_s": round(wall - p.reported_at, 1) if p.reported_at is not None else None,
            }
        return {"paused": self.paused, "on_disconnect": str(self.on_disconnect), "participants": rows}
