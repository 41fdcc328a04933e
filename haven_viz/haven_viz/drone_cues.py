"""The drone's intent cues of Walker, Hedayati, Lee & Szafir, "Communicating Robot Motion Intent with
Augmented Reality", HRI '18 (ACM/IEEE International Conference on Human-Robot Interaction, 2018,
pp. 316-324, doi:10.1145/3171221.3171253), as `haven.cues` plugins for aerial robots only
(`kinematics = ("aerial",)`: a robot of another kind has none of them):

  * NavPoints (`nav_points`): the next `nav_points_ahead` waypoints of the remaining path (its
    corners, every `nav_point_spacing_m` along it between them, and its end) as spheres at flight height, joined by a
    line from the robot, each with a countdown of its estimated arrival in seconds (distance along the path / the
    robot's cruise speed);
  * Arrow (`arrow`): one 3D arrow on the robot pointing at the next waypoint;
  * Gaze (`gaze`): an eye on the robot (a white ball and a dark pupil) looking at the point
    `gaze_lookahead_m` ahead along the path.

Their parameters are in `builtin_cues.CueParams` with HAVEN's. The simulated participants read
NavPoints' points where they are drawn, and the Arrow's and Gaze's target with the robot.
"""

from __future__ import annotations

import math

from haven_viz.builtin_cues import SCHEMES, CueParams
from haven_viz.cue_kind import CueContext, Shown, TrackedPath
from haven_viz.markers import MarkerSpec, Shape

NAV_NS, ARROW_NS, GAZE_NS = "nav_points", "arrow", "gaze"
AERIAL = ("aerial",)  # the robot kinds these cues serve (haven_sim.robots.description.Kinematics)
TEXT_COLOUR = (0.05, 0.05, 0.05, 1.0)
EYE_RADIUS_M = 0.08  # the Gaze eye's ball (ours: legible at a few metres, about a third of the drone's width)
PUPIL_RADIUS_M = 0.04
CORNER_TOLERANCE_M = 0.1  # a path simplified to within this (a grid planner's cell wiggle is smaller) ...
CORNER_DEG = 30.0  # ... has a corner where it turns by this much (ours)


def _simplify(xy: list[tuple[float, float]], lo: int, hi: int, out: list[int]) -> None:
    """Ramer-Douglas-Peucker: the indices strictly between lo and hi of the points kept."""
    (ax, ay), (bx, by) = xy[lo], xy[hi]
    chord = math.hypot(bx - ax, by - ay)
    far, worst = -1, CORNER_TOLERANCE_M
    for i in range(lo + 1, hi):
        px, py = xy[i]
        d = abs((bx - ax) * (ay - py) - (ax - px) * (by - ay)) / chord if chord > 1e-9 else math.hypot(px - ax, py - ay)
        if d > worst:
            far, worst = i, d
    if far >= 0:
        _simplify(xy, lo, far, out)
        out.append(far)
        _simplify(xy, far, hi, out)


def corners(path: TrackedPath) -> list[float]:
    """Arc lengths of the path's corners: where the path, simplified to within CORNER_TOLERANCE_M,
    turns by at least CORNER_DEG."""
    line = path.line
    xy, cum = [(float(x), float(y)) for x, y in line.points], line.cumulative.tolist()
    kept: list[int] = []
    if len(xy) > 2:
        _simplify(xy, 0, len(xy) - 1, kept)
    idx = [0, *kept, len(xy) - 1]
    out = []
    for a, b, c in zip(idx, idx[1:], idx[2:], strict=False):
        turn = math.atan2(xy[c][1] - xy[b][1], xy[c][0] - xy[b][0]) - math.atan2(
            xy[b][1] - xy[a][1], xy[b][0] - xy[a][0]
        )
        if abs(math.remainder(turn, math.tau)) >= math.radians(CORNER_DEG):
            out.append(cum[b])
    return out


def waypoints(
    path: TrackedPath, params: CueParams, turns: list[float] | None = None
) -> list[tuple[float, float, float]]:
    """(x, y, s) of the waypoints not yet reached: the path's corners (`turns`, default: found
    here), and between them every `nav_point_spacing_m` along the path (none within half of that of
    a corner), and its end, beyond `consume_distance_m` ahead of the robot, nearest first."""
    line = path.line
    if len(line) < 2:
        return []
    step = params.nav_point_spacing_m
    turns = corners(path) if turns is None else turns
    regular = [k * step for k in range(1, int(line.length / step - 1e-9) + 1)]
    stations = sorted([*turns, *(s for s in regular if all(abs(s - t) >= step / 2.0 for t in turns)), line.length])
    limit = path.progress + params.consume_distance_m
    return [(*line.point_at(s), s) for s in stations if s > limit]


class _Waypoints:
    """A cue's waypoints, with the corners found once per path."""

    def __init__(self, params: CueParams) -> None:
        self.params = params
        self.path: TrackedPath | None = None
        self.turns: list[float] = []

    def __call__(self, path: TrackedPath) -> list[tuple[float, float, float]]:
        if path is not self.path:
            self.path, self.turns = path, corners(path)
        return waypoints(path, self.params, self.turns)


def _height(ctx: CueContext) -> float:
    """Where the robot flies: its cruise height (its altitude until it knows one)."""
    return max(ctx.flight_z_m, ctx.robot_z_m)


def _arrow_z(ctx: CueContext) -> float:
    """Above the body, between the turn-signal arrows and the battery gauge (clear of both)."""
    return ctx.robot_z_m + (ctx.mounts.signal_height_m + ctx.mounts.gauge_height_m) / 2.0


def _eye_z(ctx: CueContext) -> float:
    """At the body's middle height, on its front (below the Arrow)."""
    return ctx.robot_z_m + ctx.robot_height_m / 2.0


class NavPoints:
    """The next waypoints with their arrival countdowns (Walker et al. 2018)."""

    key, hidden, exposure, rank, kinematics = "nav_points", 0, "nav_points_shown_s", 4, AERIAL

    def __init__(self, params: CueParams) -> None:
        self.params = params
        self.waypoints = _Waypoints(params)

    def show(self, ctx: CueContext, markers: bool) -> Shown | None:
        p = self.params
        points = self.waypoints(ctx.path)[: p.nav_points_ahead]
        if not points:
            return None
        way = tuple((x, y) for x, y, _ in points)
        if not markers:
            return Shown(len(points), [], way, on_robot=False)
        z, size, color = _height(ctx), p.marker_size_m, SCHEMES[p.scheme]
        speed = max(ctx.cruise_mps, 1e-3)
        specs = [
            MarkerSpec(
                NAV_NS,
                0,
                Shape.LINE_STRIP,
                (0.0, 0.0, 0.0),
                0.0,
                (0.02, 0.0, 0.0),
                color,
                "",
                ((ctx.robot.x, ctx.robot.y, z), *((x, y, z) for x, y, _ in points)),
            )
        ]
        for i, (x, y, s) in enumerate(points):
            eta = (s - ctx.path.progress) / speed
            specs.append(MarkerSpec(NAV_NS, 1 + 2 * i, Shape.SPHERE, (x, y, z), 0.0, (size,) * 3, color))
            specs.append(
                MarkerSpec(
                    NAV_NS,
                    2 + 2 * i,
                    Shape.TEXT_VIEW_FACING,
                    (x, y, z + size),
                    0.0,
                    (0.0, 0.0, 0.12),
                    TEXT_COLOUR,
                    f"{eta:.0f} s",
                )
            )
        return Shown(len(points), specs, way, on_robot=False)


class Arrow:
    """A 3D arrow on the robot pointing at the next waypoint (Walker et al. 2018); its value: the
    arrow's heading in the map (whole degrees: /haven/cue_state changes only when it turns)."""

    key, hidden, exposure, rank, kinematics = "arrow", None, "arrow_shown_s", 5, AERIAL

    def __init__(self, params: CueParams) -> None:
        self.params = params
        self.waypoints = _Waypoints(params)

    def show(self, ctx: CueContext, markers: bool) -> Shown | None:
        points = self.waypoints(ctx.path)
        if not points:
            return None
        x, y, _ = points[0]
        robot = ctx.robot
        yaw = math.atan2(y - robot.y, x - robot.x)
        length = min(0.5, max(0.15, math.hypot(x - robot.x, y - robot.y)))
        spec = MarkerSpec(
            ARROW_NS,
            0,
            Shape.ARROW,
            (robot.x, robot.y, _arrow_z(ctx)),
            yaw,
            (length, 0.06, 0.1),
            SCHEMES[self.params.scheme],
        )
        return Shown(round(math.degrees(yaw)), [spec] if markers else [], ((x, y),), on_robot=True)


class Gaze:
    """An eye on the robot looking where it will go (Walker et al. 2018); its value: where it looks
    (whole degrees, in the map)."""

    key, hidden, exposure, rank, kinematics = "gaze", None, "gaze_shown_s", 6, AERIAL

    def __init__(self, params: CueParams) -> None:
        self.params = params

    def show(self, ctx: CueContext, markers: bool) -> Shown | None:
        path = ctx.path
        if len(path.line) < 2 or path.remaining_m <= self.params.consume_distance_m:
            return None
        robot = ctx.robot
        gx, gy = path.line.point_at(min(path.line.length, path.progress + self.params.gaze_lookahead_m))
        yaw = math.atan2(gy - robot.y, gx - robot.x)
        if not markers:
            return Shown(round(math.degrees(yaw)), [], ((gx, gy),), on_robot=True)
        z = _eye_z(ctx)
        # The eye sits on the robot's front in the direction it looks; the pupil on the ball's surface, toward the
        # look-at point.
        ex, ey = (
            robot.x + ctx.mounts.signal_offset_m * 0.5 * math.cos(yaw),
            robot.y + ctx.mounts.signal_offset_m * 0.5 * math.sin(yaw),
        )
        dz = _height(ctx) - z
        dist = math.hypot(math.hypot(gx - ex, gy - ey), dz)
        k = (EYE_RADIUS_M - PUPIL_RADIUS_M / 2.0) / max(dist, 1e-6)
        pupil = (ex + k * (gx - ex), ey + k * (gy - ey), z + k * dz)
        specs = [
            MarkerSpec(GAZE_NS, 0, Shape.SPHERE, (ex, ey, z), yaw, (2 * EYE_RADIUS_M,) * 3, (1.0, 1.0, 1.0, 1.0)),
            MarkerSpec(GAZE_NS, 1, Shape.SPHERE, pupil, yaw, (2 * PUPIL_RADIUS_M,) * 3, (0.05, 0.05, 0.05, 1.0)),
        ]
        return Shown(round(math.degrees(yaw)), specs, ((gx, gy),), on_robot=True)
