"""HAVEN's AR cues as marker data and what they show, for any set of registered cues.

The cues are plugins of kind `haven.cues` (`cue_kind`; HAVEN's four in `builtin_cues`, registered
as a lab's are): CUES names them in order, HAVEN's first. `Toggles` is the study condition (which
cues are on: the viz node's run-time parameters, one per cue); `ArCues` keeps one robot's path
(`cue_kind.TrackedPath`) and asks each cue that is on what it shows; `CueState` is what is shown as
data, which the viz node publishes on /haven/cue_state and metrics and the simulated participants
read: nothing has to be inferred from marker namespaces and ids. Its JSON has the value of each cue
the robot has under the cue's key (HAVEN's: path_markers, turn_signal, thought, battery_level) and
the toggles. A cue serves some kinds of robot (`cue_kind.serves`): a robot has only those
(`cues_for`), and a toggle of a cue it does not have shows nothing (condition `all`: every cue it has).
"""

from __future__ import annotations

import dataclasses
import json
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from haven_sim.common import contain, plugins
from haven_sim.common.geometry import Point, Pose2D
from haven_sim.common.params import config, param
from haven_sim.robots.description import Kinematics, RobotDescription
from haven_sim.robots.fields import DEFAULT
from haven_viz.builtin_cues import (
    BATTERY_NS,
    PATH_NS,
    SCHEMES,
    SIGNAL_NS,
    THOUGHT_NS,
    CueParams,
    PathProjection,
    TurnSignals,
    battery_color,
)
from haven_viz.cue_kind import NO_MANOEUVRE, Cue, CueContext, CueSpec, TrackedPath, serves
from haven_viz.markers import MarkerSpec

__all__ = [
    "BATTERY_NS",
    "CUES",
    "PATH_NS",
    "SCHEMES",
    "SIGNAL_NS",
    "THOUGHT_NS",
    "ArCues",
    "CueParams",
    "CueState",
    "Toggles",
    "battery_color",
]

RESERVED_KEYS = frozenset({"stamp", "toggles"})
CASTS: dict[str, Any] = {"path_markers": int, "turn_signal": int, "thought": str, "battery_level": float}


def cue_specs(reg: plugins.Registry) -> dict[str, CueSpec]:
    """name -> spec of every cue in the registry, by rank (HAVEN's four: 0 to 3); a cue whose state
    key another cue already has is left out, with one line in the registry's problems."""
    out: dict[str, CueSpec] = {}
    keys: dict[str, str] = {}
    for name, item in sorted(reg.items.items(), key=lambda kv: kv[1].value.rank):  # (stable: ours first, then by name)
        key = item.value.key
        if key in keys or key in RESERVED_KEYS:
            why = f"its state key {key!r} is taken" + (f" by cue {keys[key]}" if key in keys else "")
            reg.problems.append(f"{plugins.GROUP_PREFIX}cues {name} ({item.target}, from {item.package}): {why}")
            reg.left_out[name] = why
            del reg.items[name]
            continue
        keys[key] = name
        out[name] = item.value
    return out


CUE_SPECS = cue_specs(plugins.registry("cues"))
CUES: tuple[str, ...] = tuple(CUE_SPECS)
# condition `all` (library cues are named)
DEFAULT_ON: tuple[str, ...] = tuple(c for c in CUES if CUE_SPECS[c].default_on)


def cues_for(kind: Kinematics | str) -> tuple[str, ...]:
    """The registered cues a robot of this kind has, in order."""
    return tuple(c for c in CUES if serves(CUE_SPECS[c], kind))


def unknown_cue(name: object) -> str:
    """Why `name` names no cue here: a cue installed but left out (and why), or the cues there are."""
    left_out = plugins.registry("cues").left_out
    if isinstance(name, str) and name in left_out:
        return f"cue {name!r} is installed but left out: {left_out[name]}"
    return f"unknown cue {str(name)[:50]!r} (cues: {', '.join(CUES)}, or all / none)"


def unfit(on: Sequence[str], robot: RobotDescription) -> str | None:
    """Why a condition that names the cues `on` cannot be shown on this robot (a cue that does not
    serve its kind, e.g. a floor projection on a drone), or None. Condition `all` names none: it is
    every cue the robot has."""
    if tuple(on) == DEFAULT_ON:
        return None
    for name in on:
        spec = CUE_SPECS[name]
        if not serves(spec, robot.kinematics):
            return (
                f"cue {name} does not fit robot {robot.name} ({robot.kinematics.value}): "
                f"it serves {', '.join(spec.kinematics)} robots"
            )
    return None


class CueToggles:
    """The study condition: which cues the participant sees. A frozen dataclass with one bool per
    registered cue (`Toggles`), so they are the viz node's parameters like any config."""

    if TYPE_CHECKING:

        def __init__(self, **on: bool) -> None: ...

    def on(self, cue: str) -> bool:
        return bool(getattr(self, cue, False))

    def names_on(self) -> list[str]:
        return [c for c in CUES if self.on(c)]

    def replaced(self, changes: Mapping[str, bool]) -> CueToggles:
        return dataclasses.replace(self, **changes)  # type: ignore[type-var]

    @classmethod
    def none(cls) -> CueToggles:
        return cls(**{c: False for c in CUES})


Toggles: type[CueToggles] = config(
    dataclasses.make_dataclass(
        "Toggles",
        [(c, bool, param(CUE_SPECS[c].default_on, "cue toggle (study condition)", runtime=True)) for c in CUES],
        bases=(CueToggles,),
        frozen=True,
        module=__name__,
    )
)


@dataclass(frozen=True)
class CueState:
    """What the participant is shown at one moment: each cue's value (its `hidden` value while it
    is off in the condition or has nothing to show), by the cue's key."""

    toggles: CueToggles = field(default_factory=Toggles)
    values: Mapping[str, Any] = field(default_factory=dict)
    cues: tuple[str, ...] = CUES  # the cues the robot has

    def __post_init__(self) -> None:  # every cue's value, hidden ones too (so equal states compare equal)
        specs = [CUE_SPECS[c] for c in self.cues if c in CUE_SPECS]
        object.__setattr__(self, "values", {spec.key: self.values.get(spec.key, spec.hidden) for spec in specs})

    def value(self, cue: str) -> Any:
        spec = CUE_SPECS[cue]
        return self.values.get(spec.key, spec.hidden)

    def shown(self, cue: str) -> bool:
        """The cue shows something now."""
        return bool(self.value(cue) != CUE_SPECS[cue].hidden)

    @property
    def path_markers(self) -> int:
        return int(self.value(PATH_NS))

    @property
    def turn_signal(self) -> int:
        return int(self.value(SIGNAL_NS))

    @property
    def thought(self) -> str:
        return str(self.value(THOUGHT_NS))

    @property
    def battery_level(self) -> float | None:
        level = self.value(BATTERY_NS)
        return None if level is None else float(level)

    def to_json(self, stamp: float) -> str:
        toggles = {c: on for c, on in dataclasses.asdict(self.toggles).items() if c in self.cues}  # type: ignore[call-overload]
        # (the console lists these)
        return json.dumps({"stamp": round(stamp, 4), "toggles": toggles, **self.values}, sort_keys=True)

    @staticmethod
    def from_json(text: str) -> tuple[float, CueState]:
        """(stamp, state) of a /haven/cue_state message (cues not installed here are left out);
        ValueError on anything else."""
        try:
            if len(text) > 65536:
                raise ValueError(f"{len(text)} characters")
            d = json.loads(text)
            toggles = Toggles(**{k: bool(v) for k, v in d["toggles"].items() if k in CUES})
            # (the robot's: each has its value, hidden or not)
            cues = tuple(c for c in CUE_SPECS if CUE_SPECS[c].key in d)
            values = {CUE_SPECS[c].key: d[CUE_SPECS[c].key] for c in cues}
            for key, cast in CASTS.items():  # (HAVEN's values, checked; a lab's cue's are its JSON)
                if values.get(key) is not None:
                    values[key] = cast(values[key])
            return float(d["stamp"]), CueState(toggles, values, cues)
        except (ValueError, KeyError, TypeError, AttributeError, RecursionError) as e:
            raise ValueError(f"not a cue state: {str(e)[:80]}") from None


@dataclass(frozen=True)
class CueFrame:
    markers: list[MarkerSpec]
    state: CueState
    # cue -> (the way it shows, drawn on the robot)
    ways: dict[str, tuple[tuple[Point, ...], bool]] = field(default_factory=dict)


class ArCues:
    """The cues of one robot: the path it follows and one object per cue (`names`: all registered)
    that serves the robot's kind (the others it does not have). A cue whose code raises or overruns its
    deadline (common/contain.py) is in `failed` and shows nothing from then on; the viz says so (a
    `plugin_failed` event), which ends the trial, not valid."""

    def __init__(
        self, params: CueParams | None = None, names: Sequence[str] | None = None, robot: RobotDescription = DEFAULT
    ) -> None:
        self.params = params or CueParams()
        self.robot = robot
        # cue -> its error, for a cue whose code raised (it shows nothing from then on)
        self.failed: dict[str, str] = {}
        self.cues: dict[str, Cue] = {}
        self.names = tuple(
            n
            for n in (CUES if names is None else names)
            if n not in CUE_SPECS or serves(CUE_SPECS[n], robot.kinematics)
        )
        flight = robot.flight
        self.flight_z_m = (
            flight.cruise_height_m if flight is not None and robot.kinematics is Kinematics.AERIAL else 0.0
        )
        for n in self.names:
            try:
                self.cues[n] = contain.call("cues", n, CUE_SPECS[n].make, self.params)
            except contain.PluginFailed as e:
                self.failed[n] = e.error
        self.set_path([])
        self.manoeuvre = NO_MANOEUVRE  # the navigator's pass under way (the viz reads it from its events)

    def set_path(self, poses: Sequence[Pose2D]) -> None:
        self.path = TrackedPath(poses, self.params.marker_spacing_m)

    def frame(
        self,
        robot: Pose2D,
        humans: Sequence[Point] = (),
        battery_level: float | None = None,
        thought: str = "",
        toggles: CueToggles | None = None,
        now: float | None = None,
        markers: bool = True,
        altitude_m: float = 0.0,
        thought_everywhere: bool = False,
    ) -> CueFrame:
        """Every marker of the cues on in `toggles` (default: all) for this moment, and what they show.
        With the time `now`, a lit turn signal is held at least `turn_signal_hold_s`. `markers=False`:
        what they show only, no markers (no one reads them in batch mode). `altitude_m`: the robot's
        height above the floor (/odom), where its cues are drawn; `thought_everywhere`: the thought is
        the researcher's, to be shown at any distance."""
        toggles = Toggles() if toggles is None else toggles
        self.path.advance(robot)
        r = self.robot
        ctx = CueContext(
            robot,
            self.path,
            humans,
            battery_level,
            thought,
            now,
            r.height_m,
            r.cues,
            altitude_m,
            self.flight_z_m,
            r.motion.cruise_speed_mps,
            r.footprint.width_m / 2.0,
            self.manoeuvre,
            thought_everywhere,
        )
        out: list[MarkerSpec] = []
        values: dict[str, Any] = {}
        ways: dict[str, tuple[tuple[Point, ...], bool]] = {}
        for name, cue in self.cues.items():
            if name in self.failed or not toggles.on(name):
                continue
            try:
                shown = contain.call("cues", name, cue.show, ctx, markers)
            except contain.PluginFailed as e:
                self.failed[name] = e.error
                continue
            if shown is None:
                continue
            values[CUE_SPECS[name].key] = shown.value
            out += shown.markers
            if shown.way:
                ways[name] = (shown.way, shown.on_robot)
        return CueFrame(out, CueState(toggles, values, self.names), ways)

    def markers(
        self,
        robot: Pose2D,
        humans: Sequence[Point] = (),
        battery_level: float | None = None,
        thought: str = "",
        toggles: CueToggles | None = None,
    ) -> list[MarkerSpec]:
        return self.frame(robot, humans, battery_level, thought, toggles).markers

    def shown_points(self, robot: Pose2D) -> list[Point]:
        """Where the projected path's markers not yet consumed are (all of them, whatever `steps_ahead`),
        nearest the robot first, after the robot reached `robot` (what a participant can look at)."""
        self.path.advance(robot)
        shown = PathProjection(dataclasses.replace(self.params, steps_ahead=0)).show(
            CueContext(robot, self.path), markers=False
        )
        return list(shown.way) if shown is not None else []

    def signal_side(self, robot: Pose2D, now: float | None = None) -> int:
        """The turn signal's side now (+1 left, -1 right, 0 dark)."""
        self.path.advance(robot)
        signals = self.cues.get(SIGNAL_NS)
        return signals.side(robot, self.path, now, self.manoeuvre) if isinstance(signals, TurnSignals) else 0
