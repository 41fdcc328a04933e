"""Scenario files: which world, whose task, which participant model, battery mode, time limit.

```yaml
name: hallway
world: hallway                 # a world shipped with haven_scenarios or haven_sim, or a path
kind: hallway                  # hallway (room centres in order) | retrieval (gems)
timeout_s: 240
end_on_contact: false
robot:
  route: [B, C, D, A]          # hallway: room centres in order
  order: nearest               # retrieval: nearest | random (seeded) gem order
  battery: {mode: off, capacity_m: 100.0, charge_until: 1.0, safety_factor: 1.2}
humans:
  - {id: h1, model: walker, route: [B, A, D, C], speed_mps: 1.0}   # walker | blocker | yielder | teleop
dwell_time_s: 3.0
```

Errors name the file and the key in one line (`ScenarioError`), like world files.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import Any

import yaml

from haven_sim.sim.world import World, WorldError, load_world

KINDS = ("hallway", "retrieval")
MODELS = ("walker", "blocker", "yielder", "teleop")
ORDERS = ("nearest", "random")
BATTERY_MODES = ("off", "on_arrival", "continuous")


class ScenarioError(ValueError):
    """A scenario file is missing or invalid; the message is one line for the user."""


@dataclass(frozen=True)
class BatteryPlan:
    mode: str = "off"
    capacity_m: float = 100.0
    charge_until: float = 1.0  # fraction of full at which charging stops
    safety_factor: float = 1.2  # continuous mode: go home when range <= this x distance home


@dataclass(frozen=True)
class HumanTask:
    id: str
    model: str = "walker"
    route: tuple[str, ...] = ()  # hallway: room names; retrieval: ignored (the human gems)
    speed_mps: float = 1.0


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
    source: str = ""


def scenario_names() -> list[str]:
    return sorted(p.stem for p in Path(str(resources.files("haven_scenarios") / "scenarios")).glob("*.yaml"))


def resolve_world(spec: str) -> Path:
    """A path, or a world shipped with haven_scenarios (scenario worlds) or haven_sim (test worlds)."""
    p = Path(spec)
    if p.suffix in (".yaml", ".yml") or p.exists():
        return p
    for package in ("haven_scenarios", "haven_sim"):
        candidate = Path(str(resources.files(package) / "worlds" / f"{spec}.yaml"))
        if candidate.exists():
            return candidate
    return p


def load_scenario(spec: str | Path) -> Scenario:
    path = Path(spec)
    if not (path.suffix in (".yaml", ".yml") or path.exists()):
        path = Path(str(resources.files("haven_scenarios") / "scenarios" / f"{spec}.yaml"))
        if not path.exists():
            raise ScenarioError(f"{spec}: no such scenario (shipped: {', '.join(scenario_names())})")
    try:
        data = yaml.safe_load(path.read_text(encoding="utf-8"))
    except OSError as e:
        raise ScenarioError(f"{path}: cannot read scenario file: {e.strerror}") from None
    except yaml.YAMLError as e:
        raise ScenarioError(f"{path}: YAML syntax error: {getattr(e, 'problem', None) or e}") from None
    return _parse(data, str(path))


def _parse(data: Any, source: str) -> Scenario:
    def fail(key: str, msg: str) -> ScenarioError:
        return ScenarioError(f"{source}: {key}: {msg}")

    def choice(value: Any, key: str, options: tuple[str, ...]) -> str:
        if value not in options:
            raise fail(key, f"must be one of {', '.join(options)}, got {value!r}")
        return str(value)

    def positive(value: Any, key: str) -> float:
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not value > 0:
            raise fail(key, f"must be a positive number, got {value!r}")
        return float(value)

    if not isinstance(data, dict):
        raise fail("name", "the scenario file must be a mapping")
    allowed = {"name", "world", "kind", "timeout_s", "end_on_contact", "robot", "humans", "dwell_time_s"}
    unknown = sorted(set(data) - allowed)
    if unknown:
        raise fail(unknown[0], f"unknown key (allowed: {', '.join(sorted(allowed))})")
    for key in ("name", "world", "kind"):
        if key not in data:
            raise fail(key, "is required")
    kind = choice(data["kind"], "kind", KINDS)
    world_path = resolve_world(str(data["world"]))
    try:
        world = load_world(world_path)
    except WorldError as e:
        raise ScenarioError(f"{source}: world: {e}") from None
    rooms = {r.name for r in world.rooms}
    robot = data.get("robot") or {}
    if not isinstance(robot, dict):
        raise fail("robot", "must be a mapping")
    route = tuple(str(r) for r in robot.get("route", ()))
    for i, r in enumerate(route):
        if r not in rooms:
            raise fail(f"robot.route[{i}]", f"names no room of world '{world.name}' (rooms: {', '.join(sorted(rooms))})")
    if kind == "hallway" and not route:
        raise fail("robot.route", "a hallway scenario needs the robot's room route")
    if kind == "retrieval" and not [g for g in world.gems if g.owner == "robot"]:
        raise fail("world", f"world '{world.name}' has no robot gems to retrieve")
    battery_raw = robot.get("battery") or {}
    mode = battery_raw.get("mode", "off")
    battery = BatteryPlan(
        mode=choice("off" if mode is False else mode, "robot.battery.mode", BATTERY_MODES),  # YAML reads `off` as false
        capacity_m=positive(battery_raw.get("capacity_m", 100.0), "robot.battery.capacity_m"),
        charge_until=positive(battery_raw.get("charge_until", 1.0), "robot.battery.charge_until"),
        safety_factor=positive(battery_raw.get("safety_factor", 1.2), "robot.battery.safety_factor"),
    )
    if battery.mode != "off" and world.charging_base is None:
        raise fail("robot.battery.mode", f"needs a charging_base in world '{world.name}'")
    humans = []
    world_humans = {h.id for h in world.humans}
    for i, h in enumerate(data.get("humans") or []):
        key = f"humans[{i}]"
        if not isinstance(h, dict) or "id" not in h:
            raise fail(f"{key}.id", "is required")
        if h["id"] not in world_humans:
            raise fail(f"{key}.id", f"names no human of world '{world.name}' (humans: {', '.join(sorted(world_humans))})")
        hroute = tuple(str(r) for r in h.get("route", ()))
        for j, r in enumerate(hroute):
            if r not in rooms:
                raise fail(f"{key}.route[{j}]", f"names no room of world '{world.name}'")
        humans.append(
            HumanTask(
                id=str(h["id"]),
                model=choice(h.get("model", "walker"), f"{key}.model", MODELS),
                route=hroute,
                speed_mps=positive(h.get("speed_mps", 1.0), f"{key}.speed_mps"),
            )
        )
    return Scenario(
        name=str(data["name"]),
        kind=kind,
        world=world,
        world_path=str(world_path),
        timeout_s=positive(data.get("timeout_s", 300.0), "timeout_s"),
        robot_route=route,
        robot_order=choice(robot.get("order", "nearest"), "robot.order", ORDERS),
        battery=battery,
        humans=tuple(humans),
        dwell_time_s=positive(data.get("dwell_time_s", 3.0), "dwell_time_s"),
        end_on_contact=bool(data.get("end_on_contact", False)),
        source=source,
    )
