"""How a simulated person moves among walls, other people and the robot: a social-force model.

Helbing & Molnár (1995): a person accelerates toward their desired velocity with relaxation time
`relax_s` and is pushed away from others and from walls by forces that fall off exponentially with
the gap between bodies, weaker for what is behind them (anisotropy `lambda_`, Helbing et al. 2000).
Like Zanlungo, Ikeda & Kanda (2011), the push from a moving body is evaluated where the two would
be closest within `horizon_s`, so people start avoiding each other (and the robot) early rather than
at arm's length, and, as pedestrians do, they keep to the right of someone coming the other way
(`keep_right`). Two hard rules on top, because a simulated participant must not be the cause of a
contact: the velocity never closes in on the robot within `personal_m` of touching it, and slides
along a wall rather than into it.

(pysocialforce on PyPI implements the same model for crowds but is unmaintained and pins numba;
a few dozen lines of numpy cover one or two people here.)
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Protocol, overload

import numpy as np

from haven_sim.common.bodies import HUMAN_BODY
from haven_sim.common.geometry import FloatArray, Point


class RayFn(Protocol):
    """Free distance from a point along a unit direction to the walls (the planner's `free_run`);
    given an (N, 2) array of directions, the N distances at once."""

    @overload
    def __call__(self, start: Point, direction: Point, max_m: float = 10.0) -> float: ...

    @overload
    def __call__(self, start: Point, direction: FloatArray, max_m: float = 10.0) -> FloatArray: ...


RAYS = 16  # directions sampled for walls
WALL_STOP_S = 0.1  # the slide rule stops motion into a wall this many seconds (at the current speed) before wall_stop_m
RAY_MARGIN_M = 0.1  # rays go this much further than a wall can matter (a gap at the limit is not rounded below it)
# Their unit vectors, computed once (as the loop over k did: the same floats).
_RAY_UNITS = [(math.cos(2.0 * math.pi * k / RAYS), math.sin(2.0 * math.pi * k / RAYS)) for k in range(RAYS)]
_RAY_DIRS = np.array(_RAY_UNITS)


@dataclass(frozen=True)
class Body:
    """Another body a person reacts to: where it is, how it moves (world frame) and its radius."""

    x: float
    y: float
    vx: float
    vy: float
    radius_m: float
    robot: bool = False


@dataclass(frozen=True)
class SocialForceParams:
    relax_s: float = 0.5  # Helbing & Molnar 1995
    agent_strength: float = 1.2  # m/s^2 at touching distance, for another person
    agent_range_m: float = 0.3
    robot_strength: float = 2.5  # people keep further from a robot
    robot_range_m: float = 0.45
    lambda_: float = 0.35  # weight of what is behind
    horizon_s: float = 2.5  # how far ahead a person predicts the closest approach
    wall_strength: float = 4.0
    wall_range_m: float = 0.12
    wall_look_m: float = 1.0
    keep_right: float = 0.6  # m/s^2 sideways, for someone coming the other way within `oncoming_m`
    oncoming_m: float = 6.0
    personal_m: float = 0.25  # never close in on the robot within this gap of touching it
    wall_stop_m: float = 0.03
    max_speed_factor: float = 1.3


def _unit(x: float, y: float) -> tuple[float, float, float]:
    n = math.hypot(x, y)
    return (x / n, y / n, n) if n > 1e-9 else (0.0, 0.0, 0.0)


class SocialForce:
    """One person's velocity, stepped at the participant's tick."""

    def __init__(
        self, free_run: RayFn, params: SocialForceParams | None = None, radius_m: float = HUMAN_BODY.radius_m
    ) -> None:
        self.free_run = free_run
        self.p = params or SocialForceParams()
        self.radius = radius_m
        self.v = (0.0, 0.0)

    def step(self, me: Point, desired: Point, others: Sequence[Body], dt: float, guard: Sequence[Body] = ()) -> Point:
        """The new world-frame velocity for `dt`, given the desired velocity and the bodies around
        (as the person perceives them); `guard`: bodies that only the hard rules see (the robot where
        it really is, which the person must never close in on, perceived or not)."""
        p = self.p
        ax = (desired[0] - self.v[0]) / p.relax_s
        ay = (desired[1] - self.v[1]) / p.relax_s
        dx_, dy_, speed0 = _unit(*desired)
        heading = (dx_, dy_) if speed0 > 0 else _unit(*self.v)[:2]
        for b in others:
            fx, fy = self._agent(me, heading, b)
            ax, ay = ax + fx, ay + fy
        cap = max(speed0, 0.3) * p.max_speed_factor
        rays = self._rays(me, cap)
        fx, fy = self._walls(rays)
        vx, vy = self.v[0] + (ax + fx) * dt, self.v[1] + (ay + fy) * dt
        ux, uy, n = _unit(vx, vy)
        if n > cap:
            vx, vy = ux * cap, uy * cap
        vx, vy = self._hard_rules(me, (vx, vy), [*others, *guard], rays)
        self.v = (vx, vy)
        return self.v

    def _agent(self, me: Point, heading: Point, b: Body) -> Point:
        p = self.p
        rx, ry = me[0] - b.x, me[1] - b.y  # from them to me
        rvx, rvy = self.v[0] - b.vx, self.v[1] - b.vy
        rv2 = rvx * rvx + rvy * rvy
        t = 0.0 if rv2 < 1e-9 else min(p.horizon_s, max(0.0, -(rx * rvx + ry * rvy) / rv2))
        px, py = rx + rvx * t, ry + rvy * t  # the separation at the closest approach
        nx, ny, d = _unit(px, py)
        if d == 0.0:
            nx, ny, d = _unit(rx, ry)
        gap = d - self.radius - b.radius_m
        strength, reach = (p.robot_strength, p.robot_range_m) if b.robot else (p.agent_strength, p.agent_range_m)
        mag = strength * math.exp(-gap / reach) / (1.0 + t)
        cos_phi = -(nx * heading[0] + ny * heading[1])  # they lie ahead of me: cos_phi > 0
        w = p.lambda_ + (1.0 - p.lambda_) * (1.0 + cos_phi) / 2.0
        fx, fy = mag * w * nx, mag * w * ny
        # Keep right of someone coming the other way.
        dist = math.hypot(rx, ry)
        oncoming = b.vx * heading[0] + b.vy * heading[1] < -0.1 or b.robot
        if oncoming and dist < p.oncoming_m and cos_phi > 0.5:
            fx += p.keep_right * heading[1] * (1.0 - dist / p.oncoming_m)
            fy -= p.keep_right * heading[0] * (1.0 - dist / p.oncoming_m)
        return fx, fy

    def _rays(self, me: Point, cap: float) -> list[tuple[float, float, float]]:
        """(direction x, direction y, gap from my body to the wall) for `RAYS` directions, cast only
        as far as a wall can matter: the wall force's reach, or where the slide rule starts at the
        top speed `cap` (the velocity never exceeds it). A gap beyond that changes nothing, so the
        person moves exactly as with rays to the far wall (10 m)."""
        p = self.p
        reach = max(p.wall_look_m, p.wall_stop_m + cap * WALL_STOP_S) + RAY_MARGIN_M
        gaps = (self.free_run(me, _RAY_DIRS, self.radius + reach) - self.radius).tolist()
        return [(c, s, g) for (c, s), g in zip(_RAY_UNITS, gaps, strict=True)]

    def _walls(self, rays: Sequence[tuple[float, float, float]]) -> Point:
        p = self.p
        fx = fy = 0.0
        for c, s, gap in rays:
            if gap < p.wall_look_m:
                mag = p.wall_strength * math.exp(-max(gap, 0.0) / p.wall_range_m) * 4.0 / RAYS
                fx, fy = fx - mag * c, fy - mag * s
        return fx, fy

    def _hard_rules(
        self, me: Point, v: Point, others: Sequence[Body], rays: Sequence[tuple[float, float, float]]
    ) -> Point:
        vx, vy = v
        for b in others:
            if not b.robot:
                continue
            ux, uy, d = _unit(me[0] - b.x, me[1] - b.y)  # away from the robot
            if d == 0.0 or d - self.radius - b.radius_m > self.p.personal_m:
                continue
            toward = -(vx * ux + vy * uy)
            if toward > 0:  # drop the part of the motion that closes in on the robot
                vx, vy = vx + toward * ux, vy + toward * uy
        for c, s, gap in rays:  # slide along walls, never into them
            into = vx * c + vy * s
            if into > 0 and gap < self.p.wall_stop_m + into * WALL_STOP_S:
                vx, vy = vx - into * c, vy - into * s
        return vx, vy


def robot_body(x: float, y: float, vx: float, vy: float, radius_m: float) -> Body:
    return Body(x, y, vx, vy, radius_m, robot=True)
