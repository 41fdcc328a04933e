"""The YAML world format and its validating loader.

A world is everything the simulator, planner and scenarios need to know about a place:

```yaml
name: small_test              # required
walls:                        # solid geometry; each item is either
  - segment: [[0, 0], [6, 0]] #   a centre line with a thickness (m) ...
    thickness: 0.1
  - polygon: [[2, 2], [3, 2], [3, 3]]   # ... or a simple polygon (any winding)
obstacles: [...]              # same shapes as walls (furniture); drawn differently
rooms:                        # named places; a centre is a navigation goal
  - {name: west, centre: [1.5, 2.0]}
hallways:                     # a centre line the robot should keep to, and its clear width
  - {name: main, centreline: [[3, 1], [3, 5]], width: 1.8}
charging_base: {position: [0.8, 0.8], radius: 0.5}
robot: {start: [1.0, 1.0, 0.0]}          # x, y, yaw (rad)
humans:
  - {id: h1, start: [5.0, 3.0, 3.14]}
gems:
  - {id: g1, owner: robot, position: [2.0, 3.0], radius: 0.3}
obstructions:                 # solid until removed (by a scenario rule)
  - {id: door, segment: [[4, 2], [4, 3]], thickness: 0.1, removed_when_human_reaches: east}
```

Units are metres and radians, frame `map` (REP-103). Every error names the file, the key and the
problem in one line (`WorldError`); nothing starts on an invalid world.
"""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import Any

import numpy as np
import yaml

from haven_sim.common.geometry import Point, Pose2D, points_in_polygon, polygon_area, segment_to_polygon
from haven_sim.sim.world import (
    ChargingBase,
    Gem,
    Hallway,
    HumanSpec,
    Obstruction,
    Room,
    Shape,
    World,
    WorldError,
)

GEM_OWNERS = ("robot", "human")
_ID_RE = re.compile(r"^[A-Za-z][A-Za-z0-9_]*$")


def _ccw(polygon: list[Point]) -> tuple[Point, ...]:
    """Counter-clockwise vertex order, so every edge's outward normal is (dy, -dx)."""
    return tuple(polygon if polygon_area(polygon) > 0 else polygon[::-1])


def load_world(path: str | Path) -> World:
    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except OSError as e:
        raise WorldError(f"{p}: cannot read world file: {e.strerror}") from None
    try:
        data = yaml.safe_load(text)
    except yaml.YAMLError as e:
        mark = getattr(e, "problem_mark", None)
        where = f" at line {mark.line + 1}" if mark is not None else ""
        problem = getattr(e, "problem", None) or "invalid YAML"
        raise WorldError(f"{p}: YAML syntax error{where}: {problem}") from None
    return parse_world(data, source=str(p))


def parse_world(data: Any, source: str = "<world>") -> World:
    return _Parser(source).world(data)


class _Parser:
    """Reads the raw YAML tree, always knowing the key path for error messages."""

    def __init__(self, source: str) -> None:
        self.source = source

    def fail(self, key: str, message: str) -> WorldError:
        return WorldError(f"{self.source}: {key}: {message}")

    # -- scalars ---------------------------------------------------------------------------
    def number(self, value: Any, key: str, positive: bool = False) -> float:
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
            raise self.fail(key, f"must be a finite number, got {value!r}")
        if positive and value <= 0:
            raise self.fail(key, f"must be positive, got {value!r}")
        return float(value)

    def point(self, value: Any, key: str) -> Point:
        if not isinstance(value, (list, tuple)) or len(value) != 2:
            raise self.fail(key, f"must be a point [x, y], got {value!r}")
        return (self.number(value[0], f"{key}[0]"), self.number(value[1], f"{key}[1]"))

    def pose(self, value: Any, key: str) -> Pose2D:
        if not isinstance(value, (list, tuple)) or len(value) not in (2, 3):
            raise self.fail(key, f"must be a pose [x, y, yaw], got {value!r}")
        yaw = self.number(value[2], f"{key}[2]") if len(value) == 3 else 0.0
        return Pose2D(self.number(value[0], f"{key}[0]"), self.number(value[1], f"{key}[1]"), yaw)

    def ident(self, value: Any, key: str) -> str:
        if not isinstance(value, str) or not _ID_RE.match(value):
            raise self.fail(key, f"must be a name of letters, digits and '_' starting with a letter, got {value!r}")
        return value

    def mapping(self, value: Any, key: str, allowed: set[str], required: set[str]) -> dict[str, Any]:
        if not isinstance(value, dict):
            raise self.fail(key, f"must be a mapping, got {type(value).__name__}")
        unknown = sorted(set(value) - allowed)
        if unknown:
            raise self.fail(f"{key}.{unknown[0]}" if key else unknown[0], f"unknown key (allowed: {', '.join(sorted(allowed))})")
        for r in sorted(required):
            if r not in value:
                raise self.fail(f"{key}.{r}" if key else r, "is required")
        return value

    def seq(self, value: Any, key: str) -> list[Any]:
        if value is None:
            return []
        if not isinstance(value, list):
            raise self.fail(key, f"must be a list, got {type(value).__name__}")
        return value

    # -- compound --------------------------------------------------------------------------
    def shape(self, item: Any, key: str, kind: str, extra: frozenset[str] = frozenset(), id_: str = "") -> Shape:
        m = self.mapping(item, key, {"segment", "polygon", "thickness"} | set(extra), set())
        if ("segment" in m) == ("polygon" in m):
            raise self.fail(key, "needs exactly one of 'segment' or 'polygon'")
        if "segment" in m:
            seg = m["segment"]
            if not isinstance(seg, list) or len(seg) != 2:
                raise self.fail(f"{key}.segment", f"must be two points [[x0, y0], [x1, y1]], got {seg!r}")
            a = self.point(seg[0], f"{key}.segment[0]")
            b = self.point(seg[1], f"{key}.segment[1]")
            if "thickness" not in m:
                raise self.fail(f"{key}.thickness", "is required with 'segment'")
            thickness = self.number(m["thickness"], f"{key}.thickness", positive=True)
            if math.hypot(b[0] - a[0], b[1] - a[1]) < 1e-9:
                raise self.fail(f"{key}.segment", "has zero length")
            return Shape(_ccw(segment_to_polygon(a, b, thickness)), kind, id_)
        if "thickness" in m:
            raise self.fail(f"{key}.thickness", "only applies to 'segment'")
        raw = self.seq(m["polygon"], f"{key}.polygon")
        if len(raw) < 3:
            raise self.fail(f"{key}.polygon", f"needs at least 3 points, got {len(raw)}")
        pts = [self.point(v, f"{key}.polygon[{i}]") for i, v in enumerate(raw)]
        if abs(polygon_area(pts)) < 1e-9:
            raise self.fail(f"{key}.polygon", "has zero area")
        return Shape(_ccw(pts), kind, id_)

    def world(self, data: Any) -> World:
        top = {"name", "walls", "obstacles", "rooms", "hallways", "charging_base", "robot", "humans", "gems", "obstructions"}
        if data is None:
            raise self.fail("name", "the world file is empty")
        d = self.mapping(data, "", top, {"name", "walls", "robot"})
        if not isinstance(d["name"], str) or not d["name"]:
            raise self.fail("name", f"must be a non-empty string, got {d['name']!r}")
        walls = self.shapes(d["walls"], "walls", "wall")
        if not walls:
            raise self.fail("walls", "needs at least one wall")
        rooms = self.rooms(d.get("rooms"))
        robot = self.mapping(d["robot"], "robot", {"start"}, {"start"})
        world = World(
            name=d["name"],
            walls=walls,
            obstacles=self.shapes(d.get("obstacles"), "obstacles", "obstacle"),
            rooms=rooms,
            hallways=self.hallways(d.get("hallways")),
            charging_base=self.charging_base(d.get("charging_base")),
            robot_start=self.pose(robot["start"], "robot.start"),
            humans=self.humans(d.get("humans")),
            gems=self.gems(d.get("gems")),
            obstructions=self.obstructions(d.get("obstructions"), {r.name for r in rooms}),
            source=self.source,
        )
        self.check_free(world)
        return world

    def shapes(self, value: Any, key: str, kind: str) -> tuple[Shape, ...]:
        return tuple(self.shape(w, f"{key}[{i}]", kind) for i, w in enumerate(self.seq(value, key)))

    def rooms(self, value: Any) -> tuple[Room, ...]:
        rooms = []
        for i, r in enumerate(self.seq(value, "rooms")):
            m = self.mapping(r, f"rooms[{i}]", {"name", "centre"}, {"name", "centre"})
            rooms.append(Room(self.ident(m["name"], f"rooms[{i}].name"), self.point(m["centre"], f"rooms[{i}].centre")))
        self.unique([r.name for r in rooms], "rooms", "name")
        return tuple(rooms)

    def hallways(self, value: Any) -> tuple[Hallway, ...]:
        hallways = []
        for i, h in enumerate(self.seq(value, "hallways")):
            k = f"hallways[{i}]"
            m = self.mapping(h, k, {"name", "centreline", "width"}, {"name", "centreline", "width"})
            line = self.seq(m["centreline"], f"{k}.centreline")
            if len(line) < 2:
                raise self.fail(f"{k}.centreline", "needs at least 2 points")
            points = tuple(self.point(p, f"{k}.centreline[{j}]") for j, p in enumerate(line))
            hallways.append(Hallway(self.ident(m["name"], f"{k}.name"), points, self.number(m["width"], f"{k}.width", positive=True)))
        self.unique([h.name for h in hallways], "hallways", "name")
        return tuple(hallways)

    def charging_base(self, value: Any) -> ChargingBase | None:
        if value is None:
            return None
        m = self.mapping(value, "charging_base", {"position", "radius"}, {"position"})
        radius = self.number(m.get("radius", 0.5), "charging_base.radius", positive=True)
        return ChargingBase(self.point(m["position"], "charging_base.position"), radius)

    def humans(self, value: Any) -> tuple[HumanSpec, ...]:
        humans = []
        for i, h in enumerate(self.seq(value, "humans")):
            m = self.mapping(h, f"humans[{i}]", {"id", "start"}, {"id", "start"})
            humans.append(HumanSpec(self.ident(m["id"], f"humans[{i}].id"), self.pose(m["start"], f"humans[{i}].start")))
        self.unique([h.id for h in humans], "humans", "id")
        return tuple(humans)

    def gems(self, value: Any) -> tuple[Gem, ...]:
        gems = []
        for i, g in enumerate(self.seq(value, "gems")):
            k = f"gems[{i}]"
            m = self.mapping(g, k, {"id", "owner", "position", "radius"}, {"id", "owner", "position"})
            if m["owner"] not in GEM_OWNERS:
                raise self.fail(f"{k}.owner", f"must be one of {', '.join(GEM_OWNERS)}, got {m['owner']!r}")
            radius = self.number(m.get("radius", 0.3), f"{k}.radius", positive=True)
            gems.append(Gem(self.ident(m["id"], f"{k}.id"), m["owner"], self.point(m["position"], f"{k}.position"), radius))
        self.unique([g.id for g in gems], "gems", "id")
        return tuple(gems)

    def obstructions(self, value: Any, room_names: set[str]) -> tuple[Obstruction, ...]:
        obstructions = []
        for i, o in enumerate(self.seq(value, "obstructions")):
            k = f"obstructions[{i}]"
            if not isinstance(o, dict) or "id" not in o:
                raise self.fail(f"{k}.id", "is required")
            oid = self.ident(o["id"], f"{k}.id")
            shape = self.shape(o, k, "obstruction", frozenset({"id", "removed_when_human_reaches"}), oid)
            trigger = o.get("removed_when_human_reaches")
            if trigger is not None and trigger not in room_names:
                raise self.fail(f"{k}.removed_when_human_reaches", f"names no room in 'rooms', got {trigger!r}")
            obstructions.append(Obstruction(oid, shape, trigger))
        self.unique([o.id for o in obstructions], "obstructions", "id")
        return tuple(obstructions)

    def unique(self, names: list[str], key: str, attr: str) -> None:
        seen: set[str] = set()
        for i, n in enumerate(names):
            if n in seen:
                raise self.fail(f"{key}[{i}].{attr}", f"duplicate {attr} {n!r}")
            seen.add(n)

    def check_free(self, world: World) -> None:
        """Start poses must not sit inside solid geometry."""
        shapes = world.solid_shapes()
        checks = [("robot.start", world.robot_start)] + [(f"humans[{i}].start", h.start) for i, h in enumerate(world.humans)]
        for key, pose in checks:
            xs, ys = np.array([pose.x]), np.array([pose.y])
            for s in shapes:
                if points_in_polygon(xs, ys, list(s.polygon))[0]:
                    what = f"{s.kind} {s.id}".strip()
                    article = "an" if what[0] in "aeiou" else "a"
                    raise self.fail(key, f"({pose.x:g}, {pose.y:g}) lies inside {article} {what}")
