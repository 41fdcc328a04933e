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
problem in one line (`WorldError`); nothing starts on an invalid world. The file is read by
`haven_sim.common.yaml_file` (at most 1 MiB of UTF-8, bounded nesting and aliases); the limits on
coordinates, the world's extent, polygons and the bodies' clearance at start are in `world_checks`.
"""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import Any

from haven_sim.common.bodies import HUMAN_BODY, ROBOT_BODY
from haven_sim.common.geometry import Point, Pose2D, polygon_area, segment_to_polygon
from haven_sim.common.yaml_file import file_label, finite, read_yaml, short, shown_key
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
from haven_sim.sim.world_checks import MAX_COORDINATE_M, MAX_EXTENT_M, MAX_POLYGON_VERTICES, overlapping_shape, polygon_problem, span_problem

GEM_OWNERS = ("robot", "human")
_ID_RE = re.compile(r"[A-Za-z][A-Za-z0-9_]{0,63}")
MAX_NAME_CHARS = 64


def _ccw(polygon: list[Point]) -> tuple[Point, ...]:
    """Counter-clockwise vertex order, so every edge's outward normal is (dy, -dx)."""
    return tuple(polygon if polygon_area(polygon) > 0 else polygon[::-1])


def load_world(path: str | Path) -> World:
    return parse_world(read_yaml(path, "world file", WorldError), source=str(path))


def parse_world(data: Any, source: str = "<world>") -> World:
    return _Parser(source).world(data)


class _Parser:
    """Reads the raw YAML tree, always knowing the key path for error messages."""

    def __init__(self, source: str) -> None:
        self.source = source

    def fail(self, key: str, message: str) -> WorldError:
        return WorldError(f"{file_label(self.source)}: {key}: {message}")

    # -- scalars ---------------------------------------------------------------------------
    def number(self, value: Any, key: str, positive: bool = False, limit: float = math.inf) -> float:
        """A finite number; `positive`: a length (> 0), at most `limit`; else within ±`limit`."""
        f = finite(value)
        if f is None:
            raise self.fail(key, f"must be a finite number, got {short(value)}")
        if positive and f <= 0:
            raise self.fail(key, f"must be positive, got {short(value)}")
        if abs(f) > limit:
            bound = f"at most {limit:g} m" if positive else f"within ±{limit:g} m"
            raise self.fail(key, f"must be {bound}, got {f:g}")
        return f

    def length(self, value: Any, key: str) -> float:
        return self.number(value, key, positive=True, limit=MAX_EXTENT_M)

    def point(self, value: Any, key: str) -> Point:
        if not isinstance(value, (list, tuple)) or len(value) != 2:
            raise self.fail(key, f"must be a point [x, y], got {short(value)}")
        return (self.number(value[0], f"{key}[0]", limit=MAX_COORDINATE_M), self.number(value[1], f"{key}[1]", limit=MAX_COORDINATE_M))

    def pose(self, value: Any, key: str) -> Pose2D:
        if not isinstance(value, (list, tuple)) or len(value) not in (2, 3):
            raise self.fail(key, f"must be a pose [x, y, yaw], got {short(value)}")
        yaw = self.number(value[2], f"{key}[2]") if len(value) == 3 else 0.0
        x, y = self.point(value[:2], key)
        return Pose2D(x, y, yaw)

    def ident(self, value: Any, key: str) -> str:
        if not isinstance(value, str) or not _ID_RE.fullmatch(value):
            raise self.fail(key, f"must be a name of up to {MAX_NAME_CHARS} letters, digits and '_' starting with a letter, got {short(value)}")
        return value

    def mapping(self, value: Any, key: str, allowed: set[str], required: set[str]) -> dict[str, Any]:
        if not isinstance(value, dict):
            raise self.fail(key, f"must be a mapping, got {type(value).__name__}")
        unknown = sorted(shown_key(k) for k in value if k not in allowed)
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
                raise self.fail(f"{key}.segment", f"must be two points [[x0, y0], [x1, y1]], got {short(seg)}")
            a = self.point(seg[0], f"{key}.segment[0]")
            b = self.point(seg[1], f"{key}.segment[1]")
            if "thickness" not in m:
                raise self.fail(f"{key}.thickness", "is required with 'segment'")
            thickness = self.length(m["thickness"], f"{key}.thickness")
            if math.hypot(b[0] - a[0], b[1] - a[1]) < 1e-9:
                raise self.fail(f"{key}.segment", "has zero length")
            return Shape(_ccw(segment_to_polygon(a, b, thickness)), kind, id_)
        if "thickness" in m:
            raise self.fail(f"{key}.thickness", "only applies to 'segment'")
        raw = self.seq(m["polygon"], f"{key}.polygon")
        if len(raw) < 3:
            raise self.fail(f"{key}.polygon", f"needs at least 3 points, got {len(raw)}")
        if len(raw) > MAX_POLYGON_VERTICES:
            raise self.fail(f"{key}.polygon", f"has {len(raw)} points; at most {MAX_POLYGON_VERTICES}")
        pts = [self.point(v, f"{key}.polygon[{i}]") for i, v in enumerate(raw)]
        if abs(polygon_area(pts)) < 1e-9:
            raise self.fail(f"{key}.polygon", "has zero area")
        problem = polygon_problem(pts)
        if problem:
            raise self.fail(f"{key}.polygon", problem)
        return Shape(_ccw(pts), kind, id_)

    def world(self, data: Any) -> World:
        top = {"name", "walls", "obstacles", "rooms", "hallways", "charging_base", "robot", "humans", "gems", "obstructions"}
        if data is None:
            raise self.fail("name", "the world file is empty")
        d = self.mapping(data, "", top, {"name", "walls", "robot"})
        if not isinstance(d["name"], str) or not d["name"] or not d["name"].isprintable() or len(d["name"]) > MAX_NAME_CHARS:
            raise self.fail("name", f"must be a non-empty line of at most {MAX_NAME_CHARS} characters, got {short(d['name'])}")
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
        self.check_extent(world)
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
            hallways.append(Hallway(self.ident(m["name"], f"{k}.name"), points, self.length(m["width"], f"{k}.width")))
        self.unique([h.name for h in hallways], "hallways", "name")
        return tuple(hallways)

    def charging_base(self, value: Any) -> ChargingBase | None:
        if value is None:
            return None
        m = self.mapping(value, "charging_base", {"position", "radius"}, {"position"})
        radius = self.length(m.get("radius", 0.5), "charging_base.radius")
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
                raise self.fail(f"{k}.owner", f"must be one of {', '.join(GEM_OWNERS)}, got {short(m['owner'])}")
            radius = self.length(m.get("radius", 0.3), f"{k}.radius")
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
            if trigger is not None and (not isinstance(trigger, str) or trigger not in room_names):
                raise self.fail(f"{k}.removed_when_human_reaches", f"names no room in 'rooms', got {short(trigger)}")
            obstructions.append(Obstruction(oid, shape, trigger))
        self.unique([o.id for o in obstructions], "obstructions", "id")
        return tuple(obstructions)

    def unique(self, names: list[str], key: str, attr: str) -> None:
        seen: set[str] = set()
        for i, n in enumerate(names):
            if n in seen:
                raise self.fail(f"{key}[{i}].{attr}", f"duplicate {attr} {short(n)}")
            seen.add(n)

    def check_extent(self, world: World) -> None:
        """Everything within a MAX_EXTENT_M square, so the occupancy grids stay small."""
        items: list[tuple[str, list[Point]]] = [(f"walls[{i}]", list(s.polygon)) for i, s in enumerate(world.walls)]
        items += [(f"obstacles[{i}]", list(s.polygon)) for i, s in enumerate(world.obstacles)]
        items += [(f"obstructions[{i}]", list(o.shape.polygon)) for i, o in enumerate(world.obstructions)]
        items += [("robot.start", [world.robot_start[:2]])] + [(f"humans[{i}].start", [h.start[:2]]) for i, h in enumerate(world.humans)]
        items += [(f"gems[{i}].position", [g.position]) for i, g in enumerate(world.gems)]
        items += [(f"rooms[{i}].centre", [r.centre]) for i, r in enumerate(world.rooms)]
        items += [(f"hallways[{i}].centreline", list(h.centreline)) for i, h in enumerate(world.hallways)]
        items += [("charging_base.position", [world.charging_base.position])] if world.charging_base else []
        problem = span_problem(items)
        if problem:
            raise self.fail(*problem)

    def check_free(self, world: World) -> None:
        """The robot's and each person's whole body (a disc of its radius) clear of solid geometry at start."""
        shapes = world.solid_shapes()
        checks = [("robot.start", world.robot_start, "the robot", ROBOT_BODY.radius_m)]
        checks += [(f"humans[{i}].start", h.start, "the person", HUMAN_BODY.radius_m) for i, h in enumerate(world.humans)]
        for key, pose, who, radius in checks:
            hit = overlapping_shape(shapes, pose.x, pose.y, radius)
            if hit is None:
                continue
            shape, centre_inside = hit
            what = f"{shape.kind} {shape.id}".strip()
            article = "an" if what[0] in "aeiou" else "a"
            if centre_inside:
                raise self.fail(key, f"({pose.x:g}, {pose.y:g}) lies inside {article} {what}")
            raise self.fail(key, f"({pose.x:g}, {pose.y:g}) puts {who}'s body (radius {radius:g} m) into {article} {what}")
