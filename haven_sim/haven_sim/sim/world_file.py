"""The YAML world format and its validating loader.

A world is everything the simulator, planner and scenarios need to know about a place:

```yaml
name: small_test              # required
map: building.yaml            # optional: walls from a ROS map or floor plan (`map_file`), then
                              #   everything below is an overlay in map coordinates
walls:                        # solid geometry (required without `map`); each item is either
  - segment: [[0, 0], [6, 0]] #   a centre line with a thickness (m) ...
    thickness: 0.1
  - polygon: [[2, 2], [3, 2], [3, 3]]   # ... or a simple polygon (any winding)
obstacles: [...]              # same shapes as walls (furniture); drawn differently; an optional
  - {polygon: [[5, 1], [6, 1], [6, 2]], height: 0.75}   # height (m): a drone flies over what is lower
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
from collections.abc import Sequence
from dataclasses import replace
from pathlib import Path
from typing import Annotated, Any, Literal

import yaml

from haven_sim.common.bodies import HUMAN_BODY
from haven_sim.common.geometry import (
    MAX_POLYGON_VERTICES,
    Point,
    Pose2D,
    polygon_area,
    polygon_problem,
    segment_to_polygon,
)
from haven_sim.common.schema import FileModel, Line, check, checked, listing
from haven_sim.common.yaml_file import file_label, finite, open_regular, read_yaml, short
from haven_sim.robots.fields import DEFAULT
from haven_sim.sim.map_file import load_map
from haven_sim.sim.map_image import MAX_IMAGE_FILE_BYTES, wall_boxes
from haven_sim.sim.world import (
    MAP_WALL_ID,
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
from haven_sim.sim.world_checks import MAX_COORDINATE_M, MAX_EXTENT_M, overlapping_shape, span_problem

_ID_RE = re.compile(r"[A-Za-z][A-Za-z0-9_]{0,63}")
MAX_NAME_CHARS = 64


def _ccw(polygon: list[Point]) -> tuple[Point, ...]:
    """Counter-clockwise vertex order, so every edge's outward normal is (dy, -dx)."""
    return tuple(polygon if polygon_area(polygon) > 0 else polygon[::-1])


def world_files(world: World, name: str) -> dict[str, bytes]:
    """The world as run, as the files of a folder that holds it on its own (a session): its file
    as `name`, with the starts it was run with (a scenario may give its own), and its map image
    beside it, named in it inline."""
    data = yaml.safe_load(Path(world.source).read_bytes())
    data["robot"] = {**data["robot"], "start": list(world.robot_start)}
    data["humans"] = [{"id": h.id, "start": list(h.start)} for h in world.humans]
    files: dict[str, bytes] = {}
    if world.map is not None:
        image = Path(world.map.source)
        image_name = f"{Path(name).stem}_map{image.suffix.lower()}"
        data["map"] = {"image": image_name, **world.map.settings}
        # (still a regular file, as when it was loaded)
        with open_regular(image, "map image", MAX_IMAGE_FILE_BYTES) as f:
            files[image_name] = f.read()
    header = f"# {world.source} as run (its starts as the scenario gave them; its map image beside it)\n"
    return {name: (header + yaml.safe_dump(data, sort_keys=False)).encode(), **files}


def check_starts(world: World, source: str) -> None:
    """The robot's and the people's starts on the map and clear of solid geometry, as a world file's
    are (for starts a scenario gives); WorldError naming `source`'s key."""
    parser = _Parser(source)
    parser.check_on_map(world)
    parser.check_free(world)


def load_world(path: str | Path) -> World:
    return parse_world(read_yaml(path, "world file", WorldError), source=str(path))


def parse_world(data: Any, source: str = "<world>") -> World:
    if data is None:
        raise WorldError(f"{file_label(source)}: name: the world file is empty")
    if (
        isinstance(data, dict)
        and {"image", "resolution"} <= data.keys()
        and not data.keys() & WorldFile.model_fields.keys()
    ):
        raise WorldError(
            f"{file_label(source)}: this is a map_server map (image, resolution, origin), not a world: "
            f"write a world file with `map: {Path(source).name}`, rooms and starts (docs/howto/own-building.md)"
        )
    return _Parser(source).world(check(WorldFile, data, source, WorldError, "world file"))


def _number(limit: float = math.inf, positive: bool = False) -> Any:
    """A finite number: a length (> 0, at most `limit` m) or a coordinate (within ±`limit` m)."""

    def check(value: Any) -> float:
        f = finite(value)
        if f is None:
            raise ValueError(f"must be a finite number, got {short(value)}")
        if positive and f <= 0:
            raise ValueError(f"must be positive, got {short(value)}")
        if abs(f) > limit:
            raise ValueError(f"must be {f'at most {limit:g} m' if positive else f'within ±{limit:g} m'}, got {f:g}")
        return f

    return Annotated[float, checked(check)]


def _sized(what: str, sizes: tuple[int, ...]) -> Any:
    def check(value: Any) -> Any:
        if not isinstance(value, list) or len(value) not in sizes:
            raise ValueError(f"must be {what}, got {short(value)}")
        return value

    return checked(check)


def _ident(value: Any) -> Any:
    if not isinstance(value, str) or not _ID_RE.fullmatch(value):
        raise ValueError(
            f"must be a name of up to {MAX_NAME_CHARS} letters, "
            f"digits and '_' starting with a letter, got {short(value)}"
        )
    return value


Coordinate = _number(MAX_COORDINATE_M)
Length = _number(MAX_EXTENT_M, positive=True)
PointT = Annotated[list[Coordinate], _sized("a point [x, y]", (2,))]  # type: ignore[valid-type]
# (x, y bounded by `pose`)
PoseT = Annotated[list[_number()], _sized("a pose [x, y, yaw]", (2, 3))]  # type: ignore[valid-type, misc]
Ident = Annotated[str, checked(_ident)]


class ShapeFile(FileModel):
    """A wall, an obstacle: a centre line with a thickness, or a polygon."""

    segment: Annotated[list[PointT], _sized("two points [[x0, y0], [x1, y1]]", (2,))] | None = None
    polygon: Annotated[list[PointT], listing("a list of points [[x, y], ...]", non_empty=False)] | None = None
    thickness: Length | None = None  # type: ignore[valid-type]


class ObstacleFile(ShapeFile):
    """Furniture: a shape with an optional height (absent: solid to the ceiling, like a wall)."""

    height: Length | None = None  # type: ignore[valid-type]


class ObstructionFile(ShapeFile):
    id: Ident
    removed_when_human_reaches: Any = None  # a room of the world


class RoomFile(FileModel):
    name: Ident
    centre: PointT


class HallwayFile(FileModel):
    name: Ident
    centreline: Annotated[list[PointT], listing("a list of points", non_empty=False)]
    width: Length  # type: ignore[valid-type]


class ChargingBaseFile(FileModel):
    position: PointT
    radius: Length = 0.5  # type: ignore[valid-type]


class RobotStartFile(FileModel):
    start: PoseT  # type: ignore[valid-type]


class HumanStartFile(FileModel):
    id: Ident
    start: PoseT  # type: ignore[valid-type]


class GemFile(FileModel):
    id: Ident
    owner: Literal["robot", "human"]
    position: PointT
    radius: Length = 0.3  # type: ignore[valid-type]


def _items(what: str) -> Any:
    return listing(f"a list of {what}", non_empty=False)


class WorldFile(FileModel):
    """A world file's shape (the module docstring shows one)."""

    name: Line(MAX_NAME_CHARS)  # type: ignore[valid-type]
    map: Any = None  # a map_server YAML file or inline map settings (`map_file`)
    walls: Annotated[list[ShapeFile], _items("walls")] | None = None
    obstacles: Annotated[list[ObstacleFile], _items("obstacles")] | None = None
    rooms: Annotated[list[RoomFile], _items("rooms")] | None = None
    hallways: Annotated[list[HallwayFile], _items("hallways")] | None = None
    charging_base: ChargingBaseFile | None = None
    robot: RobotStartFile
    humans: Annotated[list[HumanStartFile], _items("humans")] | None = None
    gems: Annotated[list[GemFile], _items("gems")] | None = None
    obstructions: Annotated[list[ObstructionFile], _items("obstructions")] | None = None


class _Parser:
    """What a world file says beyond its shape (polygons, names, extent, clear starts), always
    knowing the key path for error messages."""

    def __init__(self, source: str) -> None:
        self.source = source

    def fail(self, key: str, message: str) -> WorldError:
        return WorldError(f"{file_label(self.source)}: {key}: {message}")

    def pose(self, value: list[float], key: str) -> Pose2D:
        for i, v in enumerate(value[:2]):
            if abs(v) > MAX_COORDINATE_M:
                raise self.fail(f"{key}[{i}]", f"must be within ±{MAX_COORDINATE_M:g} m, got {v:g}")
        return Pose2D(value[0], value[1], value[2] if len(value) == 3 else 0.0)

    # -- compound --------------------------------------------------------------------------
    def shape(self, m: ShapeFile, key: str, kind: str, id_: str = "") -> Shape:
        if (m.segment is None) == (m.polygon is None):
            raise self.fail(key, "needs exactly one of 'segment' or 'polygon'")
        if m.segment is not None:
            a, b = (tuple(p) for p in m.segment)
            if m.thickness is None:
                raise self.fail(f"{key}.thickness", "is required with 'segment'")
            if math.hypot(b[0] - a[0], b[1] - a[1]) < 1e-9:
                raise self.fail(f"{key}.segment", "has zero length")
            return Shape(_ccw(segment_to_polygon((a[0], a[1]), (b[0], b[1]), m.thickness)), kind, id_)
        if m.thickness is not None:
            raise self.fail(f"{key}.thickness", "only applies to 'segment'")
        raw = m.polygon or []
        if len(raw) < 3:
            raise self.fail(f"{key}.polygon", f"needs at least 3 points, got {len(raw)}")
        if len(raw) > MAX_POLYGON_VERTICES:
            raise self.fail(f"{key}.polygon", f"has {len(raw)} points; at most {MAX_POLYGON_VERTICES}")
        pts: list[Point] = [(p[0], p[1]) for p in raw]
        if abs(polygon_area(pts)) < 1e-9:
            raise self.fail(f"{key}.polygon", "has zero area")
        problem = polygon_problem(pts)
        if problem:
            raise self.fail(f"{key}.polygon", problem)
        return Shape(_ccw(pts), kind, id_)

    def world(self, d: WorldFile) -> World:
        walls = self.shapes(d.walls, "walls", "wall")
        grid = load_map(d.map, self.source) if d.map is not None else None
        if grid is not None:
            walls = tuple(Shape(_ccw(list(box)), "wall", MAP_WALL_ID) for box in wall_boxes(grid)) + walls
        if not walls:
            raise self.fail(
                "walls",
                "needs at least one wall"
                + (" (or a map: to make them from)" if grid is None else " (the map has no occupied cell)"),
            )
        rooms = tuple(Room(r.name, (r.centre[0], r.centre[1])) for r in d.rooms or ())
        self.unique([r.name for r in rooms], "rooms", "name")
        base = d.charging_base
        world = World(
            name=d.name,
            walls=walls,
            obstacles=self.obstacles(d.obstacles or []),
            rooms=rooms,
            hallways=self.hallways(d.hallways or []),
            charging_base=ChargingBase((base.position[0], base.position[1]), base.radius) if base else None,
            robot_start=self.pose(d.robot.start, "robot.start"),
            humans=self.humans(d.humans or []),
            gems=self.gems(d.gems or []),
            obstructions=self.obstructions(d.obstructions or [], {r.name for r in rooms}),
            source=self.source,
            map=grid,
        )
        self.check_extent(world)
        self.check_on_map(world)
        self.check_free(world)
        return world

    def shapes(self, value: Sequence[ShapeFile] | None, key: str, kind: str) -> tuple[Shape, ...]:
        return tuple(self.shape(w, f"{key}[{i}]", kind) for i, w in enumerate(value or ()))

    def obstacles(self, value: list[ObstacleFile]) -> tuple[Shape, ...]:
        shapes = self.shapes(value, "obstacles", "obstacle")
        return tuple(replace(s, height_m=o.height) for s, o in zip(shapes, value, strict=True))

    def hallways(self, value: list[HallwayFile]) -> tuple[Hallway, ...]:
        hallways = []
        for i, h in enumerate(value):
            if len(h.centreline) < 2:
                raise self.fail(f"hallways[{i}].centreline", "needs at least 2 points")
            hallways.append(Hallway(h.name, tuple((p[0], p[1]) for p in h.centreline), h.width))
        self.unique([h.name for h in hallways], "hallways", "name")
        return tuple(hallways)

    def humans(self, value: list[HumanStartFile]) -> tuple[HumanSpec, ...]:
        humans = tuple(HumanSpec(h.id, self.pose(h.start, f"humans[{i}].start")) for i, h in enumerate(value))
        self.unique([h.id for h in humans], "humans", "id")
        return humans

    def gems(self, value: list[GemFile]) -> tuple[Gem, ...]:
        gems = tuple(Gem(g.id, g.owner, (g.position[0], g.position[1]), g.radius) for g in value)
        self.unique([g.id for g in gems], "gems", "id")
        return gems

    def obstructions(self, value: list[ObstructionFile], room_names: set[str]) -> tuple[Obstruction, ...]:
        obstructions = []
        for i, o in enumerate(value):
            k = f"obstructions[{i}]"
            shape = self.shape(o, k, "obstruction", o.id)
            trigger = o.removed_when_human_reaches
            if trigger is not None and (not isinstance(trigger, str) or trigger not in room_names):
                raise self.fail(f"{k}.removed_when_human_reaches", f"names no room in 'rooms', got {short(trigger)}")
            obstructions.append(Obstruction(o.id, shape, trigger))
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
        items += [("robot.start", [world.robot_start[:2]])] + [
            (f"humans[{i}].start", [h.start[:2]]) for i, h in enumerate(world.humans)
        ]
        items += [(f"gems[{i}].position", [g.position]) for i, g in enumerate(world.gems)]
        items += [(f"rooms[{i}].centre", [r.centre]) for i, r in enumerate(world.rooms)]
        items += [(f"hallways[{i}].centreline", list(h.centreline)) for i, h in enumerate(world.hallways)]
        items += [("charging_base.position", [world.charging_base.position])] if world.charging_base else []
        problem = span_problem(items)
        if problem:
            raise self.fail(*problem)

    def check_on_map(self, world: World) -> None:
        """On a world made from a map, the places the overlay names lie on the map."""
        if world.map is None:
            return
        items = [("robot.start", world.robot_start[:2])] + [
            (f"humans[{i}].start", h.start[:2]) for i, h in enumerate(world.humans)
        ]
        items += [(f"rooms[{i}].centre", r.centre) for i, r in enumerate(world.rooms)]
        items += [(f"gems[{i}].position", g.position) for i, g in enumerate(world.gems)]
        items += [("charging_base.position", world.charging_base.position)] if world.charging_base else []
        for key, (x, y) in items:
            if not world.map.contains(x, y):
                x0, y0, x1, y1 = world.map.bounds()
                raise self.fail(key, f"({x:g}, {y:g}) lies outside the map (x {x0:g}..{x1:g}, y {y0:g}..{y1:g})")

    def check_free(self, world: World) -> None:
        """The default robot's and each person's whole body (a disc of its radius) clear of solid
        geometry where they start and where they must stand: rooms' centres (visited), gems (by
        their owner) and the charging base (another robot is checked when a trial chooses it:
        `robot_fits`). A place in a wall would otherwise only show as a trial that times out."""
        shapes = world.solid_shapes()
        robot, person = ("the robot", DEFAULT.radius_m), ("the person", HUMAN_BODY.radius_m)
        checks = [("robot.start", world.robot_start.x, world.robot_start.y, *robot)]
        checks += [(f"humans[{i}].start", h.start.x, h.start.y, *person) for i, h in enumerate(world.humans)]
        checks += [(f"rooms[{i}].centre", *r.centre, *robot) for i, r in enumerate(world.rooms)]
        checks += [
            (f"gems[{i}].position", *g.position, *(robot if g.owner == "robot" else person))
            for i, g in enumerate(world.gems)
        ]
        checks += [("charging_base.position", *world.charging_base.position, *robot)] if world.charging_base else []
        for key, x, y, who, radius in checks:
            hit = overlapping_shape(shapes, x, y, radius)
            if hit is None:
                continue
            shape, centre_inside = hit
            what = "a wall of the map" if shape.id == MAP_WALL_ID else f"{shape.kind} {shape.id}".strip()
            what = what if what.startswith("a wall of") else ("an " if what[0] in "aeiou" else "a ") + what
            if centre_inside:
                raise self.fail(key, f"({x:g}, {y:g}) lies inside {what}")
            raise self.fail(key, f"({x:g}, {y:g}) puts {who}'s body (radius {radius:g} m) into {what}")
