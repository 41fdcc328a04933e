"""The study rules of HAVEN's two scenarios, as pure functions of poses and time.

Gems: the robot collects only its current target gem (it does not collect gems it brushes past); a
human collects a human gem by staying within its radius for `dwell_time_s` (3 s) without a break,
the timer restarting whenever they leave. Hallway: each party visits room centres in order. An
obstruction disappears when a human reaches its named room. A trial ends when every party is done,
on a timeout, or (optionally) on a robot-human contact. Every rule that fires is an event (a dict
that becomes one JSON object on /haven/events).
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from enum import StrEnum
from typing import Any

from haven_sim.common.events import Event, EventKind, Source, event
from haven_sim.common.geometry import Pose2D
from haven_sim.sim.world import Gem, World


def _rule(kind: EventKind, now: float, **data: Any) -> Event:
    return event(kind, now, Source.SCENARIO, **data)


def _near(p: Pose2D, xy: tuple[float, float], radius: float) -> bool:
    return math.hypot(p.x - xy[0], p.y - xy[1]) <= radius


class GemRules:
    def __init__(self, gems: Sequence[Gem], dwell_time_s: float = 3.0) -> None:
        if dwell_time_s < 0:
            raise ValueError(f"dwell_time_s must not be negative, got {dwell_time_s}")
        self.gems = {g.id: g for g in gems}
        self.dwell_time_s = dwell_time_s
        self.collected: dict[str, str] = {}  # gem id -> who ("robot" or a human id)
        self.robot_target: str | None = None
        self._dwell: dict[tuple[str, str], float] = {}  # (gem, human) -> time they arrived

    def remaining(self, owner: str) -> list[Gem]:
        return [g for g in self.gems.values() if g.owner == owner and g.id not in self.collected]

    def dwell_progress(self, human: str, now: float) -> float | None:
        """How far `human` is through standing in a gem (0..1), None while in none."""
        since = [t for (_, hid), t in self._dwell.items() if hid == human]
        if not since or self.dwell_time_s == 0:
            return None
        return min(1.0, (now - min(since)) / self.dwell_time_s)

    def update(self, now: float, robot: Pose2D, humans: Mapping[str, Pose2D]) -> list[Event]:
        events: list[Event] = []
        target = self.gems.get(self.robot_target or "")
        if (
            target is not None
            and target.owner == "robot"
            and target.id not in self.collected
            and _near(robot, target.position, target.radius)
        ):
            self.collected[target.id] = "robot"
            events.append(_rule(EventKind.GEM_COLLECTED, now, gem=target.id, by="robot"))
            self.robot_target = None
        for gem in self.remaining("human"):
            for hid, pose in humans.items():
                key = (gem.id, hid)
                inside = _near(pose, gem.position, gem.radius)
                if inside and key not in self._dwell:
                    self._dwell[key] = now
                    events.append(_rule(EventKind.DWELL_STARTED, now, gem=gem.id, by=hid))
                elif not inside and key in self._dwell:
                    stayed = now - self._dwell.pop(key)
                    events.append(_rule(EventKind.DWELL_RESET, now, gem=gem.id, by=hid, after_s=round(stayed, 3)))
                if key in self._dwell and now - self._dwell[key] >= self.dwell_time_s - 1e-9:
                    self.collected[gem.id] = hid
                    events.append(_rule(EventKind.GEM_COLLECTED, now, gem=gem.id, by=hid))
                    self._dwell = {k: v for k, v in self._dwell.items() if k[0] != gem.id}
                    break
        return events


@dataclass
class RouteRules:
    """Room centres each party visits in order (the hallway task)."""

    world: World
    routes: Mapping[str, Sequence[str]]  # party ("robot" or a human id) -> room names
    reach_m: float = 0.5
    progress: dict[str, int] = field(default_factory=dict)

    def __post_init__(self) -> None:
        names = {r.name for r in self.world.rooms}
        for who, route in self.routes.items():
            unknown = [r for r in route if r not in names]
            if unknown:
                raise ValueError(f"route of {who} names rooms not in world '{self.world.name}': {', '.join(unknown)}")
            self.progress.setdefault(who, 0)

    def next_room(self, who: str) -> str | None:
        route = self.routes.get(who, ())
        i = self.progress.get(who, 0)
        return route[i] if i < len(route) else None

    def done(self, who: str) -> bool:
        return self.next_room(who) is None

    def update(self, now: float, poses: Mapping[str, Pose2D]) -> list[Event]:
        events: list[Event] = []
        for who, pose in poses.items():
            room = self.next_room(who)
            if room is not None and _near(pose, self.world.room(room).centre, self.reach_m):
                self.progress[who] += 1
                events.append(_rule(EventKind.ROOM_REACHED, now, room=room, by=who, index=self.progress[who]))
        return events


@dataclass
class ObstructionRules:
    """An obstruction goes away when a human reaches its named room centre."""

    world: World
    reach_m: float = 0.5
    cleared: set[str] = field(default_factory=set)

    def update(self, now: float, humans: Mapping[str, Pose2D]) -> list[Event]:
        events: list[Event] = []
        for o in self.world.obstructions:
            if o.id in self.cleared or o.removed_when_human_reaches is None:
                continue
            centre = self.world.room(o.removed_when_human_reaches).centre
            for hid, pose in humans.items():
                if _near(pose, centre, self.reach_m):
                    self.cleared.add(o.id)
                    events.append(
                        _rule(EventKind.OBSTRUCTION_CLEARED, now, id=o.id, by=hid, room=o.removed_when_human_reaches)
                    )
                    break
        return events


class EndReason(StrEnum):
    """Why a trial ended (`trial_end`'s reason, metrics' `end_reason`)."""

    COMPLETED = "completed"
    TIMEOUT = "timeout"
    CONTACT = "contact"
    BATTERY_EMPTY = "battery_empty"  # flat off the charging base
    INTERRUPTED = "interrupted"  # stopped before a `trial_end` (Ctrl-C, a node died)
    STOPPED = "stopped"  # the researcher ended the trial early (the console's stop)
    ABORTED = "aborted"  # the researcher called the trial off (the console's abort): not for analysis
    # a plugin's code raised or overran its deadline (a `plugin_failed` event says which): not valid
    PLUGIN_FAILED = "plugin_failed"


class TrialState(StrEnum):
    """Where a trial is (/haven/trial_status's `state`)."""

    WAITING = "waiting"  # for the nodes it needs
    HELD = "held"  # for the researcher's start
    RUNNING = "running"
    ENDED = "ended"


class TrialCommand(StrEnum):
    """What /haven/trial_control asks of the trial (the researcher console, `ros2 topic pub`)."""

    START = "start"  # begin a trial held for the researcher (`hold_start`)
    STOP = "stop"  # end it now: completed as far as it went
    ABORT = "abort"  # end it now: called off

    @staticmethod
    def parse(text: str) -> tuple[TrialCommand, str]:
        """A command and who asked (`abort dropout:h1`; default `researcher`); ValueError in one line."""
        word, _, by = text.strip().partition(" ")
        try:
            command = TrialCommand(word.lower())
        except ValueError:
            raise ValueError(f"unknown trial command {text!r} (expected {', '.join(TrialCommand)})") from None
        by = by.strip() or "researcher"
        if not _BY.match(by):
            raise ValueError(
                f"trial command {text[:80]!r}: who asked must be letters, digits, '_', ':' or '-' (up to 64)"
            )
        return command, by


_BY = re.compile(r"^[A-Za-z0-9_:-]{1,64}$")  # who asked for a trial command (trial_end's `by`)


@dataclass(frozen=True)
class EndRule:
    timeout_s: float
    end_on_contact: bool = False

    def reason(self, elapsed_s: float, all_done: bool, contact: bool) -> EndReason | None:
        if all_done:
            return EndReason.COMPLETED
        if self.end_on_contact and contact:
            return EndReason.CONTACT
        if elapsed_s >= self.timeout_s:
            return EndReason.TIMEOUT
        return None
