"""What a cue is: the plugin kind `haven.cues` (haven_sim/common/plugins.py).

A cue is a class registered by name; the viz node, batch mode and the simulated participants' director
each make one per robot (`Cue(params)`, `params`: the shared `builtin_cues.CueParams`) and ask it, at the cue rate
and only while the study condition has it on, what it shows now::

    class FloorArrows:
        key = "floor_arrows"        # its key in /haven/cue_state (default: the registered name)
        hidden = 0                  # its value there while it shows nothing
        exposure = "floor_arrows_shown_s"   # its exposure metric (default: "<name>_shown_s")
        rank = 10                   # where it comes among the cues (default 100; then by name)
        kinematics = ("diff_drive", "omni")  # the robot kinds it serves (default: every kind)
        default_on = True           # on in condition `all` (False: a library cue, shown only where a condition
                                    # names it)

        def __init__(self, params: CueParams) -> None: ...

        def show(self, ctx: CueContext, markers: bool) -> Shown | None:
            ...                     # None: nothing to show now

`CueContext` holds what every cue may draw on: the robot's pose, its path and how far along it is
(`TrackedPath`), the people, the battery level, the thought text, the time, where on this
robot its own cues sit (`mounts`, from its robot file, above `robot_z_m`: its altitude, 0 on the
ground), the height it travels at (`flight_z_m`), its cruise speed (`cruise_mps`) and half its
width (`half_width_m`), and a pass round a person under way (`manoeuvre`). A robot
gets only the cues that serve its kind (`kinematics`). `Shown` says what
the cue shows: its value (JSON, recorded on /haven/cue_state), its markers (in frame `map`, drawn by
every viewer and the participant page without page code), and for the simulated participants where
it shows the robot's way ahead (`way`, nearest the robot first) and whether it is drawn on the robot
(seen only with it) or where its points are.
"""

from __future__ import annotations

import inspect
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any, Protocol, cast

from haven_sim.common.geometry import FloatArray, Point, Pose2D
from haven_sim.common.paths import SegmentKind, read_path
from haven_sim.common.polyline import Polyline
from haven_sim.nav.motion_style import MotionStyle
from haven_sim.robots.description import CueMounts, Kinematics
from haven_sim.robots.fields import DEFAULT
from haven_viz.markers import MarkerSpec

STYLE = MotionStyle()  # how a path reads: HAVEN's turning rule (the viz node takes no motion-style parameters)


@dataclass(frozen=True)
class PathMarker:
    """A place every `marker_spacing_m` along the path (the projected path's markers)."""

    x: float
    y: float
    s: float  # arc length along the path
    arc: bool  # on an arc (HAVEN draws cubes there, spheres on straight parts)


@dataclass(frozen=True)
class Rotation:
    """A rotation in place on the path."""

    x: float
    y: float
    s: float
    yaw: float  # where the rotation ends


class TrackedPath:
    """The robot's current path (/plan, from any planner) read once, and how far along it the robot
    is (monotonic, searched near the last value). A new path is a new object."""

    def __init__(self, poses: Sequence[Pose2D], spacing_m: float) -> None:
        self.line = Polyline(poses)
        reading = read_path(poses, STYLE.arc_max_angle_rad, STYLE.facing_tolerance_rad)
        self.headings: FloatArray = reading.headings  # travel heading per segment
        self.rotations: list[Rotation] = []
        self.markers: list[PathMarker] = []
        self.progress = 0.0
        if not poses:
            return
        self.rotations = [
            Rotation(poses[seg.end].x, poses[seg.end].y, float(self.line.cumulative[seg.end]), seg.yaw)
            for seg in reading.segments
            if seg.kind is SegmentKind.ROTATE
        ]
        for k in range(1, int(self.line.length / spacing_m + 1e-9) + 1):
            s = k * spacing_m
            x, y = self.line.point_at(s)
            self.markers.append(PathMarker(x, y, s, any(a - 1e-9 <= s <= b + 1e-9 for a, b in reading.arcs)))

    def advance(self, robot: Pose2D) -> None:
        if len(self.line) >= 2:
            self.progress = max(
                self.progress, self.line.project(robot.x, robot.y, self.progress, self.progress + 2.0).s
            )

    @property
    def remaining_m(self) -> float:
        return max(0.0, self.line.length - self.progress) if len(self.line) >= 2 else 0.0

    def ahead(self, distances_m: Sequence[float]) -> list[tuple[float, float, float]]:
        """(x, y, heading) at each distance ahead of the robot along the path, for those the path reaches."""
        out = []
        for d in distances_m:
            s = self.progress + d
            if len(self.line) < 2 or s > self.line.length + 1e-9:
                break
            x, y = self.line.point_at(s)
            out.append((x, y, float(self.headings[self.line.moving_segment_at(s)])))
        return out


@dataclass(frozen=True)
class Manoeuvre:
    """A pass the robot's navigator is making round a person (its `replanned` event: the side it
    passes on, +1 left, -1 right), and whether it is on its way back to its route (`reverted`);
    `count` tells one pass from the next. Only the viz knows it, from /haven/events; another
    planner's paths have none."""

    count: int = 0
    side: int = 0  # 0: no pass
    returning: bool = False


NO_MANOEUVRE = Manoeuvre()


@dataclass(frozen=True)
class CueContext:
    """What a cue may draw on at one moment."""

    robot: Pose2D
    path: TrackedPath
    humans: Sequence[Point] = ()
    battery_level: float | None = None
    thought: str = ""
    now: float | None = None  # sim time (None: a single picture, no timing)
    robot_height_m: float = 0.0  # the robot's body, from its robot file
    mounts: CueMounts = DEFAULT.cues  # where its own cues sit (robot file: cues), above ...
    robot_z_m: float = 0.0  # ... its base frame, this high above the floor (an aerial robot's altitude)
    flight_z_m: float = 0.0  # the height it travels at (an aerial robot's cruise height; 0 on the ground)
    cruise_mps: float = DEFAULT.motion.cruise_speed_mps  # its cruise speed (arrival estimates)
    half_width_m: float = DEFAULT.footprint.width_m / 2.0  # half its body's width (lights on its body sit within it)
    manoeuvre: Manoeuvre = NO_MANOEUVRE  # a pass under way (the turn signals' pass-side rule)
    thought_everywhere: bool = False  # the researcher's thought: shown whoever is near (Wizard of Oz)


@dataclass(frozen=True)
class Shown:
    """What one cue shows now."""

    value: Any  # its value on /haven/cue_state (JSON: a number, text or true)
    markers: list[MarkerSpec] = field(default_factory=list)
    way: tuple[Point, ...] = ()  # where it says the robot goes, nearest the robot first (() = it says nothing of that)
    on_robot: bool = True  # drawn on the robot (seen only with it); else seen where `way` is


class Cue(Protocol):
    """A cue's object, made per robot from its class: what it shows now (None: nothing)."""

    def show(self, ctx: CueContext, markers: bool) -> Shown | None: ...


@dataclass(frozen=True)
class CueSpec:
    """A registered cue: its class and what the class declares, read once with the defaults (the
    lab's class itself is never changed)."""

    name: str
    make: Callable[[Any], Cue]  # the class, called with the shared CueParams
    key: str  # its key in /haven/cue_state
    hidden: Any  # its value there while it shows nothing
    exposure: str  # its exposure metric
    rank: int  # where it comes among the cues
    kinematics: tuple[str, ...]  # the robot kinds it serves
    default_on: bool  # on in condition `all`


KINDS: tuple[str, ...] = tuple(k.value for k in Kinematics)


def serves(cue: CueSpec, kind: Kinematics | str) -> bool:
    """Whether a cue serves a robot of this kind."""
    return Kinematics(kind).value in cue.kinematics


def accept_plugin(name: str, value: Any) -> CueSpec:
    """A `haven.cues` plugin: a class taking `(params: CueParams)` whose objects `show(ctx, markers)`;
    its `key`, `hidden`, `exposure`, `rank`, `kinematics` and `default_on` default to the name, None,
    `<name>_shown_s`, 100, every kind and True."""
    if not inspect.isclass(value) or not callable(getattr(value, "show", None)):
        raise ValueError("is not a cue: a class taking (params) with a show(ctx, markers) method")
    spec = CueSpec(
        name,
        cast(Callable[[Any], Cue], value),
        key=getattr(value, "key", name),
        hidden=getattr(value, "hidden", None),
        exposure=getattr(value, "exposure", f"{name}_shown_s"),
        rank=getattr(value, "rank", 100),
        kinematics=getattr(value, "kinematics", KINDS),
        default_on=getattr(value, "default_on", True),
    )
    kinds = spec.kinematics
    if isinstance(kinds, str) or not isinstance(kinds, tuple) or not kinds or any(k not in KINDS for k in kinds):
        raise ValueError(
            f"is not a cue: its kinematics must be a tuple of robot kinds ({', '.join(KINDS)}), got {str(kinds)[:50]}"
        )
    if not isinstance(spec.default_on, bool):
        raise ValueError("is not a cue: its default_on must be true or false")
    if (
        not isinstance(spec.key, str)
        or not spec.key
        or not isinstance(spec.exposure, str)
        or not isinstance(spec.rank, int)
    ):
        raise ValueError("is not a cue: its key and exposure must be names, its rank a whole number")
    return spec
