"""The study log's vocabulary: one `Event` type and the enum of every event kind on /haven/events.

An event is one JSON object on the wire (`{"stamp": 12.34, "source": "planner", "type":
"replanned", "side": "left", ...}`): `stamp` is sim time in seconds, `source` the node that saw it,
`type` one of `EventKind`, the other keys its data. Producers build `Event`s, consumers read them back
with `Event.from_dict`, which refuses anything malformed with `EventError` (one line), so a bad
string from another node is skipped instead of taking a node down. The kind strings are a stable
interface: recordings and users' analysis scripts read them.
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from enum import StrEnum
from typing import Any

from haven_sim.common.yaml_file import short

MAX_EVENT_BYTES = 64 * 1024  # an event is a few hundred bytes; anything this big is refused


class EventKind(StrEnum):
    # simulator
    CONTACT_BEGIN = "contact_begin"  # other: "wall" or "human:<id>"
    CONTACT_END = "contact_end"
    BATTERY_EMPTY = "battery_empty"
    OBSTRUCTION_REMOVED = "obstruction_removed"  # id
    RESET = "reset"
    TOOK_OFF = "took_off"  # an aerial robot left its pad (climbing to cruise height)
    LANDED = "landed"  # an aerial robot is down on its pad
    # real_time_factor, requested: the controller fell behind, sim time ran slower (free-running)
    CLOCK_HELD = "clock_held"
    # velocity mux
    CMD_SOURCE = "cmd_source"  # from, to: nav | teleop | estop | idle
    # planner
    PLAN_MADE = "plan_made"  # goal, length_m, poses
    PLAN_REFUSED = "plan_refused"  # reason; failure (nav.planner.PlanFailure) where a plan was tried
    WAITING = "waiting"  # reason, human
    RESUMED = "resumed"
    REPLANNED = "replanned"  # side, human
    REVERTED = "reverted"
    GOAL_CANCELLED = "goal_cancelled"  # by: the goal dropped on /haven/cancel_goal (a Nav2 client's cancel)
    GOAL_STORM = "goal_storm"  # goals, superseded, seconds: goals came faster than goal_interval_s (the newest won)
    # controller
    GOAL_REACHED = "goal_reached"  # goal, pose
    # viz
    CUE_TOGGLED = "cue_toggled"  # cue, on
    # cue, error: what recordings before plugin_failed said of a cue that raised (read as plugin_failed)
    CUE_FAILED = "cue_failed"
    # scenario and mission executive
    TRIAL_START = "trial_start"
    TARGET_SELECTED = "target_selected"
    GOAL_SENT = "goal_sent"  # goal: [x, y] published on /goal_pose at this stamp
    GEM_COLLECTED = "gem_collected"  # gem, by
    DWELL_STARTED = "dwell_started"
    DWELL_RESET = "dwell_reset"
    ROOM_REACHED = "room_reached"  # room, by, index
    OBSTRUCTION_CLEARED = "obstruction_cleared"  # id, by, room
    CHARGE_TRIP = "charge_trip"  # reason, abandoned
    CHARGING_STARTED = "charging_started"
    CHARGING_DONE = "charging_done"
    CHARGING_STALLED = "charging_stalled"
    BATTERY_INSUFFICIENT = "battery_insufficient"
    TASK_DONE = "task_done"  # by
    TRIAL_END = "trial_end"  # reason
    # any node
    # kind, name, error: a plugin raised or overran its deadline (common/contain.py): the trial ends, not valid
    PLUGIN_FAILED = "plugin_failed"
    # request (parameter | service), name, reason: somebody asked what a running trial does not allow
    REQUEST_REFUSED = "request_refused"
    # any node on the lockstep clock (nodes/lockstep.py)
    # topic, ignored, taken, dropped: messages from outside the suite since the last one
    OUTSIDE_INPUT = "outside_input"
    INPUT_LOST = "input_lost"  # topic, messages: announced by the suite, never arrived
    # researcher console (Wizard of Oz)
    INTERVENTION = "intervention"  # action: thought (text) | drive | drive_end | skip_questionnaires, by
    PARTICIPANT_READY = "participant_ready"  # by: a participant pressed Start on their page
    # by, policy: their page's connection closed (a tab, the network)
    PARTICIPANT_DISCONNECTED = "participant_disconnected"
    PARTICIPANT_RECONNECTED = "participant_reconnected"  # by, away_s (wall time)
    PARTICIPANT_LOST = "participant_lost"  # by, away_s: not back within the pause's timeout (the trial is aborted)
    TRIAL_PAUSED = "trial_paused"  # simulated time stands still (a participant away, on_disconnect: pause)
    TRIAL_RESUMED = "trial_resumed"  # paused_s (wall time)
    # by, questionnaire, scores, answers: after the trial, on their page
    QUESTIONNAIRE_ANSWERED = "questionnaire_answered"


class Source(StrEnum):
    SIM = "sim"
    MUX = "mux"
    PLANNER = "planner"
    CONTROLLER = "controller"
    VIZ = "viz"
    SCENARIO = "scenario"
    MISSION = "mission"
    WEB = "web"  # the study's web pages (participants, researcher console)


# Data keys a consumer relies on, checked when an event is read.
REQUIRED: dict[EventKind, tuple[str, ...]] = {
    EventKind.CONTACT_BEGIN: ("other",),
    EventKind.CONTACT_END: ("other",),
    EventKind.OBSTRUCTION_REMOVED: ("id",),
    EventKind.CUE_TOGGLED: ("cue", "on"),
    EventKind.CUE_FAILED: ("cue", "error"),
    EventKind.PLUGIN_FAILED: ("kind", "name", "error"),
    EventKind.GEM_COLLECTED: ("gem", "by"),
    EventKind.ROOM_REACHED: ("room", "by"),
    EventKind.OBSTRUCTION_CLEARED: ("id",),
    EventKind.TASK_DONE: ("by",),
    EventKind.TRIAL_END: ("reason",),
    EventKind.INTERVENTION: ("action",),
    EventKind.OUTSIDE_INPUT: ("topic",),
    EventKind.REQUEST_REFUSED: ("request", "name"),
    EventKind.INPUT_LOST: ("topic", "messages"),
    EventKind.PARTICIPANT_READY: ("by",),
    EventKind.QUESTIONNAIRE_ANSWERED: ("by", "questionnaire", "scores"),
}
_RESERVED = ("stamp", "source", "type")
PLAN_POSES = "plan_poses"  # on the planner's event that goes with a /plan: how many poses it has
GOAL_POSE = "goal"  # on `goal_sent`: [x, y] of the /goal_pose that goes with it
_KINDS = frozenset(k.value for k in EventKind)


class EventError(ValueError):
    """Not a valid event; the message says why in one line."""


@dataclass(frozen=True)
class Event:
    kind: EventKind
    stamp: float
    source: str
    data: Mapping[str, Any] = field(default_factory=dict)

    def __getitem__(self, key: str) -> Any:
        return self.data[key]

    def get(self, key: str, default: Any = None) -> Any:
        return self.data.get(key, default)

    def to_dict(self) -> dict[str, Any]:
        return {"stamp": round(self.stamp, 4), "source": self.source, "type": self.kind.value, **self.data}

    def to_json(self) -> str:
        return json.dumps(self.to_dict(), sort_keys=True)

    @staticmethod
    def from_dict(d: Any) -> Event:
        if not isinstance(d, Mapping):
            raise EventError(f"an event must be a JSON object, got {type(d).__name__}")
        kind = d.get("type")
        if not isinstance(kind, str) or kind not in _KINDS:
            raise EventError(f"unknown event type {short(kind)}")
        k = EventKind(kind)
        stamp = d.get("stamp")
        if isinstance(stamp, bool) or not isinstance(stamp, (int, float)) or not math.isfinite(stamp):
            raise EventError(f"{k.value}: stamp must be a finite number, got {short(stamp)}")
        source = d.get("source", "")
        if not isinstance(source, str):
            raise EventError(f"{k.value}: source must be a string, got {short(source)}")
        data = {key: v for key, v in d.items() if key not in _RESERVED}
        missing = [key for key in REQUIRED.get(k, ()) if key not in data]
        if missing:
            raise EventError(f"{k.value}: missing {', '.join(missing)}")
        for key in ("gem", "by", "id", "room", "cue", "other", "reason"):
            if key in data and not isinstance(data[key], str):
                raise EventError(f"{k.value}: {key} must be a string, got {short(data[key])}")
        return Event(k, float(stamp), source, data)

    @staticmethod
    def from_json(text: str | bytes) -> Event:
        if len(text) > MAX_EVENT_BYTES:
            raise EventError(f"event of {len(text)} bytes is larger than {MAX_EVENT_BYTES}")
        try:
            d = json.loads(text)
        except (ValueError, RecursionError) as e:
            raise EventError(f"not JSON: {str(e)[:80]}") from None
        return Event.from_dict(d)


def event(kind: EventKind, stamp: float, source: str, **data: Any) -> Event:
    """Shorthand for producers: `event(EventKind.WAITING, now, Source.PLANNER, reason=...)`."""
    return Event(kind, stamp, source, data)


class Sequencer:
    """Numbers a publisher's events per source (`seq` 1, 2, ...), so a reader can tell whether
    any went missing on the way."""

    def __init__(self) -> None:
        self._count: dict[str, int] = {}

    def number(self, e: Event) -> Event:
        n = self._count.get(e.source, 0) + 1
        self._count[e.source] = n
        return Event(e.kind, e.stamp, e.source, {**e.data, "seq": n})
