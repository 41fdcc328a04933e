"""Simulated participants for unattended trials, as velocity commands for /humans/<id>/cmd_vel.

  * `Walker`: walks its task (room centres in order, or the human gems, standing on each for the
    dwell time) along planned paths, with seeded variation in speed and, for gems, in route;
  * `Blocker`: a walker that first steps into the robot's projected path a few metres ahead of the
    robot and stands there a while (the case that makes HAVEN's robot wait or detour);
  * `Yielder`: a walker that stops and steps aside when the robot comes close in front of it.

They see what a participant sees: the robot's pose and its projected path, and the other people.
All of them move by the social-force model (`social_force`): their task gives a desired velocity,
walls, people and the robot push them off it, and they never close in on the robot.
"""

from __future__ import annotations

import math
import random
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Protocol

from haven_scenarios.study.social_force import Body, SocialForce, robot_body
from haven_sim.common.bodies import HUMAN_BODY
from haven_sim.common.geometry import Point, Pose2D, Twist2D, wrap_angle
from haven_sim.nav.planner import Planner, PlannerParams, PlanningError

# How a simulated participant plans their own walks: their body, a little margin, generous snapping.
CLOSE_ENOUGH_M = 0.3  # a stop the person cannot get nearer to than this (someone beside it) counts as reached
ROBOT_ON_STOP_M = 0.6  # the robot this close to a stop stands on it
HUMAN_PLANNER = PlannerParams(safety_margin_m=0.05, snap_radius_m=0.5, body_radius_m=HUMAN_BODY.radius_m)


class Participant(Protocol):
    """A simulated participant model: a velocity for /humans/<id>/cmd_vel from what they see."""

    id: str
    done: bool  # their task is finished

    def command(self, now: float, me: Pose2D, robot: Pose2D, robot_path: Sequence[Pose2D], others: Sequence[Pose2D] = ()) -> Twist2D: ...


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

    def __init__(self, human_id: str, stops: Sequence[Stop], planner: Planner, speed_mps: float = 1.0, seed: int = 0) -> None:
        self.id = human_id
        self.rng = random.Random(seed)
        self.speed = speed_mps * self.rng.uniform(0.85, 1.15)
        self.stops = list(stops)
        self.planner = planner
        self.crowd = SocialForce(planner.free_run)
        self._waypoints: list[Point] = []
        self._arrived_at: float | None = None
        self._progress_mark: tuple[float, float] | None = None  # (when, distance to the waypoint) at the last progress
        self._last: tuple[float, Pose2D] | None = None  # (when, the robot's pose) at the last tick
        self._dt = 0.1
        self._others: Sequence[Pose2D] = ()  # the other people, as of this tick
        self._robot: Pose2D | None = None  # the robot, as of this tick
        self.done = not self.stops

    def command(self, now: float, me: Pose2D, robot: Pose2D, robot_path: Sequence[Pose2D], others: Sequence[Pose2D] = ()) -> Twist2D:
        self._others, self._robot = others, robot
        return self._move(now, me, robot, others, self._desired(now, me, robot, robot_path))

    def _desired(self, now: float, me: Pose2D, robot: Pose2D, robot_path: Sequence[Pose2D]) -> Point:
        """The velocity the person wants (world frame), before the social forces."""
        return self._task(now, me)

    # -- moving ------------------------------------------------------------------------------------
    def _move(self, now: float, me: Pose2D, robot: Pose2D, others: Sequence[Pose2D], desired: Point) -> Twist2D:
        """The social-force step from the desired velocity, as a command in the person's frame."""
        rvx = rvy = 0.0
        if self._last is not None and now > self._last[0]:
            self._dt = min(0.5, now - self._last[0])
            rvx, rvy = (robot.x - self._last[1].x) / self._dt, (robot.y - self._last[1].y) / self._dt
        self._last = (now, robot)
        bodies = [robot_body(robot.x, robot.y, rvx, rvy)] + [Body(o.x, o.y, 0.0, 0.0, HUMAN_BODY.radius_m) for o in others]
        vx, vy = self.crowd.step((me.x, me.y), desired, bodies, self._dt)
        return self._twist(me, (vx, vy), desired)

    def _twist(self, me: Pose2D, v: Point, desired: Point) -> Twist2D:
        """World velocity `v` as a command in the person's own frame, turning to face where they
        go. The command holds for the tick, so it is aimed along the heading they will have half-way
        through, or the walk would curl as they turn."""
        face = v if math.hypot(*v) > 0.1 else desired
        wz = max(-3.0, min(3.0, 2.0 * wrap_angle(math.atan2(face[1], face[0]) - me.yaw))) if math.hypot(*face) > 1e-3 else 0.0
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
        if d <= stop.reach_m or self._arrived_at is not None and d <= self._close_enough(stop):
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
            if self._contested(stop) and len(self.stops) > 1 and self.rng.random() < 0.5:
                self.stops.append(self.stops.pop(0))  # others are going for it: come back to it later
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
        held = robot is not None and stop.dwell_s == 0.0 and math.hypot(stop.x - robot.x, stop.y - robot.y) < ROBOT_ON_STOP_M
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
    """Walks (along a planned path, round walls) onto the robot's projected path `ahead_m` in front
    of the robot, stands `block_s`, then goes about its task; gives the block up if the spot
    cannot be reached within `give_up_s`."""

    def __init__(self, *args: object, ahead_m: float = 3.0, block_s: float = 8.0, give_up_s: float = 30.0, **kwargs: object) -> None:
        super().__init__(*args, **kwargs)  # type: ignore[arg-type]
        self.ahead_m, self.block_s, self.give_up_s = ahead_m, block_s, give_up_s
        self._spot: Point | None = None
        self._route: list[Point] = []  # planned waypoints to the spot
        self._spot_since = 0.0
        self._blocking_since: float | None = None
        self.blocked = False

    def _choose_spot(self, now: float, me: Pose2D, robot: Pose2D, robot_path: Sequence[Pose2D]) -> None:
        walked = 0.0
        for a, b in zip(robot_path, robot_path[1:]):
            walked += math.hypot(b.x - a.x, b.y - a.y)
            if walked >= self.ahead_m and math.hypot(b.x - robot.x, b.y - robot.y) >= self.ahead_m * 0.8:
                try:
                    self._route = self.planner.plan((me.x, me.y), (b.x, b.y)).points[1:]
                except PlanningError:
                    return
                self._spot, self._spot_since = (b.x, b.y), now
                return

    def _desired(self, now: float, me: Pose2D, robot: Pose2D, robot_path: Sequence[Pose2D]) -> Point:
        if self.blocked:
            return self._task(now, me)
        if self._spot is None and len(robot_path) >= 2:
            self._choose_spot(now, me, robot, robot_path)
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
    """Stops and steps to its right, as far as the wall allows, when the robot is within `yield_m`
    in front of it. If the robot does not move on for `patience_s` (it waits for them in turn),
    the person walks on past it for `walk_on_s`: nobody waits for ever."""

    def __init__(self, *args: object, yield_m: float = 1.5, patience_s: float = 4.0, walk_on_s: float = 6.0, **kwargs: object) -> None:
        super().__init__(*args, **kwargs)  # type: ignore[arg-type]
        self.yield_m, self.patience_s, self.walk_on_s = yield_m, patience_s, walk_on_s
        self._yielding: tuple[float, Pose2D] | None = None  # since when, and where the robot was then
        self._walk_on_until = -math.inf

    def _desired(self, now: float, me: Pose2D, robot: Pose2D, robot_path: Sequence[Pose2D]) -> Point:
        dx, dy = robot.x - me.x, robot.y - me.y
        ahead = math.hypot(dx, dy) < self.yield_m and abs(wrap_angle(math.atan2(dy, dx) - me.yaw)) < math.radians(70)
        if not ahead or now < self._walk_on_until:
            self._yielding = None
            return self._task(now, me)
        if self._yielding is None:
            self._yielding = (now, robot)
        since, robot_then = self._yielding
        if now - since >= self.patience_s and robot.distance_to(robot_then) < 0.1:
            self._walk_on_until, self._yielding = now + self.walk_on_s, None  # the robot waits for us: go on
            return self._task(now, me)
        right = (math.sin(me.yaw), -math.cos(me.yaw))
        room = self.planner.free_run((me.x, me.y), right, 1.0) - HUMAN_BODY.radius_m - 0.05  # to the wall, body and margin off
        step = min(0.4, max(0.0, 2.0 * room))
        return (right[0] * step, right[1] * step)


MODELS: dict[str, type[Walker]] = {"walker": Walker, "blocker": Blocker, "yielder": Yielder}


def make_walker(model: str, human_id: str, stops: Sequence[Stop], planner: Planner, speed_mps: float, seed: int) -> Participant:
    """A simulated participant of the named model (the names a scenario file uses)."""
    return MODELS[model](human_id, stops, planner, speed_mps, seed)
