"""What one simulated participant perceives at one moment: the robot and the AR cues they can see.

A cue is perceived only when it is on in the condition and has something to show now (as the viz
publishes it on /haven/cue_state, `haven_viz.cues.CueState`), and where it is shown lies within the
person's field of view and viewing distance (`person.PersonParams`) with no wall in between (line of
sight on the occupancy grid). The robot itself is seen by the same rule; the turn signal, thought
bubble and battery gauge are drawn on the robot, so they are seen only with it. Of the projected path,
the person sees the markers the projection shows (the first `path_markers` ahead of the robot) that
pass the same test, never the whole plan. A lab's cue (`haven_viz.cue_kind`) is perceived by the same
rule: where it shows the robot's way (`Shown.way`), drawn on the robot (seen with it) or on the floor
(the points seen); its value and the way seen are in the percept (`shown`, `ways`), and the simulated
participants read that way as they read the projected path.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from haven_scenarios.study.person import PersonParams
from haven_sim.common.geometry import Point, Pose2D, wrap_angle
from haven_sim.robots.fields import DEFAULT
from haven_sim.sim.occupancy import OccupancyGridData
from haven_viz.cues import BATTERY_NS, PATH_NS, SIGNAL_NS, THOUGHT_NS, ArCues, CueState

OCCUPIED = 50  # an occupancy value this high is a wall (nav_msgs/OccupancyGrid)
BY_FIELD = frozenset({PATH_NS, SIGNAL_NS, THOUGHT_NS, BATTERY_NS})  # HAVEN's cues: a field of the percept each
Ways = Mapping[str, tuple[tuple[Point, ...], bool]]  # cue -> (the way it shows, drawn on the robot)


@dataclass(frozen=True)
class Percept:
    """What a person perceives at `stamp`: the robot (None when out of sight) and the cues they see."""

    stamp: float
    robot: Pose2D | None = None
    path: tuple[Point, ...] = ()  # projected-path markers seen, nearest the robot first
    signal: int = 0  # +1 the robot's left, -1 its right, 0 dark or not seen
    thought: str = ""
    battery: float | None = None
    ways: tuple[tuple[Point, ...], ...] = ()  # the robot's way as other cues show it, the parts seen
    shown: Mapping[str, Any] = field(default_factory=dict)  # other cues seen: cue -> its value
    # the robot's size (its footprint's enclosing circle), as anyone can see it
    robot_radius_m: float = DEFAULT.radius_m

    @property
    def intent_shown(self) -> bool:
        """The robot's way ahead is shown to this person (its projected path, a lit turn signal or another cue's
        way)."""
        return bool(self.path) or self.signal != 0 or bool(self.ways)


@functools.lru_cache(maxsize=256)
def _fractions(k: int) -> np.ndarray:
    """np.linspace(0, 1, k), made once per k (read-only, as it is shared)."""
    out = np.linspace(0.0, 1.0, k)
    out.setflags(write=False)
    return out


class Sight:
    """Lines of sight on an occupancy grid: walls (not unknown space) block them."""

    def __init__(self, grid: OccupancyGridData) -> None:
        self.grid = grid
        self.walls = np.asarray(grid.data) >= OCCUPIED

    def clear(self, eye: Point, targets: np.ndarray) -> np.ndarray:
        """For each target (N, 2): no wall cell between `eye` and it (sampled at the grid's
        resolution, all rays at once)."""
        targets = np.asarray(targets, dtype=float).reshape(-1, 2)
        if len(targets) == 0:
            return np.zeros(0, dtype=bool)
        g = self.grid
        delta = targets - np.asarray(eye, dtype=float)
        lengths = np.hypot(delta[:, 0], delta[:, 1])
        k = max(2, math.ceil(float(lengths.max()) / g.resolution_m) + 1)
        frac = _fractions(k)
        xs = eye[0] + delta[:, :1] * frac  # (N, k)
        ys = eye[1] + delta[:, 1:] * frac
        cols = np.floor((xs - g.origin_x) / g.resolution_m).astype(np.intp)
        rows = np.floor((ys - g.origin_y) / g.resolution_m).astype(np.intp)
        inside = (rows >= 0) & (rows < g.height) & (cols >= 0) & (cols < g.width)
        blocked = np.where(inside, self.walls[np.clip(rows, 0, g.height - 1), np.clip(cols, 0, g.width - 1)], True)
        blocked[:, 0] = False  # the eye's own cell (a person brushing a wall still sees)
        return ~blocked.any(axis=1)


def in_view(params: PersonParams, me: Pose2D, points: np.ndarray) -> np.ndarray:
    """Which points (N, 2) lie within the field of view and viewing distance."""
    points = np.asarray(points, dtype=float).reshape(-1, 2)
    dx, dy = points[:, 0] - me.x, points[:, 1] - me.y
    near = np.hypot(dx, dy) <= params.view_m
    if params.fov_deg >= 360.0:
        return near
    bearing = np.arctan2(dy, dx) - me.yaw
    off = np.abs((bearing + math.pi) % (2.0 * math.pi) - math.pi)
    return near & (off <= math.radians(params.fov_deg) / 2.0)


def seen(params: PersonParams, sight: Sight, me: Pose2D, points: np.ndarray) -> np.ndarray:
    """In view and in line of sight (the wall test only for what is in view)."""
    ok = in_view(params, me, points)
    if ok.any():
        ok[ok] = sight.clear((me.x, me.y), np.asarray(points, dtype=float).reshape(-1, 2)[ok])
    return ok


def sees(params: PersonParams, sight: Sight, me: Pose2D, point: Point) -> bool:
    """`seen` for one point (plain arithmetic first: most of the time it is out of view)."""
    d = math.hypot(point[0] - me.x, point[1] - me.y)
    if d > params.view_m:
        return False
    if params.fov_deg < 360.0 and d > 0.0 and not ahead_of(me, point, math.radians(params.fov_deg) / 2.0):
        return False
    return bool(sight.clear((me.x, me.y), np.array([point]))[0])


def perceive(
    params: PersonParams,
    sight: Sight,
    now: float,
    me: Pose2D,
    robot: Pose2D,
    cues: CueState | None,
    markers: Sequence[Point] = (),
    ways: Ways | None = None,
    robot_radius_m: float = DEFAULT.radius_m,
) -> Percept:
    """What the person at `me` perceives. `markers`: the projected path's markers ahead of the
    robot, nearest first, and `ways`: the other cues' ways (the director lays them out as the viz
    does); `cues`: what the viz shows now (None before its first message: nothing)."""
    robot_seen = sees(params, sight, me, (robot.x, robot.y))
    if cues is None:
        return Percept(now, robot if robot_seen else None, robot_radius_m=robot_radius_m)
    path: tuple[Point, ...] = ()
    shown = list(markers[: cues.path_markers]) if cues.toggles.on(PATH_NS) else []
    if shown:
        visible = seen(params, sight, me, np.array(shown))
        path = tuple(p for p, v in zip(shown, visible, strict=True) if v)
    seen_ways, values = [], {}
    for cue, (way, on_robot) in (ways or {}).items():
        if not (cues.toggles.on(cue) and cues.shown(cue)):
            continue
        part = (
            (way if robot_seen else ())
            if on_robot
            else tuple(p for p, v in zip(way, seen(params, sight, me, np.array(way)), strict=True) if v)
        )
        if part:
            seen_ways.append(part)
            values[cue] = cues.value(cue)
    if not robot_seen:
        return Percept(now, None, path, ways=tuple(seen_ways), shown=values, robot_radius_m=robot_radius_m)
    t = cues.toggles
    return Percept(
        now,
        robot,
        path,
        cues.turn_signal if t.on(SIGNAL_NS) else 0,
        cues.thought if t.on(THOUGHT_NS) else "",
        cues.battery_level if t.on(BATTERY_NS) else None,
        tuple(seen_ways),
        values,
        robot_radius_m,
    )


def cue_ways(
    cues: ArCues,
    state: CueState | None,
    robot: Pose2D,
    humans: Sequence[Point],
    level: float | None,
    thought: str,
    now: float,
) -> Ways:
    """Where the cues in `cues` (laid out as the viz does) that show something now say the robot
    goes (only while one of them is on show)."""
    if state is None or not any(state.shown(c) for c in cues.cues):
        return {}
    return cues.frame(robot, humans, level, thought, state.toggles, now, markers=False).ways


def ahead_of(me: Pose2D, point: Point, half_angle_rad: float) -> bool:
    """Whether `point` lies within `half_angle_rad` of the person's heading."""
    return abs(wrap_angle(math.atan2(point[1] - me.y, point[0] - me.x) - me.yaw)) <= half_angle_rad
