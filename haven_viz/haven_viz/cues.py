"""HAVEN's AR cues as marker data: path projection, turn signals, thought bubble, battery indicator.

Inputs are plain values (robot pose, path poses, humans, battery level, thought text); outputs are
`MarkerSpec`s in frame `map`, one namespace per cue with stable ids, so a viewer shows what a HAVEN
participant saw:

  * path projection: markers every `marker_spacing_m` along the remaining path, spheres on straight
    parts and cubes on arcs (the shared classifier of haven_sim), `steps_ahead` of them (0 = all),
    consumed as the robot passes them;
  * turn signals: an arrow on the robot's left or right while the path within `signal_lookahead_m`
    ahead turns away from the robot's heading by at least `turn_signal_threshold` (11 deg), or a
    rotation in place is under way, like a driver's indicator before and through a turn; once lit
    it stays lit until the turn is within `turn_signal_release_deg`, and at least
    `turn_signal_hold_s`, so neither a wobbling heading nor an S-curve makes it flicker;
  * thought bubble: the robot's current thought as view-facing text above it, shown while a human
    is within `thought_radius_m`, with hysteresis so it does not flicker at the edge;
  * battery indicator: a level bar coloured by HAVEN's thresholds, and the percentage.

Each update also says what is shown as data (`CueState`), which the viz node publishes on
/haven/cue_state and metrics read: nothing has to be inferred from marker namespaces and ids.
"""

from __future__ import annotations

import dataclasses
import json
import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from haven_sim.common.bodies import ROBOT_BODY
from haven_sim.common.geometry import FloatArray, Point, Pose2D, wrap_angle
from haven_sim.common.params import param
from haven_sim.common.paths import SegmentKind, read_path
from haven_sim.common.polyline import Polyline
from haven_sim.nav.motion_style import MotionStyle
from haven_viz.markers import Color, MarkerSpec, Shape

PATH_NS, SIGNAL_NS, THOUGHT_NS, BATTERY_NS = "path_projection", "turn_signals", "thought_bubble", "battery_indicator"
CUES = (PATH_NS, SIGNAL_NS, THOUGHT_NS, BATTERY_NS)
LOOKAHEAD_STEP_M = 0.1  # the turn signals sample the path ahead this finely

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

STYLE = MotionStyle()  # how a path reads: HAVEN's turning rule (the viz node takes no motion-style parameters)


@dataclass(frozen=True)
class CueParams:
    marker_spacing_m: float = param(0.4, "HAVEN: 1 m at its 2.6x robot scale")
    steps_ahead: int = param(0, "projected markers shown ahead; 0 = the whole remaining path")
    marker_size_m: float = param(0.2, "HAVEN's 0.2 m spheres and cubes")
    consume_distance_m: float = param(0.2, "a marker this close ahead of the robot along the path is used up")
    scheme: str = param("yellow", "marker colour: yellow (HAVEN), white (the paper's figures), cyan")
    turn_signal_threshold_deg: float = param(11.0, "HAVEN: a heading error this large lights the turn signal")
    turn_signal_release_deg: float = param(6.0, "a lit turn signal goes dark only when the turn ahead is within this (hysteresis)")
    turn_signal_hold_s: float = param(0.5, "a lit turn signal stays lit at least this long (no flicker on S-curves)")
    signal_lookahead_m: float = param(1.2, "the turn signals show a turn of the path this far ahead (3 s at 0.4 m/s; drivers signal about 3 s ahead)")
    thought_radius_m: float = param(3.0, "a human this close shows the thought bubble ...")
    thought_hysteresis_m: float = param(0.5, "... which hides again only beyond radius + this")
    thought_backdrop: bool = param(True, "a white bubble behind the thought's text")

    def __post_init__(self) -> None:
        if self.marker_spacing_m <= 0 or self.marker_size_m <= 0:
            raise ValueError("marker_spacing_m and marker_size_m must be positive")
        if self.steps_ahead < 0:
            raise ValueError(f"steps_ahead must be 0 (all) or more, got {self.steps_ahead}")
        if self.scheme not in SCHEMES:
            raise ValueError(f"scheme must be one of {', '.join(SCHEMES)}, got {self.scheme!r}")
        if self.thought_radius_m <= 0 or self.thought_hysteresis_m < 0:
            raise ValueError("thought_radius_m must be positive and thought_hysteresis_m not negative")
        if not 0 < self.turn_signal_threshold_deg < 180:
            raise ValueError(f"turn_signal_threshold_deg must be within (0, 180), got {self.turn_signal_threshold_deg}")
        if not 0 <= self.turn_signal_release_deg <= self.turn_signal_threshold_deg:
            raise ValueError(f"turn_signal_release_deg must be within [0, turn_signal_threshold_deg], got {self.turn_signal_release_deg}")
        if self.signal_lookahead_m < 0 or self.turn_signal_hold_s < 0:
            raise ValueError("signal_lookahead_m and turn_signal_hold_s must not be negative")

    @property
    def turn_signal_threshold_rad(self) -> float:
        return math.radians(self.turn_signal_threshold_deg)

    @property
    def turn_signal_release_rad(self) -> float:
        return math.radians(self.turn_signal_release_deg)


@dataclass(frozen=True)
class Toggles:
    """The study condition: which cues the participant sees (the viz node's run-time parameters)."""

    path_projection: bool = param(True, "cue toggle (study condition), settable at run time")
    turn_signals: bool = param(True, "cue toggle (study condition), settable at run time")
    thought_bubble: bool = param(True, "cue toggle (study condition), settable at run time")
    battery_indicator: bool = param(True, "cue toggle (study condition), settable at run time")


@dataclass(frozen=True)
class CueState:
    """What the participant is shown at one moment (the cue is on in the condition and has
    something to show)."""

    toggles: Toggles = field(default_factory=Toggles)
    path_markers: int = 0  # projected path markers shown
    turn_signal: int = 0  # +1 left, -1 right, 0 dark
    thought: str = ""  # the bubble's text, "" while hidden
    battery_level: float | None = None  # the level shown, None while hidden

    def to_json(self, stamp: float) -> str:
        return json.dumps({"stamp": round(stamp, 4), **dataclasses.asdict(self)}, sort_keys=True)

    @staticmethod
    def from_json(text: str) -> tuple[float, CueState]:
        """(stamp, state) of a /haven/cue_state message; ValueError on anything else."""
        try:
            if len(text) > 65536:
                raise ValueError(f"{len(text)} characters")
            d = json.loads(text)
            toggles = Toggles(**{k: bool(v) for k, v in d["toggles"].items() if k in CUES})
            level = d["battery_level"]
            state = CueState(toggles, int(d["path_markers"]), int(d["turn_signal"]), str(d["thought"]), None if level is None else float(level))
            return float(d["stamp"]), state
        except (ValueError, KeyError, TypeError, AttributeError, RecursionError) as e:
            raise ValueError(f"not a cue state: {str(e)[:80]}") from None


@dataclass(frozen=True)
class CueFrame:
    markers: list[MarkerSpec]
    state: CueState


def battery_color(level: float) -> Color:
    for above, color in BATTERY_BANDS:
        if level > above:
            return color
    return BATTERY_LOW


@dataclass(frozen=True)
class _PathMarker:
    x: float
    y: float
    s: float  # arc length along the path
    arc: bool


@dataclass(frozen=True)
class _Rotation:
    x: float
    y: float
    s: float
    yaw: float  # where the rotation ends


def _layout(poses: Sequence[Pose2D], spacing: float) -> tuple[list[_PathMarker], list[_Rotation], Polyline, FloatArray]:
    """Marker positions every `spacing` along the path, the rotations in place, the path as a
    polyline and its travel heading per segment (read from its geometry: any planner's path)."""
    line = Polyline(poses)
    reading = read_path(poses, STYLE.arc_max_angle_rad, STYLE.facing_tolerance_rad)
    if not poses:
        return [], [], line, reading.headings
    rotations = [
        _Rotation(poses[seg.end].x, poses[seg.end].y, float(line.cumulative[seg.end]), seg.yaw)
        for seg in reading.segments
        if seg.kind is SegmentKind.ROTATE
    ]
    markers = []
    for k in range(1, int(line.length / spacing + 1e-9) + 1):
        s = k * spacing
        x, y = line.point_at(s)
        markers.append(_PathMarker(x, y, s, any(a - 1e-9 <= s <= b + 1e-9 for a, b in reading.arcs)))
    return markers, rotations, line, reading.headings


class ArCues:
    """The cue state of one robot: the path it follows, what is consumed, whether the bubble shows."""

    def __init__(self, params: CueParams | None = None) -> None:
        self.params = params or CueParams()
        self.bubble_shown = False
        self._lit = 0  # the side the turn signal shows
        self._lit_since = 0.0
        self.set_path([])

    def set_path(self, poses: Sequence[Pose2D]) -> None:
        self._markers, self._rotations, self._line, self._heading = _layout(poses, self.params.marker_spacing_m)
        self._progress = 0.0
        self._rotations_done = 0

    # -- state updates ---------------------------------------------------------------------------
    def _advance(self, robot: Pose2D) -> None:
        """Arc length reached along the path (monotonic, searched near the last value)."""
        if len(self._line) >= 2:
            self._progress = max(self._progress, self._line.project(robot.x, robot.y, self._progress, self._progress + 2.0).s)

    @property
    def remaining(self) -> int:
        """Path markers not consumed yet."""
        limit = self._progress + self.params.consume_distance_m
        return sum(1 for m in self._markers if m.s > limit)

    def turn_error(self, robot: Pose2D) -> float | None:
        """Signed heading error (rad, + = left) the turn signals show, or None without a path."""
        p = self.params
        # A rotation in place at (or just behind) the robot that has not finished yet.
        while self._rotations_done < len(self._rotations):
            rot = self._rotations[self._rotations_done]
            if rot.s > self._progress + p.consume_distance_m:
                break
            err = wrap_angle(rot.yaw - robot.yaw)
            if abs(err) < p.turn_signal_threshold_rad or math.hypot(rot.x - robot.x, rot.y - robot.y) > 0.3:
                self._rotations_done += 1
                continue
            return err
        line = self._line
        if len(line) < 2 or self._progress >= line.length - 1e-6:
            return None
        # The path's heading at points ahead: the nearest that turns away by the threshold, else
        # the largest turn within the look-ahead.
        ahead = np.arange(self._progress, min(line.length, self._progress + p.signal_lookahead_m) + 1e-9, LOOKAHEAD_STEP_M)
        largest: float | None = None
        for s in ahead.tolist():
            e = wrap_angle(self._heading[line.moving_segment_at(s)] - robot.yaw)
            if abs(e) >= p.turn_signal_threshold_rad:
                return e
            largest = e if largest is None or abs(e) > abs(largest) else largest  # the first of the largest, as max() keeps
        return largest

    def _update_bubble(self, robot: Pose2D, humans: Sequence[Point]) -> bool:
        p = self.params
        nearest = min((math.hypot(h[0] - robot.x, h[1] - robot.y) for h in humans), default=math.inf)
        if self.bubble_shown:
            self.bubble_shown = nearest <= p.thought_radius_m + p.thought_hysteresis_m
        else:
            self.bubble_shown = nearest <= p.thought_radius_m
        return self.bubble_shown

    # -- markers ---------------------------------------------------------------------------------
    def frame(
        self,
        robot: Pose2D,
        humans: Sequence[Point] = (),
        battery_level: float | None = None,
        thought: str = "",
        toggles: Toggles = Toggles(),
        now: float | None = None,
        markers: bool = True,
    ) -> CueFrame:
        """Every cue marker for this moment (cues that are off are simply absent) and what they show.
        With the time `now`, a lit turn signal is held at least `turn_signal_hold_s`. `markers=False`:
        what they show only, no markers (no one reads them in batch mode)."""
        self._advance(robot)
        shown_bubble = self._update_bubble(robot, humans)  # tracked even while the cue is off
        out: list[MarkerSpec] = []
        path, side, text, level = 0, 0, "", None
        if toggles.path_projection:
            shown = self._shown()
            path = len(shown)
            out += self._path_markers(shown) if markers else []
        if toggles.turn_signals:
            side = self.signal_side(robot, now)
            out += self._signal_markers(robot, side) if markers else []
        if toggles.thought_bubble and shown_bubble and thought:
            text = thought
            out += self._thought_markers(robot, thought) if markers else []
        if toggles.battery_indicator and battery_level is not None:
            level = min(1.0, max(0.0, battery_level))
            out += self._battery_markers(robot, level) if markers else []
        return CueFrame(out, CueState(toggles, path, side, text, level))

    def markers(
        self, robot: Pose2D, humans: Sequence[Point] = (), battery_level: float | None = None, thought: str = "", toggles: Toggles = Toggles()
    ) -> list[MarkerSpec]:
        return self.frame(robot, humans, battery_level, thought, toggles).markers

    def _shown(self) -> list[tuple[int, _PathMarker]]:
        """(id, marker) of the projected path's markers on show: not consumed, `steps_ahead` of them."""
        p = self.params
        limit = self._progress + p.consume_distance_m
        out = [(i, m) for i, m in enumerate(self._markers) if m.s > limit]
        return out[: p.steps_ahead] if p.steps_ahead else out

    def shown_points(self, robot: Pose2D) -> list[Point]:
        """Where the projected path's markers on show are, nearest the robot first, after the robot
        reached `robot` (what a participant can look at; the markers themselves need a frame)."""
        self._advance(robot)
        return [(m.x, m.y) for _, m in self._shown()]

    def _path_markers(self, shown: list[tuple[int, _PathMarker]]) -> list[MarkerSpec]:
        p = self.params
        color = SCHEMES[p.scheme]
        size = p.marker_size_m
        return [
            MarkerSpec(PATH_NS, i, Shape.CUBE if m.arc else Shape.SPHERE, (m.x, m.y, size / 2.0), 0.0, (size, size, size), color) for i, m in shown
        ]

    def signal_side(self, robot: Pose2D, now: float | None = None) -> int:
        """+1 (left) or -1 (right) while the turn ahead reaches the threshold (a lit side stays lit
        down to the release angle, and for `turn_signal_hold_s` when the time is given), else 0."""
        err = self.turn_error(robot)
        p = self.params
        if now is not None and self._lit and now - self._lit_since < p.turn_signal_hold_s:
            return self._lit
        if err is None:
            side = 0
        elif self._lit and err * self._lit >= p.turn_signal_release_rad:
            side = self._lit
        else:
            side = (1 if err > 0 else -1) if abs(err) >= p.turn_signal_threshold_rad else 0
        if side != self._lit:
            self._lit, self._lit_since = side, now if now is not None else 0.0
        return self._lit

    def _signal_markers(self, robot: Pose2D, side: int) -> list[MarkerSpec]:
        if side == 0:
            return []
        # An arrow beside the robot pointing outward, like HAVEN's arrows on the robot's sides.
        out_yaw = robot.yaw + side * math.pi / 2.0
        base = 0.25
        x = robot.x + base * math.cos(out_yaw)
        y = robot.y + base * math.sin(out_yaw)
        color = SCHEMES[self.params.scheme]
        return [MarkerSpec(SIGNAL_NS, 0 if side > 0 else 1, Shape.ARROW, (x, y, ROBOT_BODY.height_m + 0.05), out_yaw, (0.3, 0.08, 0.08), color)]

    def _thought_markers(self, robot: Pose2D, thought: str) -> list[MarkerSpec]:
        z = ROBOT_BODY.height_m + 0.6
        out = [MarkerSpec(THOUGHT_NS, 0, Shape.TEXT_VIEW_FACING, (robot.x, robot.y, z), 0.0, (0.0, 0.0, 0.15), (0.05, 0.05, 0.05, 1.0), thought)]
        if self.params.thought_backdrop:
            width = max(0.6, 0.085 * len(thought))
            out.append(MarkerSpec(THOUGHT_NS, 1, Shape.SPHERE, (robot.x, robot.y, z), robot.yaw, (width, width, 0.35), (1.0, 1.0, 1.0, 0.85)))
        return out

    def _battery_markers(self, robot: Pose2D, level: float) -> list[MarkerSpec]:
        level = min(1.0, max(0.0, level))
        z = ROBOT_BODY.height_m + 0.25
        full, thick = 0.4, 0.08
        color = battery_color(level)
        # A bar along the map's x axis (a cube cannot face the viewer the way HAVEN's sprite did),
        # filled from its left end.
        filled = max(level * full, 0.005)
        bx, by = robot.x - full / 2.0 + filled / 2.0, robot.y
        return [
            MarkerSpec(BATTERY_NS, 0, Shape.CUBE, (robot.x, robot.y, z), 0.0, (full + 0.02, thick + 0.02, thick + 0.02), (0.15, 0.15, 0.15, 0.6)),
            MarkerSpec(BATTERY_NS, 1, Shape.CUBE, (bx, by, z), 0.0, (filled, thick, thick + 0.03), color),
            MarkerSpec(BATTERY_NS, 2, Shape.TEXT_VIEW_FACING, (robot.x, robot.y, z + 0.15), 0.0, (0.0, 0.0, 0.12), color, f"{round(100 * level)} %"),
        ]
