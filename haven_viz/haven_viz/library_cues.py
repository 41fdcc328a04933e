"""A cue library: designs from the HRI literature beside HAVEN's four, as `haven.cues` plugins
registered as a lab's are (haven_viz/pyproject.toml). They are library cues (`default_on = False`): off
in condition `all`, shown in a condition that names them, so HAVEN's own conditions stay what the
paper had.

  * `path_line`: the robot's remaining path as a continuous line on the floor, after Chadalavada,
    Andreasson, Krug & Lilienthal, "That's on my mind! Robot to human intention communication
    through on-board projection on shared floor space", European Conference on Mobile Robots (ECMR)
    2015 (an autonomous forklift projected its intended path as lines
    on the floor). Ours: a flat band `PATH_LINE_WIDTH_M` wide, just above the floor, in the colour
    scheme; from the robot to the goal.
  * `projected_arrows`: short arrows along the path and a sphere at the destination, flat on the
    floor, after Han, Parrillo, Wilkinson, Yanco & Williams, "Projecting Robot Navigation Paths:
    Hardware and Software for Projected AR", HRI 2022 (Short Contributions), whose ROS code
    (github.com/umhan35/arrow_projection, src/PathProjection.cpp) we follow: path points `HAN_SPACING_M` apart paired
    into arrows (so arrows 0.1 m long with 0.1 m gaps), magenta, 0.06 m shafts and 0.08 m heads, and a 0.12 m green
    sphere at the destination. A projector needs a floor under it: ground robots only.
  * `light_ring`: lights on the robot's body, after Szafir, Mutlu & Fong, "Communicating
    Directionality in Flying Robots", HRI 2015, pp. 19-26, doi:10.1145/2696454.2696475 (a ring of
    lights on the robot; their "blinker" design lights the side of an upcoming turn like a car's
    indicator) and the TurtleBot 4's light ring: `LIGHT_RING_LEDS` lights round the top of the
    body; those facing where the robot heads next are lit, and while HAVEN's turn-signal rule
    (`builtin_cues.TurnSignals`, the same code and parameters) signals a turn, the lights on that
    side blink amber at `BLINK_HZ`, a car indicator's rate.
"""

from __future__ import annotations

import itertools
import math

from haven_sim.common.geometry import wrap_angle
from haven_viz.builtin_cues import SCHEMES, CueParams, TurnSignals
from haven_viz.cue_kind import CueContext, Shown
from haven_viz.markers import Color, MarkerSpec, Shape

LINE_NS, ARROWS_NS, RING_NS = "path_line", "projected_arrows", "light_ring"
GROUND = ("diff_drive", "omni")  # a floor projector's robots (haven_sim.robots.description.Kinematics)
FLOOR_Z_M = 0.01  # projected cues lie just above the floor (clear of it in the renderers' depth test; arrows lie on it)
PATH_LINE_WIDTH_M = 0.05  # ours: a projector's line about as wide as the projected path's markers are small
PATH_LINE_STEP_M = 0.1  # the band follows the path's arcs this finely
HAN_SPACING_M = 0.1  # arrow_projection: DISTANCE_BETWEEN, path points this far apart ...
# ... its arrows' shaft and head diameters, the destination sphere's
HAN_SHAFT_M, HAN_HEAD_M, HAN_GOAL_M = 0.06, 0.08, 0.12
MAGENTA: Color = (1.0, 0.0, 1.0, 1.0)  # arrow_projection's arrows
GREEN: Color = (0.0, 1.0, 0.0, 1.0)  # ... and destination
MAX_ARROWS = 150  # arrows drawn at most (30 m of path): a marker array stays small
LIGHT_RING_LEDS = 12  # ours (12 show a direction to 30 degrees)
LED_RADIUS_M = 0.025
LIT_HALF_ANGLE_DEG = 45.0  # lights within this of the heading ahead are lit (ours: a quarter of the ring)
BLINK_HZ = 1.5  # UNECE Regulation No. 48: direction indicators flash 90 +/- 30 times a minute
AMBER: Color = (1.0, 0.55, 0.0, 1.0)  # direction indicators' colour (UNECE R6)
DARK: Color = (0.15, 0.15, 0.15, 1.0)


def _band(points: list[tuple[float, float]], width: float, z: float) -> tuple[tuple[float, float, float], ...]:
    """A flat band along a polyline, as triangles (TRIANGLE_LIST points)."""
    tris: list[tuple[float, float, float]] = []
    half = width / 2.0
    for (x0, y0), (x1, y1) in itertools.pairwise(points):
        length = math.hypot(x1 - x0, y1 - y0)
        if length < 1e-9:
            continue
        nx, ny = -(y1 - y0) / length * half, (x1 - x0) / length * half
        a, b, c, d = (x0 + nx, y0 + ny, z), (x0 - nx, y0 - ny, z), (x1 - nx, y1 - ny, z), (x1 + nx, y1 + ny, z)
        tris += [a, b, c, a, c, d]
    return tuple(tris)


def _stations(ctx: CueContext, step: float, params: CueParams) -> list[tuple[float, float]]:
    """Points every `step` along the path from the robot's progress to its end (both included);
    none once the rest is within `consume_distance_m` (the projected path's markers are used up there too)."""
    line, start = ctx.path.line, ctx.path.progress
    if len(line) < 2 or start >= line.length - params.consume_distance_m:
        return []
    n = max(1, math.ceil((line.length - start) / step))
    return [line.point_at(min(line.length, start + k * step)) for k in range(n + 1)]


class PathLine:
    """The remaining path as a line on the floor (Chadalavada et al. 2015)."""

    key, hidden, exposure, rank, default_on = "path_line", 0.0, "path_line_shown_s", 10, False

    def __init__(self, params: CueParams) -> None:
        self.params = params

    def show(self, ctx: CueContext, markers: bool) -> Shown | None:
        points = _stations(ctx, PATH_LINE_STEP_M, self.params)
        if len(points) < 2:
            return None
        remaining = round(ctx.path.remaining_m, 1)
        way = tuple(points[1:])
        if not markers:
            return Shown(remaining, [], way, on_robot=False)
        band = MarkerSpec(
            LINE_NS,
            0,
            Shape.TRIANGLE_LIST,
            color=SCHEMES[self.params.scheme],
            points=_band(points, PATH_LINE_WIDTH_M, FLOOR_Z_M),
        )
        return Shown(remaining, [band], way, on_robot=False)


class ProjectedArrows:
    """Arrows along the path and the destination, projected on the floor (Han et al. 2022)."""

    key, hidden, exposure, rank, kinematics, default_on = (
        "projected_arrows",
        0,
        "projected_arrows_shown_s",
        11,
        GROUND,
        False,
    )

    def __init__(self, params: CueParams) -> None:
        self.params = params

    def show(self, ctx: CueContext, markers: bool) -> Shown | None:
        points = _stations(ctx, HAN_SPACING_M, self.params)
        if len(points) < 2:
            return None
        # (arrow_projection pairs them from the destination; we from the robot)
        pairs = list(zip(points[::2], points[1::2], strict=False))[:MAX_ARROWS]
        goal = points[-1]
        way = (*tuple(b for _, b in pairs), goal)
        if not markers:
            return Shown(len(pairs), [], way, on_robot=False)
        specs = [
            MarkerSpec(
                ARROWS_NS,
                i + 1,
                Shape.ARROW,
                (ax, ay, HAN_HEAD_M / 2.0),
                math.atan2(by - ay, bx - ax),
                (HAN_SPACING_M, HAN_SHAFT_M, HAN_HEAD_M),
                MAGENTA,
            )
            for i, ((ax, ay), (bx, by)) in enumerate(pairs)
        ]
        specs.append(
            MarkerSpec(
                ARROWS_NS, 0, Shape.SPHERE, (goal[0], goal[1], FLOOR_Z_M), 0.0, (HAN_GOAL_M, HAN_GOAL_M, 0.01), GREEN
            )
        )
        return Shown(len(pairs), specs, way, on_robot=False)


class LightRing:
    """Lights round the robot's body: where it heads lit, the side of a turn blinking (Szafir et al. 2015)."""

    key, hidden, exposure, rank, default_on = "light_ring", None, "light_ring_shown_s", 12, False

    def __init__(self, params: CueParams) -> None:
        self.params = params
        self.signal = TurnSignals(params)  # HAVEN's rule says when a turn is signalled, and to which side

    def show(self, ctx: CueContext, markers: bool) -> Shown | None:
        ahead = ctx.path.ahead([min(self.params.signal_lookahead_m, ctx.path.remaining_m)])
        if not ahead or ctx.path.remaining_m <= self.params.consume_distance_m:
            return None
        robot = ctx.robot
        x, y, _ = ahead[0]
        bearing = (
            wrap_angle(math.atan2(y - robot.y, x - robot.x) - robot.yaw)
            if math.hypot(x - robot.x, y - robot.y) > 1e-3
            else 0.0
        )
        side = self.signal.side(robot, ctx.path, ctx.now, ctx.manoeuvre)
        blink_on = side != 0 and (ctx.now is None or (ctx.now * BLINK_HZ) % 1.0 < 0.5)
        value = {"bearing_deg": round(math.degrees(bearing)), "blink": side}
        way = ((x, y),)
        if not markers:
            return Shown(value, [], way)
        radius, z = (
            max(LED_RADIUS_M, ctx.half_width_m - LED_RADIUS_M),
            ctx.robot_z_m + ctx.robot_height_m + LED_RADIUS_M,
        )
        lit = SCHEMES[self.params.scheme]
        specs = []
        for i in range(LIGHT_RING_LEDS):
            angle = 2.0 * math.pi * i / LIGHT_RING_LEDS  # relative to the robot's heading, anticlockwise (REP-103)
            facing = abs(wrap_angle(angle - bearing)) <= math.radians(LIT_HALF_ANGLE_DEG)
            on_side = side != 0 and abs(wrap_angle(angle - side * math.pi / 2.0)) <= math.radians(LIT_HALF_ANGLE_DEG)
            color = AMBER if on_side and blink_on else lit if facing else DARK
            yaw = robot.yaw + angle
            pos = (robot.x + radius * math.cos(yaw), robot.y + radius * math.sin(yaw), z)
            specs.append(MarkerSpec(RING_NS, i, Shape.SPHERE, pos, 0.0, (2 * LED_RADIUS_M,) * 3, color))
        return Shown(value, specs, way)
