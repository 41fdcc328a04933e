"""HAVEN's four AR cues, as `haven.cues` plugins (registered in haven_viz's pyproject.toml, as a lab's are):

  * path projection: markers every `marker_spacing_m` along the remaining path, spheres on straight
    parts and cubes on arcs (the shared classifier of haven_sim), `steps_ahead` of them (0 = all),
    consumed as the robot passes them;
  * turn signals: an arrow on the robot's left or right while the path within `signal_lookahead_m`
    ahead turns away from the robot's heading by at least `turn_signal_threshold` (11 deg), or a
    rotation in place is under way, like a driver's indicator before and through a turn; once lit
    it stays lit until the turn is within `turn_signal_release_deg`, and at least
    `turn_signal_hold_s`, so neither a wobbling heading nor an S-curve makes it flicker;
  * thought bubble: the robot's current thought as view-facing text above it, shown while a human
    is within `thought_radius_m`, with hysteresis so it does not flicker at the edge (tracked while
    the cue is on);
  * battery indicator: a level bar coloured by HAVEN's thresholds, and the percentage.

All draw at the robot's height (`CueContext.robot_z_m`: 0 on the ground, an aerial robot's altitude),
the projected path too, so a drone's path is projected at its flight height.

`CueParams` are the viz node's cue parameters, shared by every cue (a lab's cue reads the colour
scheme and marker size from them too).
"""

from __future__ import annotations

import math

import numpy as np

from haven_sim.common.geometry import Pose2D, wrap_angle
from haven_sim.common.params import NOT_NEGATIVE, POSITIVE, Bounds, config, param
from haven_viz.cue_kind import NO_MANOEUVRE, CueContext, Manoeuvre, Shown, TrackedPath
from haven_viz.markers import Color, MarkerSpec, Shape

PATH_NS, SIGNAL_NS, THOUGHT_NS, BATTERY_NS = "path_projection", "turn_signals", "thought_bubble", "battery_indicator"
LOOKAHEAD_STEP_M = 0.1  # the turn signals sample the path ahead this finely
SIGNAL_RULES = ("pass_side", "path_turn")

SCHEMES: dict[str, Color] = {
    "yellow": (0.934, 0.923, 0.0, 1.0),  # HAVEN's marker material
    "white": (1.0, 1.0, 1.0, 1.0),  # the paper's figures
    "cyan": (0.0, 0.9, 1.0, 1.0),
}
BATTERY_BANDS: tuple[tuple[float, Color], ...] = (  # HAVEN's indicator: level above -> colour
    (0.8, (0.0, 0.8, 0.0, 1.0)),  # green
    (0.6, (0.55, 0.9, 0.3, 1.0)),  # light green
    (0.4, (1.0, 0.9, 0.0, 1.0)),  # yellow
    (0.2, (1.0, 0.55, 0.0, 1.0)),  # orange
)
BATTERY_LOW: Color = (0.9, 0.0, 0.0, 1.0)  # red


@config
class CueParams:
    marker_spacing_m: float = param(0.4, "HAVEN: 1 m at its 2.6x robot scale", POSITIVE)
    steps_ahead: int = param(0, "projected markers shown ahead; 0 = the whole remaining path", NOT_NEGATIVE)
    marker_size_m: float = param(0.2, "HAVEN's 0.2 m spheres and cubes", POSITIVE)
    consume_distance_m: float = param(
        0.2, "a marker this close ahead of the robot along the path is used up", NOT_NEGATIVE
    )
    scheme: str = param("yellow", "marker colour: yellow (HAVEN), white (the paper's figures), cyan")
    turn_signal_threshold_deg: float = param(
        11.0,
        "HAVEN: a heading error this large lights the turn signal",
        Bounds(0.0, 180.0, low_open=True, high_open=True),
    )
    turn_signal_release_deg: float = param(
        6.0, "a lit turn signal goes dark only when the turn ahead is within this (hysteresis)"
    )
    turn_signal_hold_s: float = param(
        0.5, "a lit turn signal stays lit at least this long (no flicker on S-curves)", NOT_NEGATIVE
    )
    signal_lookahead_m: float = param(
        1.2,
        "the turn signals show a turn of the path this far ahead (3 s at 0.4 m/s; drivers signal about 3 s ahead)",
        NOT_NEGATIVE,
    )
    thought_radius_m: float = param(3.0, "a human this close shows the thought bubble ...", POSITIVE)
    thought_hysteresis_m: float = param(0.5, "... which hides again only beyond radius + this", NOT_NEGATIVE)
    thought_backdrop: bool = param(True, "a white bubble behind the thought's text")
    nav_points_ahead: int = param(
        3,
        "NavPoints (aerial robots): waypoints shown ahead, each with its arrival countdown (Walker et al. 2018)",
        POSITIVE,
    )
    nav_point_spacing_m: float = param(
        1.0, "NavPoints: a waypoint this far apart along the path, and at its end (ours)", POSITIVE
    )
    gaze_lookahead_m: float = param(
        1.0, "Gaze (aerial robots): the eye looks at the path this far ahead (ours)", POSITIVE
    )
    turn_signal_rule: str = param(
        "pass_side",
        "in a pass round a person: pass_side (the side passed on, the whole pass; "
        "dark on the way back) or path_turn (every turn of the path)",
    )

    def __post_init__(self) -> None:
        if self.turn_signal_rule not in SIGNAL_RULES:
            raise ValueError(
                f"turn_signal_rule must be one of {', '.join(SIGNAL_RULES)}, got {self.turn_signal_rule!r}"
            )
        if self.scheme not in SCHEMES:
            raise ValueError(f"scheme must be one of {', '.join(SCHEMES)}, got {self.scheme!r}")
        if not 0 <= self.turn_signal_release_deg <= self.turn_signal_threshold_deg:
            raise ValueError(
                "turn_signal_release_deg must be within "
                f"[0, turn_signal_threshold_deg], got {self.turn_signal_release_deg}"
            )

    @property
    def turn_signal_threshold_rad(self) -> float:
        return math.radians(self.turn_signal_threshold_deg)

    @property
    def turn_signal_release_rad(self) -> float:
        return math.radians(self.turn_signal_release_deg)


def battery_color(level: float) -> Color:
    for above, color in BATTERY_BANDS:
        if level > above:
            return color
    return BATTERY_LOW


class PathProjection:
    """The projected path: the markers not yet consumed, `steps_ahead` of them (0 = all)."""

    key, hidden, exposure, rank = "path_markers", 0, "path_projection_shown_s", 0

    def __init__(self, params: CueParams) -> None:
        self.params = params

    def show(self, ctx: CueContext, markers: bool) -> Shown | None:
        p = self.params
        limit = ctx.path.progress + p.consume_distance_m
        shown = [(i, m) for i, m in enumerate(ctx.path.markers) if m.s > limit]
        shown = shown[: p.steps_ahead] if p.steps_ahead else shown
        if not shown:
            return None
        size, color = p.marker_size_m, SCHEMES[p.scheme]
        specs = [
            MarkerSpec(
                PATH_NS,
                i,
                Shape.CUBE if m.arc else Shape.SPHERE,
                (m.x, m.y, ctx.robot_z_m + size / 2.0),
                0.0,
                (size,) * 3,
                color,
            )
            for i, m in shown
        ]
        return Shown(len(shown), specs if markers else [], tuple((m.x, m.y) for _, m in shown), on_robot=False)


class TurnSignals:
    """A driver's indicator: +1 left, -1 right, 0 dark."""

    key, hidden, exposure, rank = "turn_signal", 0, "turn_signal_shown_s", 1

    def __init__(self, params: CueParams) -> None:
        self.params = params
        self.lit = 0  # the side shown
        self.lit_since = 0.0
        self.path: TrackedPath | None = None
        self.rotations_done = 0
        self.back_done = 0  # the last pass whose way back is over (Manoeuvre.count)

    def turn_error(self, robot: Pose2D, path: TrackedPath) -> float | None:
        """Signed heading error (rad, + = left) the turn signals show, or None without a path."""
        p = self.params
        if path is not self.path:
            self.path, self.rotations_done = path, 0
        # A rotation in place at (or just behind) the robot that has not finished yet.
        while self.rotations_done < len(path.rotations):
            rot = path.rotations[self.rotations_done]
            if rot.s > path.progress + p.consume_distance_m:
                break
            err = wrap_angle(rot.yaw - robot.yaw)
            if abs(err) < p.turn_signal_threshold_rad or math.hypot(rot.x - robot.x, rot.y - robot.y) > 0.3:
                self.rotations_done += 1
                continue
            return err
        line = path.line
        if len(line) < 2 or path.progress >= line.length - 1e-6:
            return None
        # The path's heading at points ahead: the nearest that turns away by the threshold, else
        # the largest turn within the look-ahead.
        ahead = np.arange(
            path.progress, min(line.length, path.progress + p.signal_lookahead_m) + 1e-9, LOOKAHEAD_STEP_M
        )
        largest: float | None = None
        for s in ahead.tolist():
            e = wrap_angle(path.headings[line.moving_segment_at(s)] - robot.yaw)
            if abs(e) >= p.turn_signal_threshold_rad:
                return e
            # the first of the largest, as max() keeps
            largest = e if largest is None or abs(e) > abs(largest) else largest
        return largest

    def side(
        self, robot: Pose2D, path: TrackedPath, now: float | None = None, manoeuvre: Manoeuvre = NO_MANOEUVRE
    ) -> int:
        """+1 (left) or -1 (right) while the turn ahead reaches the threshold (a lit side stays lit
        down to the release angle, and for `turn_signal_hold_s` when the time is given), else 0.
        With the pass-side rule, during a pass round a person (`manoeuvre`) the side passed on,
        and dark on the way back until the robot heads along its path again (within the release angle)."""
        err = self.turn_error(robot, path)
        lit = self._path_turn(err, now)
        m = manoeuvre
        if self.params.turn_signal_rule != "pass_side" or m.side == 0 or self.back_done == m.count:
            return lit
        if not m.returning:
            return m.side
        if err is None or abs(err) < self.params.turn_signal_release_rad:
            self.back_done = m.count  # back on its way: the pass is over
            return lit
        return 0

    def _path_turn(self, err: float | None, now: float | None) -> int:
        """The path-turn rule (HAVEN's): the side of the turn ahead, with hysteresis and a hold."""
        p = self.params
        if now is not None and self.lit and now - self.lit_since < p.turn_signal_hold_s:
            return self.lit
        if err is None:
            side = 0
        elif self.lit and err * self.lit >= p.turn_signal_release_rad:
            side = self.lit
        else:
            side = (1 if err > 0 else -1) if abs(err) >= p.turn_signal_threshold_rad else 0
        if side != self.lit:
            self.lit, self.lit_since = side, now if now is not None else 0.0
        return self.lit

    def show(self, ctx: CueContext, markers: bool) -> Shown | None:
        side = self.side(ctx.robot, ctx.path, ctx.now, ctx.manoeuvre)
        if side == 0:
            return None
        robot = ctx.robot
        # An arrow beside the robot pointing outward, like HAVEN's arrows on the robot's sides.
        out_yaw = robot.yaw + side * math.pi / 2.0
        m = ctx.mounts
        x, y = robot.x + m.signal_offset_m * math.cos(out_yaw), robot.y + m.signal_offset_m * math.sin(out_yaw)
        color = SCHEMES[self.params.scheme]
        arrow = MarkerSpec(
            SIGNAL_NS,
            0 if side > 0 else 1,
            Shape.ARROW,
            (x, y, ctx.robot_z_m + m.signal_height_m),
            out_yaw,
            (0.3, 0.08, 0.08),
            color,
        )
        return Shown(side, [arrow] if markers else [])


class ThoughtBubble:
    """The robot's thought as text above it, while a person is near."""

    key, hidden, exposure, rank = "thought", "", "thought_bubble_shown_s", 2

    def __init__(self, params: CueParams) -> None:
        self.params = params
        self.near = False  # a person within the radius (with hysteresis)

    def show(self, ctx: CueContext, markers: bool) -> Shown | None:
        p = self.params
        robot = ctx.robot
        nearest = min((math.hypot(h[0] - robot.x, h[1] - robot.y) for h in ctx.humans), default=math.inf)
        self.near = nearest <= p.thought_radius_m + (p.thought_hysteresis_m if self.near else 0.0)
        if not ((self.near or ctx.thought_everywhere) and ctx.thought):
            return None
        if not markers:
            return Shown(ctx.thought)
        z = ctx.robot_z_m + ctx.mounts.bubble_height_m
        text = ctx.thought
        out = [
            MarkerSpec(
                THOUGHT_NS,
                0,
                Shape.TEXT_VIEW_FACING,
                (robot.x, robot.y, z),
                0.0,
                (0.0, 0.0, 0.15),
                (0.05, 0.05, 0.05, 1.0),
                text,
            )
        ]
        if p.thought_backdrop:
            width = max(0.6, 0.085 * len(text))
            out.append(
                MarkerSpec(
                    THOUGHT_NS,
                    1,
                    Shape.SPHERE,
                    (robot.x, robot.y, z),
                    robot.yaw,
                    (width, width, 0.35),
                    (1.0, 1.0, 1.0, 0.85),
                )
            )
        return Shown(text, out)


class BatteryIndicator:
    """A level bar and the percentage above the robot."""

    key, hidden, exposure, rank = "battery_level", None, "battery_indicator_shown_s", 3

    def __init__(self, params: CueParams) -> None:
        self.params = params

    def show(self, ctx: CueContext, markers: bool) -> Shown | None:
        if ctx.battery_level is None:
            return None
        level = min(1.0, max(0.0, ctx.battery_level))
        if not markers:
            return Shown(level)
        robot, z = ctx.robot, ctx.robot_z_m + ctx.mounts.gauge_height_m
        full, thick = 0.4, 0.08
        color = battery_color(level)
        # A bar along the map's x axis (a cube cannot face the viewer the way HAVEN's sprite did),
        # filled from its left end.
        filled = max(level * full, 0.005)
        bx, by = robot.x - full / 2.0 + filled / 2.0, robot.y
        return Shown(
            level,
            [
                MarkerSpec(
                    BATTERY_NS,
                    0,
                    Shape.CUBE,
                    (robot.x, robot.y, z),
                    0.0,
                    (full + 0.02, thick + 0.02, thick + 0.02),
                    (0.15, 0.15, 0.15, 0.6),
                ),
                MarkerSpec(BATTERY_NS, 1, Shape.CUBE, (bx, by, z), 0.0, (filled, thick, thick + 0.03), color),
                MarkerSpec(
                    BATTERY_NS,
                    2,
                    Shape.TEXT_VIEW_FACING,
                    (robot.x, robot.y, z + 0.15),
                    0.0,
                    (0.0, 0.0, 0.12),
                    color,
                    f"{round(100 * level)} %",
                ),
            ],
        )
