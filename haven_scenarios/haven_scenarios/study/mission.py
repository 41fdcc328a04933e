"""The mission executive: which target next, when to go and charge, what the robot is thinking.

It sends goals (a room centre, a gem, the charging base), says what the robot is doing (the
thought bubble's text), picks the next robot gem by its mission behaviour (a plugin: `nearest` by planned path length, a
seeded `random` order, `fixed`, or a lab's; study/mission_orders.py), and runs HAVEN's two battery modes with
planned path lengths instead of straight lines:

  * `on_arrival`: before leaving for a target, if path(robot -> target) + path(target -> base),
    times `safety_factor` (planned paths leave out turns and detours; HAVEN used 1), exceeds the
    remaining range, go and charge first;
  * `continuous`: the same check before leaving, and at every tick, when the remaining range falls
    to `safety_factor` x path(robot -> base), abandon the target and go and charge.

A robot that drains while it waits (a drone hovers while a person holds it up; `drains_waiting`)
runs the continuous check in either mode: a check made on leaving cannot foresee how long it will
be held up. It is the low-battery "Return" failsafe of drone autopilots (PX4's COM_LOW_BAT_ACT).

Charging lasts until the level reaches `charge_until`; then the remaining targets resume, the
abandoned one first. A target that a battery charged to `charge_until` can serve from the base one
way only is kept for last (the mission ends there); one it cannot reach from the base at all is
skipped with a `battery_insufficient` event; so no mode strands the robot or sends it back and
forth for ever. (The original wiped its target list on a detour and never charged.)
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from enum import Enum
from typing import Any

from haven_scenarios.study.mission_orders import MissionBehaviour, PathLength
from haven_scenarios.study.scenario import BatteryPlan
from haven_sim.common import contain, plugins
from haven_sim.common.events import Event, EventKind, Source, event
from haven_sim.common.geometry import Point, Pose2D

WAITING_THOUGHT = "Waiting for you to pass"  # the thought while the robot waits for a person (participants read it)


def _m(x: float) -> float | None:
    return round(x, 2) if math.isfinite(x) else None  # (JSON has no inf)


@dataclass(frozen=True)
class Target:
    id: str
    x: float
    y: float
    label: str  # for the thought bubble: "gem rg3", "room B"

    @property
    def xy(self) -> Point:
        return (self.x, self.y)


class Phase(Enum):
    IDLE = "idle"
    GOING = "going"
    TO_BASE = "to_base"
    CHARGING = "charging"
    DONE = "done"


@dataclass
class MissionOutput:
    goal: Pose2D | None = None  # a goal to send now
    thought: str | None = None  # a new thought text
    events: list[Event] = field(default_factory=list)


class Mission:
    def __init__(
        self,
        targets: Sequence[Target],
        path_length: PathLength,
        # a mission behaviour (study/mission_orders.py): fixed (the given order) | nearest | random | a lab's
        order: str = "fixed",
        battery: BatteryPlan | None = None,
        base: Point | None = None,
        seed: int = 0,
    ) -> None:
        self.battery = battery or BatteryPlan()
        if self.battery.mode != "off" and base is None:
            raise ValueError("a battery mode other than 'off' needs a charging base")
        self.path_length = path_length
        self.order = order
        self.behaviour: MissionBehaviour = contain.call("missions", order, plugins.registry("missions").get(order))
        self.base = base
        self.pending = contain.call("missions", order, self.behaviour.arrange, targets, seed)
        self.phase = Phase.IDLE
        self.current: Target | None = None
        self.done_ids: list[str] = []
        self.thought = ""
        self.charge_trips = 0
        self.skipped: list[str] = []  # targets no charged battery can reach from the base
        self.last_only: set[str] = set()  # targets a charged battery serves one way only: kept for last
        self._charge_level, self._charge_ticks = 0.0, 0  # charging progress, to notice a stall
        self._now = 0.0  # the time of the call being answered (stamps its events)

    def _event(self, out: MissionOutput, kind: EventKind, **data: Any) -> None:
        out.events.append(event(kind, self._now, Source.MISSION, **data))

    # -- decisions -------------------------------------------------------------------------------
    def _range(self, level: float) -> float:
        """Metres the robot can travel on `level`: the pack, less what the time at cruise drains (a
        drone hovers all the way; nothing for a robot that drains only as it moves)."""
        return level * self.battery.capacity_m / self.battery.drain_factor

    def _pick(self, robot: Pose2D) -> Target | None:
        """The next target by the order; targets kept for last come after every other."""
        candidates = [t for t in self.pending if t.id not in self.last_only] or self.pending
        if not candidates:
            return None
        picked: Target = contain.call("missions", self.order, self.behaviour.pick, candidates, robot, self.path_length)
        return picked

    def _say(self, out: MissionOutput, text: str) -> None:
        if text != self.thought:
            self.thought = text
            out.thought = text

    def _go(self, out: MissionOutput, target: Target) -> None:
        self.current, self.phase = target, Phase.GOING
        out.goal = Pose2D(target.x, target.y, math.nan)
        self._say(out, f"Going to {target.label}")
        self._event(out, EventKind.TARGET_SELECTED, target=target.id)

    def _to_base(self, out: MissionOutput, reason: str) -> None:
        assert self.base is not None
        self.phase = Phase.TO_BASE
        self.charge_trips += 1
        out.goal = Pose2D(self.base[0], self.base[1], math.nan)
        self._say(out, "Low battery: going to charge")
        self._event(out, EventKind.CHARGE_TRIP, reason=reason, abandoned=self.current.id if self.current else None)

    def _next(self, out: MissionOutput, robot: Pose2D, level: float) -> None:
        """The next target, or the base first when the range left does not cover it.

        In both battery modes the robot never leaves for a target it cannot reach and, unless it
        is the last one, come back from to the base (planned lengths times `safety_factor`, which
        keeps turns, arcs and detours in hand). A target that a charged battery (`charge_until`)
        can serve from the base only one way is kept for last; one it cannot reach at all from the
        base is skipped, with the reason, rather than driven to on a flat battery."""
        while True:
            target = self.current if self.current is not None else self._pick(robot)
            if target is None:
                self.phase, self.current = Phase.DONE, None
                self._say(out, "All done")
                self._event(out, EventKind.TASK_DONE, by="robot", skipped=list(self.skipped))
                return
            if self.battery.mode != "off" and self.base is not None:
                sf, full = self.battery.safety_factor, self._range(self.battery.charge_until)
                last = [t.id for t in self.pending] == [target.id]  # the mission ends there
                there = self.path_length(self.base, target.xy)
                back = self.path_length(target.xy, self.base)
                if sf * there > full:
                    self._event(
                        out,
                        EventKind.BATTERY_INSUFFICIENT,
                        target=target.id,
                        need_m=_m(sf * there),
                        has_m=_m(full),
                        skipped=True,
                    )
                    self.pending = [t for t in self.pending if t.id != target.id]
                    self.skipped.append(target.id)
                    self.current = None
                    continue
                if sf * (there + back) > full and not last and target.id not in self.last_only:
                    self.last_only.add(target.id)  # only as the last target: there is no coming back
                    self.current = None
                    continue
                if target.id in self.last_only and not last:
                    # Several targets a charged battery serves one way only: one of them can be the
                    # last; the farthest of the others is skipped.
                    one_way = [t for t in self.pending if t.id in self.last_only]
                    far = max(one_way, key=lambda t: self.path_length(self.base, t.xy))  # type: ignore[arg-type]
                    need_m = sf * (self.path_length(self.base, far.xy) + self.path_length(far.xy, self.base))
                    self._event(
                        out,
                        EventKind.BATTERY_INSUFFICIENT,
                        target=far.id,
                        need_m=_m(need_m),
                        has_m=_m(full),
                        skipped=True,
                    )
                    self.pending = [t for t in self.pending if t.id != far.id]
                    self.skipped.append(far.id)
                    self.current = None
                    continue
                home = 0.0 if last else self.path_length(target.xy, self.base)
                need = sf * (self.path_length((robot.x, robot.y), target.xy) + home)
                # (Charged as full as it gets, the check from the base above is the one that counts.)
                if need > self._range(level) and level < self.battery.charge_until - 1e-6:
                    self.current = target
                    self._to_base(out, f"needs {need:.1f} m, has {self._range(level):.1f} m")
                    return
            self._go(out, target)
            return

    # -- inputs ----------------------------------------------------------------------------------
    def start(self, now: float, robot: Pose2D, level: float = 1.0) -> MissionOutput:
        self._now = now
        out = MissionOutput()
        self._next(out, robot, level)
        return out

    def target_done(self, now: float, target_id: str, robot: Pose2D, level: float) -> MissionOutput:
        """A rule says the current target is finished (gem collected, room reached)."""
        self._now = now
        out = MissionOutput()
        self.pending = [t for t in self.pending if t.id != target_id]
        self.done_ids.append(target_id)
        if self.current is not None and self.current.id == target_id:
            self.current = None
            if self.phase is Phase.GOING:
                self._next(out, robot, level)
        return out

    def resend(self) -> MissionOutput:
        """The world changed (an obstruction went away): ask for the current goal again."""
        out = MissionOutput()
        if self.phase is Phase.GOING and self.current is not None:
            out.goal = Pose2D(self.current.x, self.current.y, math.nan)
        elif self.phase is Phase.TO_BASE and self.base is not None:
            out.goal = Pose2D(self.base[0], self.base[1], math.nan)
        return out

    def tick(
        self, now: float, robot: Pose2D, level: float, at_base: bool = False, waiting: bool = False
    ) -> MissionOutput:
        self._now = now
        out = MissionOutput()
        p = self.battery
        if self.phase is Phase.TO_BASE and at_base:
            self.phase = Phase.CHARGING
            self._charge_level, self._charge_ticks = level, 0
            self._event(out, EventKind.CHARGING_STARTED, level=round(level, 3))
        if self.phase is Phase.CHARGING:
            if level >= p.charge_until - 1e-6:
                self._event(out, EventKind.CHARGING_DONE, level=round(level, 3))
                self._next(out, robot, level)
            elif level <= self._charge_level + 1e-4 and self._charge_ticks >= 25:
                # Not charging (e.g. stopped just off the base): drive onto it again.
                self._event(out, EventKind.CHARGING_STALLED, level=round(level, 3))
                self.phase = Phase.TO_BASE
                assert self.base is not None
                out.goal = Pose2D(self.base[0], self.base[1], math.nan)
            else:
                if level > self._charge_level + 1e-4:
                    self._charge_level, self._charge_ticks = level, 0
                self._charge_ticks += 1
                self._say(out, f"Charging: {round(100 * level)} %")
            return out
        # (checked one way on leaving)
        last = self.current is not None and [t.id for t in self.pending] == [self.current.id]
        watch = p.mode == "continuous" or p.drains_waiting
        if self.phase is Phase.GOING and watch and self.base is not None and not last:
            home = self.path_length((robot.x, robot.y), self.base)
            if self._range(level) <= p.safety_factor * home:
                self._to_base(out, f"range {self._range(level):.1f} m <= {p.safety_factor:g} x {home:.1f} m home")
                return out
        if self.phase is Phase.GOING and self.current is not None:
            self._say(out, WAITING_THOUGHT if waiting else f"Going to {self.current.label}")
        return out
