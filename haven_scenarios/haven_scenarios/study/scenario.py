"""Scenario files: which world, whose task, which participant model, battery mode, time limit.

```yaml
name: hallway
world: hallway                 # a world shipped with haven_scenarios or haven_sim, or a path
kind: hallway                  # hallway (room centres in order) | retrieval (gems)
timeout_s: 240
end_on_contact: false
condition: [turn_signals]      # the cues shown unless the run says (--condition): all | none | cue names
cues: {steps_ahead: 5}         # cue parameters (the viz node's; a run's --params-file value wins)
robot:
  model: turtlebot2            # a robot (haven robots) or a robot file beside this one (a run's --robot wins)
  route: [B, C, D, A]          # hallway: room centres in order
  order: nearest               # retrieval: nearest | random (seeded) gem order
  battery: {mode: off, capacity_m: 100.0, charge_until: 1.0, safety_factor: 1.2}   # capacity_m: the pack
                                                                                   # (default: the robot's own)
  start: [2.0, 2.0, 0.0]       # where it starts (default: the world's robot start)
humans:
  - {id: h1, model: walker, route: [B, A, D, C], speed_mps: 1.0}   # walker | blocker | yielder | teleop
  - id: h2
    model: yielder
    params: {reaction_s: 1.0, fov_deg: 110}   # perception parameters
    start: [16.0, 16.0, 3.14]   # a start of this scenario's own (default: the world's start for h2)
dwell_time_s: 3.0
```

A simulated person's `params` are `person.PersonParams` (field of view, viewing distance, reaction
time, passing gap, ...; defaults from the literature, cited there); `HumanTask.params` holds them as
a frozen dataclass of numbers, so a sweep varies one with `dataclasses.replace(task.params, reaction_s=0.8)`.

Errors name the file and the key in one line (`ScenarioError`), like world files; the file is read
as they are (`haven_sim.common.yaml_file`: at most 1 MiB of UTF-8, bounded nesting and aliases), and
every key is type-checked (booleans are true or false, numbers finite, lists lists, ids strings).
"""

from __future__ import annotations

from dataclasses import dataclass, field, fields, replace
from difflib import get_close_matches
from importlib import resources
from pathlib import Path
from typing import Annotated, Any, Literal

from haven_scenarios.study.person import PersonParams
from haven_sim.common import contain, plugins
from haven_sim.common.geometry import Pose2D
from haven_sim.common.params import build
from haven_sim.common.schema import FileModel, Line, Positive, check, checked, listing
from haven_sim.common.yaml_file import file_label, finite, one_line, read_yaml, short, shown_key
from haven_sim.nav.planner import check_plannable
from haven_sim.robots.description import RobotDescription
from haven_sim.robots.fields import DEFAULT
from haven_sim.robots.robot_file import RobotError
from haven_sim.robots.robot_kind import DEFAULT_ROBOT, is_file_spec, resolve_robot
from haven_sim.sim.world import World, WorldError
from haven_sim.sim.world_checks import MAX_COORDINATE_M, overlapping_shape
from haven_sim.sim.world_file import check_starts, load_world
from haven_viz.cues import CUES, CueParams, unfit, unknown_cue

TELEOP = "teleop"  # a person drives this avatar (the browser or `haven teleop`), no simulated model
MAX_WALKING_SPEED_MPS = 3.0
MAX_TIMEOUT_S = 24 * 3600.0  # also the longest dwell
MAX_NAME_CHARS = 64


class ScenarioError(ValueError):
    """A scenario file is missing or invalid; the message is one line for the user."""


@dataclass(frozen=True)
class BatteryPlan:
    mode: str = "off"
    capacity_m: float = 100.0
    charge_until: float = 1.0  # fraction of full at which charging stops
    safety_factor: float = 1.2  # continuous mode: go home when range <= this x distance home
    drain_factor: float = 1.0  # charge used per metre, in metres: 1 + what the time at cruise drains (a drone hovers)
    # the robot drains while it waits (a drone hovers): return-to-home failsafe in every mode
    drains_waiting: bool = False


@dataclass(frozen=True)
class HumanTask:
    id: str
    model: str = "walker"
    route: tuple[str, ...] = ()  # hallway: room names; retrieval: ignored (the human gems)
    speed_mps: float = 1.0
    params: PersonParams = field(default_factory=PersonParams)  # a simulated person's perception and walk

    @property
    def teleoperated(self) -> bool:
        return self.model == TELEOP


@dataclass(frozen=True)
class Scenario:
    name: str
    kind: str
    world: World
    world_path: str
    timeout_s: float
    robot_route: tuple[str, ...] = ()
    robot_order: str = "nearest"
    battery: BatteryPlan = field(default_factory=BatteryPlan)
    humans: tuple[HumanTask, ...] = ()
    dwell_time_s: float = 3.0
    end_on_contact: bool = False
    condition: tuple[str, ...] = ("all",)  # the cues shown unless a run picks a condition
    cues: CueParams = field(default_factory=CueParams)  # as the scenario file sets them
    source: str = ""
    robot: RobotDescription = DEFAULT  # robot: model (a run's --robot replaces it: `for_robot`)
    robot_model: str = DEFAULT_ROBOT  # ... as named: a robot's name or a robot file
    pack_m: float | None = None  # robot.battery.capacity_m as the file gives it (None: the robot's own pack)

    def for_robot(self, robot: RobotDescription, model: str | None = None) -> Scenario:
        """This scenario with `robot` (named `model`: a name or a file; default its name); its battery
        pack is the file's, else the robot's own. ScenarioError (one line) if the robot's body does
        not fit at the world's robot start."""
        start = self.world.robot_start
        hit = overlapping_shape(self.world.solid_shapes(), start.x, start.y, robot.radius_m)
        if hit is not None:
            what = f"{hit[0].kind} {hit[0].id}".strip()
            raise ScenarioError(
                f"{self.source or self.name}: robot {robot.name!r} (radius {robot.radius_m:.2f} m) does not fit "
                f"at world '{self.world.name}''s robot start ({start.x:g}, {start.y:g}): its body overlaps a {what}"
            )
        pack = self.pack_m if self.pack_m is not None else robot.battery.capacity_m
        # (1 for a robot that drains only as it moves)
        drain = 1.0 + robot.battery.idle_drain_per_s * pack / robot.motion.cruise_speed_mps
        battery = replace(
            self.battery, capacity_m=pack, drain_factor=drain, drains_waiting=robot.battery.idle_drain_per_s > 0
        )
        return replace(self, robot=robot, robot_model=model or robot.name, battery=battery)


def scenario_names() -> list[str]:
    return sorted(p.stem for p in Path(str(resources.files("haven_scenarios") / "scenarios")).glob("*.yaml"))


def resolve_world(spec: str, base: Path | None = None) -> Path:
    """A path (relative to `base`, the scenario file's folder, when the file is there), or a world
    shipped with haven_scenarios (scenario worlds) or haven_sim (test worlds)."""
    p = Path(spec)
    if base is not None and not p.is_absolute() and _exists(base / p):
        return base / p
    if p.suffix in (".yaml", ".yml") or _exists(p):
        return p
    for package in ("haven_scenarios", "haven_sim"):
        candidate = Path(str(resources.files(package) / "worlds" / f"{spec}.yaml"))
        if _exists(candidate):
            return candidate
    if not p.suffix and len(p.parts) == 1:  # a name, not a path: say which names there are
        shipped = world_names()
        close = get_close_matches(spec, shipped, n=1)
        hint = f"did you mean {close[0]!r}? " if close else ""
        raise WorldError(
            f"{spec}: no such world file and no shipped world of that name ({hint}shipped: {', '.join(shipped)})"
        )
    return p


def world_names() -> list[str]:
    """The worlds shipped with haven_scenarios (the scenarios' worlds)."""
    return sorted(p.stem for p in Path(str(resources.files("haven_scenarios") / "worlds")).glob("*.yaml"))


def _exists(p: Path) -> bool:
    """`p.exists()`, False for a name no file can have (a NUL byte, too long)."""
    try:
        return p.exists()
    except (OSError, ValueError):
        return False


def load_scenario(spec: str | Path, world: str | None = None) -> Scenario:
    """A shipped scenario by name, or a scenario file; `world` (a packaged world name or a world
    file) plays it in another world, which must have the rooms, gems and humans it names."""
    path = Path(spec)
    if not (path.suffix in (".yaml", ".yml") or _exists(path)):
        path = Path(str(resources.files("haven_scenarios") / "scenarios" / f"{spec}.yaml"))
        if not _exists(path):
            raise ScenarioError(f"{file_label(spec)}: no such scenario (shipped: {', '.join(scenario_names())})")
    data = read_yaml(path, "scenario file", ScenarioError)
    if world is not None and isinstance(data, dict):
        data = {**data, "world": str(Path(world).resolve()) if _exists(Path(world)) else world}
    return parse_scenario(data, str(path))


def parse_scenario(data: Any, source: str) -> Scenario:
    """A scenario from its YAML tree (`source`: the file, for messages and to find a relative world)."""
    return _ScenarioParser(source).scenario(check(ScenarioFile, data, source, ScenarioError, "scenario file"))


class BatteryFile(FileModel):
    # (YAML reads `off` as false)
    mode: Annotated[Literal["off", "on_arrival", "continuous"], checked(lambda v: "off" if v is False else v)] = "off"
    # the pack in metres of travel (default: the robot's own)
    capacity_m: Positive() | None = None  # type: ignore[valid-type]
    charge_until: Positive() = 1.0  # type: ignore[valid-type]
    safety_factor: Positive() = 1.2  # type: ignore[valid-type]


class RobotFile(FileModel):
    # a robot (haven robots) or a robot file beside the scenario
    model: Line(4096) | None = None  # type: ignore[valid-type]
    route: Any = None  # room names of the world
    order: Any = "nearest"  # a mission behaviour
    battery: BatteryFile | None = None
    start: Any = None  # [x, y, yaw]: where the robot starts (default: the world's robot start)


class HumanFile(FileModel):
    id: Any  # a human of the world
    model: Any = "walker"  # a participant model, or teleop
    route: Any = None  # room names of the world
    speed_mps: Positive() = 1.0  # type: ignore[valid-type]
    params: dict[Any, Any] | None = None  # PersonParams fields
    start: Any = None  # [x, y, yaw]: where this person starts (default: the world's start for them)


class ScenarioFile(FileModel):
    """A scenario file's shape (the module docstring shows one); what it names is checked against
    its world and the registries as it is read."""

    name: Line(MAX_NAME_CHARS)  # type: ignore[valid-type]
    world: Line(4096)  # type: ignore[valid-type]
    kind: Literal["hallway", "retrieval"]
    timeout_s: Positive(MAX_TIMEOUT_S) = 300.0  # type: ignore[valid-type]
    end_on_contact: bool = False
    condition: Annotated[list[Any], listing("a list of cue names (or [all] / [none])")] = ["all"]  # noqa: RUF012 (a pydantic field: the default is copied per instance)
    cues: dict[Any, Any] | None = None  # CueParams fields
    robot: RobotFile | None = None
    humans: Annotated[list[HumanFile], listing("a list", non_empty=False)] | None = None
    dwell_time_s: Positive(MAX_TIMEOUT_S) = 3.0  # type: ignore[valid-type]


class _ScenarioParser:
    """What a scenario file names, checked against its world and the registries; every error
    names the file and the key in one line."""

    def __init__(self, source: str) -> None:
        self.source = source

    def fail(self, key: str, msg: str) -> ScenarioError:
        return ScenarioError(f"{file_label(self.source)}: {key}: {msg}")

    def registered(self, value: Any, key: str, kind: str) -> str:
        """The name of a registered plugin of `kind`."""
        reg = plugins.registry(kind)
        if not isinstance(value, str):
            raise self.fail(
                key, f"must be the name of a {contain.singular(kind)} ({', '.join(reg.names())}), got {short(value)}"
            )
        if value not in reg:
            raise self.fail(key, reg.unknown(value))
        return value

    def mapping(self, value: dict[Any, Any] | None, key: str, allowed: tuple[str, ...]) -> dict[str, Any]:
        unknown = sorted(shown_key(k) for k in value or {} if k not in allowed)
        if unknown:
            raise self.fail(f"{key}.{unknown[0]}", f"unknown key (allowed: {', '.join(sorted(allowed))})")
        return dict(value or {})

    def names(self, value: Any, key: str, known: set[str], what: str) -> tuple[str, ...]:
        """A list of names from `known` (rooms of the world)."""
        if value is None:
            return ()
        if not isinstance(value, list):
            raise self.fail(key, f"must be a list of {what} names, got {short(value)}")
        for i, name in enumerate(value):
            if not isinstance(name, str) or name not in known:
                raise self.fail(
                    f"{key}[{i}]", f"names no {what} of the world (known: {_listing(known)}), got {short(name)}"
                )
        return tuple(value)

    def scenario(self, f: ScenarioFile) -> Scenario:
        try:
            world_path = resolve_world(f.world, Path(self.source).parent)
            world = load_world(world_path)
            check_plannable(world, file_label(world_path))
        except WorldError as e:
            raise self.fail("world", str(e)) from None
        robot = f.robot or RobotFile()
        world = self.starts(world, robot.start, f.humans or [])
        route = self.names(robot.route, "robot.route", {r.name for r in world.rooms}, "room")
        if f.kind == "hallway" and not route:
            raise self.fail("robot.route", "a hallway scenario needs the robot's room route")
        if f.kind == "retrieval" and not [g for g in world.gems if g.owner == "robot"]:
            raise self.fail("world", f"world '{world.name}' has no robot gems to retrieve")
        battery = robot.battery or BatteryFile()
        scenario = Scenario(
            name=f.name,
            kind=f.kind,
            world=world,
            world_path=str(world_path),
            timeout_s=f.timeout_s,
            robot_route=route,
            robot_order=self.registered(robot.order, "robot.order", "missions"),
            battery=self.battery(battery, world),
            humans=self.humans(f.humans, world),
            dwell_time_s=f.dwell_time_s,
            end_on_contact=f.end_on_contact,
            condition=self.condition(f.condition),
            cues=self.cues(f.cues),
            source=self.source,
            pack_m=battery.capacity_m,
        )
        scenario = scenario.for_robot(*self.robot(robot.model))
        why = (
            unfit(list(scenario.condition), scenario.robot) if scenario.condition not in (("all",), ("none",)) else None
        )
        if why is not None:
            raise self.fail("condition", why)
        return scenario

    def starts(self, world: World, robot: Any, humans: list[HumanFile]) -> World:
        """The world with the starts the scenario gives (a world serves several scenarios), checked
        as a world file's starts are."""
        if robot is None and all(h.start is None for h in humans):
            return world
        pose = self.pose(robot, "robot.start") if robot is not None else world.robot_start
        given = {h.id: self.pose(h.start, f"humans[{i}].start") for i, h in enumerate(humans) if h.start is not None}
        people = tuple(replace(h, start=given.get(h.id, h.start)) for h in world.humans)
        moved = replace(world, robot_start=pose, humans=people)
        try:
            check_starts(moved, self.source)
        except WorldError as e:
            raise ScenarioError(str(e)) from None
        return moved

    def pose(self, value: Any, key: str) -> Pose2D:
        if (
            not isinstance(value, list)
            or len(value) not in (2, 3)
            or any(finite(v) is None or abs(v) > MAX_COORDINATE_M for v in value)
        ):
            raise self.fail(
                key, f"must be a pose [x, y, yaw] (metres within ±{MAX_COORDINATE_M:g}, radians), got {short(value)}"
            )
        return Pose2D(float(value[0]), float(value[1]), float(value[2]) if len(value) == 3 else 0.0)

    def robot(self, model: str | None) -> tuple[RobotDescription, str]:
        """The robot `robot.model` names (a name, or a file beside the scenario file), as named."""
        if model is None:
            return DEFAULT, DEFAULT_ROBOT
        spec = str(Path(self.source).parent / model) if is_file_spec(model) and not Path(model).is_absolute() else model
        try:
            return resolve_robot(spec), spec
        except RobotError as e:
            raise self.fail("robot.model", str(e)) from None

    def condition(self, value: list[Any]) -> tuple[str, ...]:
        for i, name in enumerate(value):
            if name not in (*CUES, "all", "none"):
                raise self.fail(f"condition[{i}]", unknown_cue(name))
        return tuple(value)

    def cues(self, value: dict[Any, Any] | None) -> CueParams:
        known = tuple(f.name for f in fields(CueParams))
        values = self.mapping(value, "cues", known)
        for name, v in values.items():  # an integer beyond a float's range (build would overflow converting it)
            if isinstance(v, int) and finite(v) is None:
                raise self.fail(f"cues.{name}", f"must be a finite number, got {short(v)}")
        try:
            return build(CueParams, values, where="cues.")
        except ValueError as e:
            raise self.fail("cues", str(e).removeprefix("cues.")) from None

    def battery(self, b: BatteryFile, world: World) -> BatteryPlan:
        if b.charge_until > 1.0:
            raise self.fail("robot.battery.charge_until", f"must be at most 1 (a full battery), got {b.charge_until:g}")
        if b.mode != "off" and world.charging_base is None:
            raise self.fail("robot.battery.mode", f"needs a charging_base in world '{world.name}'")
        return BatteryPlan(b.mode, b.capacity_m or DEFAULT.battery.capacity_m, b.charge_until, b.safety_factor)

    def humans(self, value: list[HumanFile] | None, world: World) -> tuple[HumanTask, ...]:
        known = {h.id for h in world.humans}
        rooms = {r.name for r in world.rooms}
        out: list[HumanTask] = []
        for i, m in enumerate(value or ()):
            key = f"humans[{i}]"
            if not isinstance(m.id, str) or m.id not in known:
                raise self.fail(
                    f"{key}.id",
                    f"names no human of world '{world.name}' (humans: {_listing(known)}), got {short(m.id)}",
                )
            if m.id in {t.id for t in out}:
                raise self.fail(f"{key}.id", f"duplicate id {short(m.id)}")
            if m.speed_mps > MAX_WALKING_SPEED_MPS:
                raise self.fail(
                    f"{key}.speed_mps",
                    f"must be at most {MAX_WALKING_SPEED_MPS:g} m/s (a brisk walk), got {m.speed_mps:g}",
                )
            route = self.names(m.route, f"{key}.route", rooms, "room")
            models = plugins.registry("participants")
            if isinstance(m.model, str) and m.model in models.left_out:
                raise self.fail(f"{key}.model", models.unknown(m.model))
            if m.model not in (*models.names(), TELEOP):
                raise self.fail(
                    f"{key}.model", f"must be one of {', '.join((*models.names(), TELEOP))}, got {short(m.model)}"
                )
            out.append(HumanTask(m.id, m.model, route, m.speed_mps, self.person(m.params, f"{key}.params")))
        return tuple(out)

    def person(self, value: dict[Any, Any] | None, key: str) -> PersonParams:
        """A person's `params`: numbers for `PersonParams` fields, checked in range."""
        values = self.mapping(value, key, tuple(f.name for f in fields(PersonParams)))
        for name, v in values.items():
            if isinstance(v, bool) or finite(v) is None:
                raise self.fail(f"{key}.{name}", f"must be a finite number, got {short(v)}")
        try:
            return PersonParams(**{name: float(v) for name, v in values.items()})
        except ValueError as e:
            raise self.fail(key, str(e)) from None


def _listing(names: set[str]) -> str:
    return one_line(", ".join(sorted(names)), 80)
