"""Simulated participants for unattended trials, as velocity commands for /humans/<id>/cmd_vel.

  * `Walker`: walks its task (room centres in order, or the human gems, standing on each for the
    dwell time) along planned paths, with seeded variation in speed and, for gems, in route;
  * `Blocker`: a walker that first steps into the robot's way a few metres ahead of the robot and
    stands there a while (the case that makes HAVEN's robot wait or detour): onto the projected path
    when they see it, else where the robot's motion, as they saw it, leads;
  * `Yielder`: a walker that stops and steps aside when the robot comes close in front of it (from
    farther, and away from its shown path, when the cues show where it goes).

They act on what they perceive (`perception`: the robot and the cues within their field of view and
viewing distance, not behind walls), one reaction time late (`anticipation.DelayLine`), with the
parameters of `person.PersonParams` (cited there) as drawn for this person and this trial
(`person.individual`: people differ, vary from trial to trial and learn over their session), and in
an encounter with the cues they sometimes ignore them (`cue_error`). One who sees the robot's way ahead (the projected
path, a lit turn signal) moves to its far side early or gives way early; one who does not reacts to
the robot's motion only, and slows while a robot whose intent they cannot read closes in, in their
way (`anticipation`). All of them move by the social-force model (`social_force`): their task gives
a desired velocity, walls, people and the robot as seen push them off it, and they never close in on
the robot (that rule uses where the robot really is: a robot at arm's length is felt, seen or not).
"""

from __future__ import annotations

import itertools
import math
import random
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Protocol

from haven_scenarios.study.anticipation import DelayLine, Seen, hesitant, intent_ways, keep_clear, waits_for_me
from haven_scenarios.study.perception import Percept, ahead_of
from haven_scenarios.study.person import PersonParams, individual
from haven_scenarios.study.scenario import HumanTask, Scenario
from haven_scenarios.study.social_force import Body, SocialForce, robot_body
from haven_sim.common.bodies import HUMAN_BODY
from haven_sim.common.geometry import Point, Pose2D, Twist2D, wrap_angle
from haven_sim.nav.planner import Planner, PlannerParams, PlanningError
from haven_sim.robots.fields import DEFAULT

# How a simulated participant plans their own walks: their body, a little margin, generous snapping.
CLOSE_ENOUGH_M = 0.3  # a stop the person cannot get nearer to than this (someone beside it) counts as reached
ROBOT_ON_STOP_M = 0.6  # the robot this close to a stop stands on it
SIDE_HOLD_S = 3.0  # a side chosen to pass the robot on is kept this long after the last step aside
# no cue seen for this long ends an encounter with the robot's cues (ours: a glance away is not a new encounter)
ENCOUNTER_GAP_S = 2.0
HUMAN_PLANNER = PlannerParams(safety_margin_m=0.05, snap_radius_m=0.5, body_radius_m=HUMAN_BODY.radius_m)


class Participant(Protocol):
    """A simulated participant model: a velocity for /humans/<id>/cmd_vel from what they perceive
    (`robot`: where the robot is, for the never-close-in rule alone)."""

    id: str
    done: bool  # their task is finished
    params: PersonParams

    def command(
        self, now: float, me: Pose2D, robot: Pose2D, percept: Percept, others: Sequence[Pose2D] = ()
    ) -> Twist2D: ...


@dataclass(frozen=True)
class Stop:
    """A place to walk to and how long to stand there."""

    x: float
    y: float
    dwell_s: float = 0.0
    reach_m: float = 0.15


def shuffled_nearest(stops: Sequence[Stop], start: Point, seed: int) -> list[Stop]:
    """A route through `stops`: nearest next, with seeded randomness (people do not plan tours)."""
    rng = random.Random(seed)
    left, here, route = list(stops), start, []
    while left:
        left.sort(key=lambda s: math.hypot(s.x - here[0], s.y - here[1]) * rng.uniform(0.7, 1.3))
        nxt = left.pop(0)
        route.append(nxt)
        here = (nxt.x, nxt.y)
    return route


class Walker:
    """Walks its stops along planned paths; moves by the social-force model (`social_force`), so it
    steers round walls, other people and the robot, keeps right of oncoming traffic and never
    closes in on the robot."""

    def __init__(
        self,
        human_id: str,
        stops: Sequence[Stop],
        planner: Planner,
        speed_mps: float = 1.0,
        seed: int = 0,
        params: PersonParams | None = None,
    ) -> None:
        self.id = human_id
        self.person = individual(params or PersonParams(), human_id, seed)  # who they are, as in this trial
        self.params = p = self.person.params
        self.rng = random.Random(seed)
        self.speed = speed_mps * self.person.speed_factor
        self.attention = DelayLine(p.reaction_s)
        self._encounter: tuple[bool, float] | None = None  # (the cues misread this encounter, when a cue was last seen)
        self.encounters = self.misreads = 0
        self.half_fov = math.radians(p.fov_deg) / 2.0
        self.stops = list(stops)
        self.planner = planner
        self.crowd = SocialForce(planner.free_run)
        self._waypoints: list[Point] = []
        self._arrived_at: float | None = None
        self._progress_mark: tuple[float, float] | None = None  # (when, distance to the waypoint) at the last progress
        self._last_tick: float | None = None
        self._dt = 0.1
        self._robot_radius = DEFAULT.radius_m  # the robot's size, as last seen
        self._others: Sequence[Pose2D] = ()  # the other people, as of this tick
        self._robot: Pose2D | None = None  # the robot as the person acts on it (None: not seen)
        self._side = (0.0, -math.inf)  # the side they pass the robot's shown way on, until when
        self.done = not self.stops

    def command(
        self, now: float, me: Pose2D, robot: Pose2D, percept: Percept, others: Sequence[Pose2D] = ()
    ) -> Twist2D:
        self._robot_radius = percept.robot_radius_m
        self.attention.push(self._read_cues(now, percept))
        seen = self.attention.acted_on(now)
        self._others, self._robot = others, seen.percept.robot if seen is not None else None
        return self._move(now, me, robot, seen, others, self._desired(now, me, seen))

    def _read_cues(self, now: float, percept: Percept) -> Percept:
        """The percept as the person reads it: in an encounter with the robot's cues (from the first
        cue seen until none has been seen for `ENCOUNTER_GAP_S`), with probability `cue_error` they
        ignore every cue, as if none were shown, for the whole encounter."""
        if not (percept.intent_shown or percept.thought):
            return percept
        if self._encounter is None or now - self._encounter[1] > ENCOUNTER_GAP_S:
            misread = self.person.rng.random() < self.params.cue_error
            self.encounters += 1
            self.misreads += misread
        else:
            misread = self._encounter[0]
        self._encounter = (misread, now)
        return Percept(percept.stamp, percept.robot) if misread else percept

    def _desired(self, now: float, me: Pose2D, seen: Seen | None) -> Point:
        """The velocity the person wants (world frame), before the social forces."""
        return self._react(now, me, self._task(now, me), seen)

    def _react(self, now: float, me: Pose2D, task: Point, seen: Seen | None) -> Point:
        """The task's walk as what the person saw changes it: clear of the robot's shown way (on the
        side first chosen, for `SIDE_HOLD_S` after the last step aside), or slowed while a robot they
        cannot read closes in."""
        if seen is None:
            return task
        ways = intent_ways(seen.percept)
        if ways:
            side = self._side[0] if now < self._side[1] else 0.0
            adjusted = keep_clear(me, task, ways, seen, self.params, self.planner.free_run, side)
            if adjusted is None:
                return task
            if adjusted[1]:
                self._side = (adjusted[1], now + SIDE_HOLD_S)
            return adjusted[0]
        if hesitant(me, task, seen, self.params, self.half_fov):
            return (task[0] * self.params.hesitate_factor, task[1] * self.params.hesitate_factor)
        return task

    # -- moving ------------------------------------------------------------------------------------
    def _move(
        self, now: float, me: Pose2D, robot: Pose2D, seen: Seen | None, others: Sequence[Pose2D], desired: Point
    ) -> Twist2D:
        """The social-force step from the desired velocity, as a command in the person's frame: the
        robot pushes where and as the person saw it move; where it is only for the hard rule."""
        if self._last_tick is not None and now > self._last_tick:
            self._dt = min(0.5, now - self._last_tick)
        self._last_tick = now
        bodies = [Body(o.x, o.y, 0.0, 0.0, HUMAN_BODY.radius_m) for o in others]
        if seen is not None and seen.percept.robot is not None:
            r = seen.percept.robot
            bodies.insert(0, robot_body(r.x, r.y, *seen.robot_v, seen.percept.robot_radius_m))
        vx, vy = self.crowd.step(
            (me.x, me.y), desired, bodies, self._dt, guard=(robot_body(robot.x, robot.y, 0.0, 0.0, self._robot_radius),)
        )
        return self._twist(me, (vx, vy), desired)

    def _twist(self, me: Pose2D, v: Point, desired: Point) -> Twist2D:
        """World velocity `v` as a command in the person's own frame, turning to face where they
        go. The command holds for the tick, so it is aimed along the heading they will have half-way
        through, or the walk would curl as they turn."""
        face = v if math.hypot(*v) > 0.1 else desired
        wz = (
            max(-3.0, min(3.0, 2.0 * wrap_angle(math.atan2(face[1], face[0]) - me.yaw)))
            if math.hypot(*face) > 1e-3
            else 0.0
        )
        mid = me.yaw + 0.5 * wz * self._dt
        c, s = math.cos(mid), math.sin(mid)
        return Twist2D(c * v[0] + s * v[1], -s * v[0] + c * v[1], wz)

    def _toward(self, me: Pose2D, x: float, y: float, speed: float) -> Point:
        """Desired velocity straight at (x, y), slowing on the last stretch."""
        dx, dy = x - me.x, y - me.y
        d = math.hypot(dx, dy)
        v = min(speed, 1.5 * d + 0.05)
        return (v * dx / max(d, 1e-9), v * dy / max(d, 1e-9))

    # -- the task ----------------------------------------------------------------------------------
    def _plan(self, me: Pose2D) -> None:
        stop = self.stops[0]
        try:
            self._waypoints = self.planner.plan((me.x, me.y), (stop.x, stop.y)).points[1:]
        except PlanningError:
            self._waypoints = [(stop.x, stop.y)]

    def _task(self, now: float, me: Pose2D) -> Point:
        """Desired velocity for the task: along the planned path to the next stop, or stand."""
        if self.done:
            return (0.0, 0.0)
        stop = self.stops[0]
        d = math.hypot(stop.x - me.x, stop.y - me.y)
        if d <= stop.reach_m or (self._arrived_at is not None and d <= self._close_enough(stop)):
            if self._arrived_at is None:
                self._arrived_at = now
            if now - self._arrived_at >= stop.dwell_s:
                self.stops.pop(0)
                self._waypoints, self._arrived_at = [], None
                self.done = not self.stops
            return (0.0, 0.0)
        self._arrived_at = None
        if not self._waypoints or self._stuck(now, me):
            if d <= self._close_enough(stop):  # held off the spot (by someone beside it): this is as close as it gets
                self._arrived_at = now
                return (0.0, 0.0)
            # Others are going for it: come back to it later (a stop to stand on; a route's rooms keep their order).
            if stop.dwell_s > 0.0 and self._contested(stop) and len(self.stops) > 1 and self.rng.random() < 0.5:
                self.stops.append(self.stops.pop(0))
            self._plan(me)
        while len(self._waypoints) > 1 and math.hypot(self._waypoints[0][0] - me.x, self._waypoints[0][1] - me.y) < 0.3:
            self._waypoints.pop(0)
        x, y = self._waypoints[0]
        return self._toward(me, x, y, self.speed)

    def _close_enough(self, stop: Stop) -> float:
        """How near a stop counts once the person is held off it: nearer when a person stands beside
        it, farther when the robot stands on a stop that is only passed through (a room's centre:
        the robot may be waiting for them and neither would move). A stop to stand on for a while
        (a gem) needs the person on it."""
        robot = self._robot
        held = (
            robot is not None
            and stop.dwell_s == 0.0
            and math.hypot(stop.x - robot.x, stop.y - robot.y) < ROBOT_ON_STOP_M
        )
        return ROBOT_ON_STOP_M + HUMAN_BODY.radius_m if held else CLOSE_ENOUGH_M

    def _contested(self, stop: Stop, near_m: float = 0.8) -> bool:
        return any(math.hypot(stop.x - o.x, stop.y - o.y) < near_m for o in self._others)

    def _stuck(self, now: float, me: Pose2D, window_s: float = 1.5, min_progress_m: float = 0.1) -> bool:
        """No progress toward the current waypoint for `window_s` (pushed aside, caught on a corner):
        time to plan again from where they are."""
        x, y = self._waypoints[0]
        d = math.hypot(x - me.x, y - me.y)
        if self._progress_mark is None or d < self._progress_mark[1] - min_progress_m:
            self._progress_mark = (now, d)
            return False
        if now - self._progress_mark[0] >= window_s:
            self._progress_mark = None
            return True
        return False


class Blocker(Walker):
    """Walks (along a planned path, round walls) into the robot's way `ahead_m` in front of the
    robot, stands `block_s`, then goes about its task; gives the block up if the spot cannot be
    reached within `give_up_s`. The spot is on the projected path when the person sees enough of
    it, else `ahead_m` along the robot's motion as they saw it; with neither, they just walk."""

    def __init__(
        self, *args: object, ahead_m: float = 3.0, block_s: float = 8.0, give_up_s: float = 30.0, **kwargs: object
    ) -> None:
        super().__init__(*args, **kwargs)  # type: ignore[arg-type]
        self.ahead_m, self.block_s, self.give_up_s = ahead_m, block_s, give_up_s
        self._spot: Point | None = None
        self._route: list[Point] = []  # planned waypoints to the spot
        self._spot_since = 0.0
        self._blocking_since: float | None = None
        self.blocked = False

    def _spot_on_path(self, seen: Seen) -> Point | None:
        """The first seen marker `ahead_m` along the shown path (and not much nearer in a straight
        line); when less of the path is in view, its farthest seen marker at least half that far."""
        path = seen.percept.path
        robot = seen.percept.robot
        ref = (robot.x, robot.y) if robot is not None else path[0]
        walked = math.hypot(path[0][0] - ref[0], path[0][1] - ref[1])
        for a, b in itertools.pairwise(path):
            walked += math.hypot(b[0] - a[0], b[1] - a[1])
            if walked >= self.ahead_m and math.hypot(b[0] - ref[0], b[1] - ref[1]) >= self.ahead_m * 0.8:
                return b
        last = path[-1]
        return (
            last
            if walked >= self.ahead_m / 2 and math.hypot(last[0] - ref[0], last[1] - ref[1]) >= self.ahead_m * 0.4
            else None
        )

    def _spot_on_motion(self, seen: Seen) -> Point | None:
        """`ahead_m` along the robot's seen motion, if it moves and that place is free."""
        robot, (vx, vy) = seen.percept.robot, seen.robot_v
        speed = math.hypot(vx, vy)
        if robot is None or speed < 0.1:
            return None
        x, y = robot.x + vx / speed * self.ahead_m, robot.y + vy / speed * self.ahead_m
        return (x, y) if self.planner.is_free(x, y) else None

    def _choose_spot(self, now: float, me: Pose2D, seen: Seen) -> None:
        spot = (self._spot_on_path(seen) if seen.percept.path else None) or self._spot_on_motion(seen)
        if spot is None:
            return
        try:
            self._route = self.planner.plan((me.x, me.y), spot).points[1:]
        except PlanningError:
            return
        self._spot, self._spot_since = spot, now

    def _desired(self, now: float, me: Pose2D, seen: Seen | None) -> Point:
        if self.blocked:
            return self._task(now, me)
        if self._spot is None and seen is not None:
            self._choose_spot(now, me, seen)
        if self._spot is None:
            return self._task(now, me)
        if self._blocking_since is None and math.hypot(self._spot[0] - me.x, self._spot[1] - me.y) > 0.2:
            if now - self._spot_since > self.give_up_s:
                self.blocked, self._waypoints = True, []
                return self._task(now, me)
            while len(self._route) > 1 and math.hypot(self._route[0][0] - me.x, self._route[0][1] - me.y) < 0.3:
                self._route.pop(0)
            x, y = self._route[0] if self._route else self._spot
            return self._toward(me, x, y, self.speed)
        if self._blocking_since is None:
            self._blocking_since = now
        if now - self._blocking_since >= self.block_s:
            self.blocked, self._waypoints = True, []
        return (0.0, 0.0)


class Yielder(Walker):
    """Stops and steps to its right, as far as the wall allows, when the robot is seen within
    `yield_m` in front of it; when the cues show the robot's way, from twice as far, and to the far
    side of that way. If the robot does not move on for `patience_s` (it waits for them in turn),
    or its thought bubble says it waits for them, the person walks on past it for `walk_on_s`:
    nobody waits for ever."""

    def __init__(
        self, *args: object, yield_m: float = 1.5, patience_s: float = 4.0, walk_on_s: float = 6.0, **kwargs: object
    ) -> None:
        super().__init__(*args, **kwargs)  # type: ignore[arg-type]
        self.yield_m, self.patience_s, self.walk_on_s = yield_m, patience_s, walk_on_s
        self._yielding: tuple[float, Pose2D] | None = None  # since when, and where the robot was then
        self._walk_on_until = -math.inf

    def _desired(self, now: float, me: Pose2D, seen: Seen | None) -> Point:
        robot = seen.percept.robot if seen is not None else None
        shown = intent_ways(seen.percept) if seen is not None else []
        reach = self.yield_m * (2.0 if shown else 1.0)
        ahead = (
            robot is not None
            and math.hypot(robot.x - me.x, robot.y - me.y) < reach
            and ahead_of(me, (robot.x, robot.y), math.radians(70))
        )
        if robot is None or not ahead or now < self._walk_on_until:
            self._yielding = None
            return self._react(now, me, self._task(now, me), seen)
        if self._yielding is None:
            self._yielding = (now, robot)
        since, robot_then = self._yielding
        waits = seen is not None and waits_for_me(seen.percept)  # it says so in its thought bubble
        if waits or (now - since >= self.patience_s and robot.distance_to(robot_then) < 0.1):
            self._walk_on_until, self._yielding = now + self.walk_on_s, None  # the robot waits for us: go on
            return self._task(now, me)
        side = -1.0  # right, unless the shown way lies to the right
        if shown:
            left = (-math.sin(me.yaw), math.cos(me.yaw))
            side = (
                1.0
                if sum((p[0] - me.x) * left[0] + (p[1] - me.y) * left[1] for way in shown for p in way) < 0.0
                else -1.0
            )
        away = (-side * math.sin(me.yaw), side * math.cos(me.yaw))
        # to the wall, body and margin off
        room = self.planner.free_run((me.x, me.y), away, 1.0) - HUMAN_BODY.radius_m - 0.05
        step = min(0.4, max(0.0, 2.0 * room))
        return (away[0] * step, away[1] * step)


def in_session(scenario: Scenario, person_seed: int, session_trial: int) -> Scenario:
    """The scenario with its simulated people as one study participant at one place in their
    session: the same `person_seed` on every trial of theirs (the same people), `session_trial`
    their trial's position (they learn). Several simulated humans stay different people: each
    one's draw also depends on their id (`person.individual`)."""

    def one(h: HumanTask) -> HumanTask:
        return (
            h
            if h.teleoperated
            else replace(h, params=replace(h.params, person_seed=person_seed, session_trial=session_trial))
        )

    return replace(scenario, humans=tuple(one(h) for h in scenario.humans))
