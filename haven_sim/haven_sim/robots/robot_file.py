"""Robot files: a robot's figures in YAML, checked by the schema layer (`haven schema robot`).

A file either describes a whole robot or starts from another (`extends: turtlebot2`, a catalogue
name or a file beside it) and changes what differs; mappings merge key by key, a footprint and a
list are replaced whole. `sources` says where each figure comes from (`limits.max_linear_speed_mps:
"Kobuki user guide, p. 3"`): the catalogue cites one for every figure it states; a file that
extends another keeps the sources of the figures it leaves as they were.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import Field, model_validator

from haven_sim.common.geometry import MAX_POLYGON_VERTICES, polygon_area, polygon_problem
from haven_sim.common.schema import FileModel, Line, Positive, Whole, check, checked, listing
from haven_sim.common.yaml_file import file_label, finite, read_yaml, short
from haven_sim.robots.description import (
    Battery,
    CueMounts,
    DriveForce,
    Flight,
    Footprint,
    Frames,
    Kinematics,
    Lidar,
    Limits,
    Look,
    Motion,
    Primitive,
    RobotDescription,
)


class RobotError(ValueError):
    """A robot file is missing, unreadable or invalid, or a robot name is unknown: one line."""


def _not_negative(v: Any) -> float:
    f = finite(v)
    if f is None or f < 0:
        raise ValueError(f"must be a number of at least 0, got {short(v)}")
    return f


def _fraction(v: Any) -> float:
    f = _not_negative(v)
    if f > 1:
        raise ValueError(f"must be a fraction of a full charge, 0..1, got {short(v)}")
    return f


def _xy(v: Any) -> Any:
    if not (
        isinstance(v, list) and len(v) == 2 and all(finite(c) is not None and abs(finite(c) or 0) <= 10 for c in v)
    ):
        raise ValueError(f"must be a point [x, y] within 10 m of the base frame, got {short(v)}")
    return tuple(float(c) for c in v)


def _triple(v: Any) -> Any:
    if not (
        isinstance(v, list) and len(v) == 3 and all(finite(c) is not None and abs(finite(c) or 0) <= 10 for c in v)
    ):
        raise ValueError(f"must be three numbers [a, b, c] within ±10, got {short(v)}")
    return tuple(float(c) for c in v)


def _colour(v: Any) -> Any:
    if not (isinstance(v, str) and len(v) == 7 and v[0] == "#" and all(c in "0123456789abcdefABCDEF" for c in v[1:])):
        raise ValueError(f"must be a colour as #rrggbb, got {short(v)}")
    return v


_FRAME_TOKEN = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
MAX_FRAME_CHARS = 60


def _frame(v: Any) -> Any:
    """A tf2 frame id by the ROS 2 name rules (design.ros2.org, "Topic and Service name mapping to
    DDS": tokens of letters, digits and '_' not starting with a digit, separated by single '/', no
    '__', no trailing '/'), without the leading '/' tf2 refuses in a frame id."""
    if (
        isinstance(v, str)
        and len(v) <= MAX_FRAME_CHARS
        and "__" not in v
        and all(_FRAME_TOKEN.fullmatch(t) for t in v.split("/"))
    ):
        return v
    raise ValueError(
        f"must be a ROS frame name (at most {MAX_FRAME_CHARS} characters): letters, digits and single '_' in parts "
        f"separated by '/', none starting with a digit, no leading '/', got {short(v)}"
    )


def _footprint_polygon(v: Any) -> Any:
    """At least 3 and at most `MAX_POLYGON_VERTICES` points, a simple polygon of non-zero area."""
    if not isinstance(v, list) or not 3 <= len(v) <= MAX_POLYGON_VERTICES:
        raise ValueError(f"must be a list of 3..{MAX_POLYGON_VERTICES} points [x, y], got {short(v)}")
    points = [_xy(p) for p in v]
    if abs(polygon_area(points)) < 1e-9:
        raise ValueError("has zero area")
    problem = polygon_problem(points)
    if problem:
        raise ValueError(problem)
    return v  # (its points are checked again as XY)


NotNegative = Annotated[float, Field(ge=0), checked(_not_negative)]
Fraction = Annotated[float, Field(ge=0, le=1), checked(_fraction)]
XY = Annotated[tuple[float, float], checked(_xy)]
Triple = Annotated[tuple[float, float, float], checked(_triple)]
Colour = Annotated[str, checked(_colour)]
Frame = Annotated[str, checked(_frame)]
WORLD_FRAMES = ("map", "odom")  # REP-105's fixed frames, the simulator's map_frame and odom_frame defaults


class FootprintFile(FileModel):
    radius_m: Positive(5.0) | None = None  # type: ignore[valid-type]
    polygon: Annotated[list[XY], checked(_footprint_polygon)] | None = None

    @model_validator(mode="after")
    def one_shape(self) -> FootprintFile:
        if (self.radius_m is None) == (self.polygon is None):
            raise ValueError("give either radius_m (a circle) or polygon (points [x, y] about the base frame)")
        return self


class LimitsFile(FileModel):
    max_linear_speed_mps: Positive(20.0)  # type: ignore[valid-type]
    max_angular_speed_rps: Positive(20.0)  # type: ignore[valid-type]
    max_linear_accel_mps2: Positive(20.0)  # type: ignore[valid-type]
    max_angular_accel_rps2: Positive(50.0)  # type: ignore[valid-type]
    max_lateral_speed_mps: NotNegative = 0.0


class MotionFile(FileModel):
    cruise_speed_mps: Positive(20.0)  # type: ignore[valid-type]
    max_turn_rate_rps: Positive(20.0)  # type: ignore[valid-type]


class BatteryFile(FileModel):
    capacity_m: Positive(1e6)  # type: ignore[valid-type]
    idle_drain_per_s: Fraction = 0.0
    drain_per_rad: Fraction = 0.0
    charge_rate_per_s: Fraction = 0.05


class LidarFile(FileModel):
    beams: Whole(1, 10000)  # type: ignore[valid-type]
    range_min_m: NotNegative
    range_max_m: Positive(100.0)  # type: ignore[valid-type]
    rate_hz: Positive(100.0)  # type: ignore[valid-type]
    height_m: NotNegative
    frame: Frame = "base_scan"


class FramesFile(FileModel):
    base: Frame = "base_footprint"
    base_link: Frame = "base_link"
    base_link_height_m: NotNegative = 0.0


class CuesFile(FileModel):
    signal_height_m: NotNegative | None = None
    signal_offset_m: NotNegative | None = None
    gauge_height_m: NotNegative | None = None
    bubble_height_m: NotNegative | None = None


class PrimitiveFile(FileModel):
    shape: Literal["box", "cylinder", "sphere", "cone", "torus"]
    size: Triple
    at: Triple = (0.0, 0.0, 0.0)
    rpy: Triple = (0.0, 0.0, 0.0)
    colour: Colour = "#808080"
    spin: bool = False


class LookFile(FileModel):
    primitives: Annotated[list[PrimitiveFile], listing("a list of primitives", non_empty=False)] = []  # noqa: RUF012 (a pydantic field: the default is copied per instance)
    model: Line(200) | None = None  # type: ignore[valid-type]


class FlightFile(FileModel):
    cruise_height_m: Positive(10.0)  # type: ignore[valid-type]
    climb_rate_mps: Positive(10.0)  # type: ignore[valid-type]
    clearance_m: NotNegative = 0.3
    person_distance_m: NotNegative = 0.5


class DriveFile(FileModel):
    max_force_n: Positive(1e5)  # type: ignore[valid-type]
    max_torque_nm: Positive(1e5)  # type: ignore[valid-type]


class RobotFileModel(FileModel):
    """A robot file (after `extends` is merged)."""

    name: Annotated[str, Field(pattern=r"^[a-z][a-z0-9_]{0,39}$"), checked(lambda v: _name(v))]
    title: Line(80)  # type: ignore[valid-type]
    kinematics: Literal["diff_drive", "omni", "aerial"]
    footprint: FootprintFile
    height_m: Positive(10.0)  # type: ignore[valid-type]
    mass_kg: Positive(1e4)  # type: ignore[valid-type]
    limits: LimitsFile
    motion: MotionFile
    battery: BatteryFile
    lidar: LidarFile
    drive: DriveFile
    frames: FramesFile = FramesFile()
    cues: CuesFile = CuesFile()
    look: LookFile = LookFile()
    flight: FlightFile | None = None
    sources: dict[str, Line(300)] = {}  # type: ignore[valid-type]  # noqa: RUF012 (a pydantic field: the default is copied per instance)

    @model_validator(mode="after")
    def consistent(self) -> RobotFileModel:
        if (self.kinematics == "aerial") != (self.flight is not None):
            raise ValueError("flight: an aerial robot needs a flight section, and only an aerial robot has one")
        if self.kinematics == "diff_drive" and self.limits.max_lateral_speed_mps > 0:
            raise ValueError("limits.max_lateral_speed_mps: a diff_drive robot cannot move sideways (0 or omit it)")
        if self.motion.cruise_speed_mps > self.limits.max_linear_speed_mps:
            raise ValueError(
                f"motion.cruise_speed_mps: {self.motion.cruise_speed_mps:g} is above "
                f"limits.max_linear_speed_mps {self.limits.max_linear_speed_mps:g}"
            )
        if self.lidar.range_min_m >= self.lidar.range_max_m:
            raise ValueError("lidar.range_min_m: must be below range_max_m")
        frames = {
            "frames.base": self.frames.base,
            "frames.base_link": self.frames.base_link,
            "lidar.frame": self.lidar.frame,
        }
        for key, name in frames.items():
            if name in WORLD_FRAMES:
                raise ValueError(
                    f"{key}: {name!r} is a frame of the world the simulator publishes (REP-105), not of the robot"
                )
            other = next((k for k, n in frames.items() if n == name and k != key), None)
            if other is not None:
                raise ValueError(f"{key}: {name!r} is also {other} (each frame of the TF tree needs its own name)")
        return self


def _name(v: Any) -> Any:
    if (
        not isinstance(v, str)
        or not v
        or len(v) > 40
        or not (v[0].isascii() and v[0].islower())
        or not all(c.isascii() and (c.islower() or c.isdigit() or c == "_") for c in v)
    ):
        raise ValueError(
            f"must be lower-case letters, digits and _ (at most 40), starting with a letter, got {short(v)}"
        )
    return v


REPLACED_WHOLE = frozenset({"footprint"})  # mappings an extending file replaces, not merges (a circle or a polygon)
MAX_EXTENDS = 8  # a chain of `extends` longer than this is a loop


def read_robot_file(path: str | Path, base: Any = None) -> RobotDescription:
    """The robot in `path` (RobotError, one line, on any problem). `base(name)` gives the
    description data (a mapping) of a robot named in `extends`; None: only files beside it."""
    data = merged(Path(path), base, 0)
    model = check(RobotFileModel, data, str(path), RobotError, "robot file")
    return description(model, Path(path))


def merged(path: Path, base: Any, depth: int) -> dict[str, Any]:
    """The file's mapping with what it `extends` merged under it."""
    data = read_yaml(path, "robot file", RobotError)
    if not isinstance(data, dict):
        raise RobotError(f"{file_label(path)}: the robot file must be a mapping")
    parent = data.pop("extends", None)
    if parent is None:
        return data
    if depth >= MAX_EXTENDS:
        raise RobotError(f"{file_label(path)}: extends: more than {MAX_EXTENDS} files deep (a loop?)")
    if not isinstance(parent, str) or not parent:
        raise RobotError(f"{file_label(path)}: extends: must be a robot name or a robot file, got {short(parent)}")
    beside = path.parent / parent
    if beside.suffix in (".yaml", ".yml") or beside.is_file():
        under = merged(beside, base, depth + 1)
    elif base is not None:
        under = base(parent, f"{file_label(path)}: extends")
    else:
        raise RobotError(f"{file_label(path)}: extends: no robot file {parent!r} beside it")
    under = dict(under)
    changed = _paths(data)  # the parent's sources no longer cite what this file changes
    kept = {k: v for k, v in (under.get("sources") or {}).items() if not any(_related(k, p) for p in changed)}
    own = data.get("sources", {})
    # (not a mapping: the schema says so)
    return {**_merge(under, data), "sources": {**kept, **own} if isinstance(own, dict) else own}


def _paths(data: dict[str, Any], prefix: str = "") -> list[str]:
    """The dotted paths a file sets (a footprint and a list are set whole)."""
    out: list[str] = []
    for k, v in data.items():
        if k in ("name", "title", "sources") and not prefix:
            continue
        path = f"{prefix}{k}"
        out += _paths(v, path + ".") if isinstance(v, dict) and path not in REPLACED_WHOLE else [path]
    return out


def _related(source: str, changed: str) -> bool:
    """A source names the changed figure, a part of it, or a section it is in."""
    return source == changed or source.startswith(changed + ".") or changed.startswith(source + ".")


def _merge(under: dict[str, Any], over: dict[str, Any]) -> dict[str, Any]:
    out = dict(under)
    for k, v in over.items():
        if isinstance(v, dict) and isinstance(out.get(k), dict) and k not in REPLACED_WHOLE:
            out[k] = _merge(out[k], v)
        else:
            out[k] = v
    return out


def description(m: RobotFileModel, path: Path) -> RobotDescription:
    """The checked file as the suite's description, with the defaults that follow from the body."""
    fp = Footprint(m.footprint.radius_m or 0.0, tuple(m.footprint.polygon or ()))
    radius = fp.circumradius_m
    c = m.cues
    mounts = CueMounts(
        signal_height_m=c.signal_height_m if c.signal_height_m is not None else m.height_m + 0.05,
        signal_offset_m=c.signal_offset_m if c.signal_offset_m is not None else radius + 0.07,
        gauge_height_m=c.gauge_height_m if c.gauge_height_m is not None else m.height_m + 0.25,
        bubble_height_m=c.bubble_height_m if c.bubble_height_m is not None else m.height_m + 0.6,
    )
    model = ""
    if m.look.model is not None:
        found = (path.parent / m.look.model).resolve()
        if not found.is_file():
            raise RobotError(f"{file_label(path)}: look.model: no file {m.look.model!r} beside the robot file")
        if found.suffix.lower() not in (".glb", ".gltf"):
            raise RobotError(
                f"{file_label(path)}: look.model: must be a glTF file (.glb or .gltf), got {m.look.model!r}"
            )
        model = str(found)
    kin = Kinematics(m.kinematics)
    lateral = m.limits.max_lateral_speed_mps
    if kin is not Kinematics.DIFF_DRIVE and lateral == 0.0:
        lateral = m.limits.max_linear_speed_mps  # holonomic: as fast sideways unless the file says
    return RobotDescription(
        name=m.name,
        title=m.title,
        kinematics=kin,
        footprint=fp,
        height_m=m.height_m,
        mass_kg=m.mass_kg,
        limits=Limits(
            m.limits.max_linear_speed_mps,
            m.limits.max_angular_speed_rps,
            m.limits.max_linear_accel_mps2,
            m.limits.max_angular_accel_rps2,
            lateral,
        ),
        motion=Motion(
            m.motion.cruise_speed_mps, m.motion.max_turn_rate_rps, rotate_in_place=kin is Kinematics.DIFF_DRIVE
        ),
        battery=Battery(
            m.battery.capacity_m, m.battery.idle_drain_per_s, m.battery.drain_per_rad, m.battery.charge_rate_per_s
        ),
        lidar=Lidar(
            m.lidar.beams, m.lidar.range_min_m, m.lidar.range_max_m, m.lidar.rate_hz, m.lidar.height_m, m.lidar.frame
        ),
        cues=mounts,
        drive=DriveForce(m.drive.max_force_n, m.drive.max_torque_nm),
        frames=Frames(m.frames.base, m.frames.base_link, m.frames.base_link_height_m),
        look=Look(tuple(Primitive(p.shape, p.size, p.at, p.rpy, p.colour, p.spin) for p in m.look.primitives), model),
        flight=None
        if m.flight is None
        else Flight(
            m.flight.cruise_height_m, m.flight.climb_rate_mps, m.flight.clearance_m, m.flight.person_distance_m
        ),
        sources=dict(m.sources),
        source_file=str(path),
    )
