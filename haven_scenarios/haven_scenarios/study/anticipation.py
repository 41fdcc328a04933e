"""How a simulated participant uses what they perceive: a delay line, reading the robot's intent, and
adjusting the walk they want.

  * `DelayLine`: a person acts on what they perceived one reaction time ago (`PersonParams.reaction_s`),
    the robot's motion included: its velocity is what they saw it move between two observations.
  * `intent_ways`: where the robot will go, as far as the cues show it: from a lit turn signal, a
    short curve off the robot's heading to that side, and the projected-path markers the person sees.
    Nothing without a cue: the robot's motion alone does not say where it will turn.
  * `keep_clear`: a person who sees the robot's way ahead along their own (head-on or overtaking)
    moves to the far side of it early, to keep `pass_gap_m` between their body and the robot's; one
    whose way the shown path crosses times it and gives way early when the robot gets there first.
  * `hesitant`: a person who cannot read the robot's intent slows when it closes in, in their way.
  * `waits_for_me`: the thought bubble, read, says the robot waits for the person to pass.
"""

from __future__ import annotations

import itertools
import math
from collections import deque
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from haven_scenarios.study.mission import WAITING_THOUGHT
from haven_scenarios.study.perception import Percept, ahead_of
from haven_scenarios.study.person import PersonParams
from haven_sim.common.bodies import HUMAN_BODY
from haven_sim.common.geometry import Point, Pose2D

RayFn = Callable[[Point, Point], float]  # free distance from a point along a unit direction (walls)
SIGNAL_TURN_RAD = math.radians(35.0)  # the curve a lit turn signal announces (HAVEN lights it from 11 deg)
SIGNAL_REACH_M = (0.6, 1.2, 1.8, 2.4, 3.0)  # ... read this far along
ALONG_COS = 0.7  # a path segment within ~45 deg of the person's way (or against it) runs along it
ROBOT_MIN_MPS = 0.15  # a robot slower than this is not judged to arrive anywhere soon
CONFLICT_S = 2.0  # arrivals at a crossing this close (plus two reaction times) conflict
CLOSING_MPS = 0.05  # a robot closing in faster than this approaches
WALL_MARGIN_M = 0.05
STRIDE_M = 1.0
SIDESTEP_GAIN = 1.2  # 1/s: how briskly a person takes up the lateral offset they want


def clearance_m(params: PersonParams, robot_radius_m: float) -> float:
    """Centre-to-centre lateral distance a person keeps from the way of a robot of this size."""
    return params.pass_gap_m + HUMAN_BODY.radius_m + robot_radius_m


@dataclass(frozen=True)
class Seen:
    """A percept as acted on, with the robot's velocity as seen (zero when it was not seen twice)."""

    percept: Percept
    robot_v: Point = (0.0, 0.0)


class DelayLine:
    """Percepts in, each handed back `delay_s` later (the perception-response time)."""

    def __init__(self, delay_s: float) -> None:
        self.delay_s = delay_s
        self._queue: deque[Seen] = deque()
        self._last: Seen | None = None  # the newest seen so far, with the robot
        self._current: Seen | None = None

    def push(self, p: Percept) -> None:
        v = (0.0, 0.0)
        last = self._last
        if p.robot is not None and last is not None and last.percept.robot is not None and p.stamp > last.percept.stamp:
            dt = p.stamp - last.percept.stamp
            v = ((p.robot.x - last.percept.robot.x) / dt, (p.robot.y - last.percept.robot.y) / dt)
        seen = Seen(p, v)
        if p.robot is not None:
            self._last = seen
        self._queue.append(seen)

    def acted_on(self, now: float) -> Seen | None:
        """The newest percept at least `delay_s` old (None before the first one is)."""
        while self._queue and self._queue[0].percept.stamp <= now - self.delay_s + 1e-9:
            self._current = self._queue.popleft()
        return self._current


def intent_ways(p: Percept) -> list[list[Point]]:
    """Where the cues say the robot goes, each way nearest the robot first: a lit signal's curve
    off the robot, the seen projected path and the ways other cues show; none without a cue."""
    ways = ([list(p.path)] if p.path else []) + [list(w) for w in p.ways]
    if p.signal != 0 and p.robot is not None:
        r = p.robot
        yaw = r.yaw + p.signal * SIGNAL_TURN_RAD
        ways.insert(0, [(r.x + s * math.cos(yaw), r.y + s * math.sin(yaw)) for s in SIGNAL_REACH_M])
    return ways


def _unit(v: Point) -> tuple[float, float, float]:
    n = math.hypot(*v)
    return (v[0] / n, v[1] / n, n) if n > 1e-9 else (0.0, 0.0, 0.0)


def _read(
    me: Pose2D, way: tuple[float, float], points: Sequence[Point], params: PersonParams, c: float
) -> tuple[list[float], tuple[float, int] | None]:
    """Of one shown way: the lateral offsets of its points ahead of me that run along my way (or
    against it), and (how far ahead, index) of the first point that crosses my way."""
    hx, hy = way
    along: list[float] = []
    for i, p in enumerate(points):
        dx, dy = p[0] - me.x, p[1] - me.y
        ahead, lateral = dx * hx + dy * hy, -dx * hy + dy * hx
        if not 0.0 < ahead < params.anticipate_m:
            continue
        a, b = (p, points[i + 1]) if i + 1 < len(points) else (points[max(i - 1, 0)], p)
        tx, ty, n = _unit((b[0] - a[0], b[1] - a[1]))
        if n == 0.0 or abs(tx * hx + ty * hy) >= ALONG_COS:
            along.append(lateral)
        elif abs(lateral) < c:
            return along, (ahead, i)
    return along, None


def keep_clear(
    me: Pose2D,
    task: Point,
    ways: Sequence[Sequence[Point]],
    seen: Seen,
    params: PersonParams,
    free_run: RayFn,
    side: float = 0.0,
) -> tuple[Point, float] | None:
    """The walk `task` adjusted for the robot's shown ways (`intent_ways`) and the side (+1 my left,
    -1 my right) it passes them on, or None when they do not bother this person. `side`: the side
    already chosen (a person who has picked a side keeps it, though a signal flickers), 0 for none."""
    hx, hy, speed = _unit(task)
    if speed == 0.0:
        return None
    c = clearance_m(params, seen.percept.robot_radius_m)
    along: list[float] = []
    for points in ways:
        lateral, crossing = _read(me, (hx, hy), points, params, c)
        along += lateral
        if crossing is not None and not (along and min(abs(a) for a in along) < c):
            slowed = _give_way(task, crossing, points, seen, params)
            return None if slowed is None else (slowed, 0.0)
    close = [a for a in along if abs(a) < c]
    if not close:
        return None
    side = side or (-1.0 if sum(close) >= 0.0 else 1.0)  # the way to my left (or dead ahead): go right
    return _sidestep(me, (hx, hy, speed), close, c, side, free_run), side


def _sidestep(
    me: Pose2D, way: tuple[float, float, float], close: list[float], c: float, side: float, free_run: RayFn
) -> Point:
    """Move to `side` of the robot's way, `c` from its points that are `close` (lateral offsets)."""
    hx, hy, speed = way
    need = max(0.0, max(c + side * a for a in close))
    sx, sy = side * -hy, side * hx
    # The room to that side here and a stride ahead (no stepping round a corner into the wall beyond it).
    free = min(free_run((me.x, me.y), (sx, sy)), free_run((me.x + hx * STRIDE_M, me.y + hy * STRIDE_M), (sx, sy)))
    room = max(0.0, free - HUMAN_BODY.radius_m - WALL_MARGIN_M)
    shift = min(need, room)
    lat = min(speed, SIDESTEP_GAIN * shift)
    vx, vy = hx * speed + sx * lat, hy * speed + sy * lat
    scale = speed / max(math.hypot(vx, vy), 1e-9)
    return (vx * scale, vy * scale)


def _give_way(
    task: Point, crossing: tuple[float, int], points: Sequence[Point], seen: Seen, params: PersonParams
) -> Point | None:
    """The shown path crosses my way: slow early when the robot gets there first, else walk on."""
    robot = seen.percept.robot
    if robot is None:
        return None
    ahead, i = crossing
    along = math.hypot(points[0][0] - robot.x, points[0][1] - robot.y)
    along += sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in itertools.pairwise(points[: i + 1]))
    robot_speed = max(math.hypot(*seen.robot_v), ROBOT_MIN_MPS)
    mine = ahead / max(math.hypot(*task), 1e-9)
    theirs = along / robot_speed
    if theirs < mine and mine - theirs < CONFLICT_S + 2.0 * params.reaction_s:
        return (task[0] * params.hesitate_factor, task[1] * params.hesitate_factor)
    return None


def hesitant(me: Pose2D, task: Point, seen: Seen, params: PersonParams, half_fov_rad: float) -> bool:
    """The robot, seen in front within `hesitate_m`, closes in and is in my way."""
    r = seen.percept.robot
    if r is None or math.hypot(*task) < 1e-6:
        return False
    dx, dy = me.x - r.x, me.y - r.y
    d = math.hypot(dx, dy)
    if d > params.hesitate_m or d < 1e-6 or not ahead_of(me, (r.x, r.y), half_fov_rad):
        return False
    closing = (seen.robot_v[0] * dx + seen.robot_v[1] * dy) / d
    hx, hy, _ = _unit(task)
    lateral = abs(dx * hy - dy * hx)  # the robot's offset from my way
    return closing > CLOSING_MPS and lateral < clearance_m(params, seen.percept.robot_radius_m)


def waits_for_me(p: Percept) -> bool:
    """The robot's thought bubble, seen, says it waits for the person to pass."""
    return p.thought == WAITING_THOUGHT
