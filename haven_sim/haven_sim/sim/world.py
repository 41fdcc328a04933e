"""The world model: solid shapes, rooms, hallways, the charging base, start poses, gems and
obstructions, in frame `map` (REP-103, metres and radians). The YAML file format and its validating
loader are in `world_file`."""

from __future__ import annotations

from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from haven_sim.common.geometry import FloatArray, Point, Pose2D, polygon_edges, polygons_edges

if TYPE_CHECKING:
    from haven_sim.sim.map_image import MapImage

MAP_WALL_ID = "map"  # the id of the walls made from a world's map (`map_image.wall_boxes`)


class WorldError(ValueError):
    """A world file is missing, unreadable or invalid; the message is one line for the user."""


@dataclass(frozen=True)
class Shape:
    """Solid geometry as a closed counter-clockwise polygon (segments are stored as their rectangle)."""

    polygon: tuple[Point, ...]
    kind: str = "wall"  # wall | obstacle | obstruction
    id: str = ""
    height_m: float | None = None  # an obstacle's top above the floor; None: solid to the ceiling

    def below(self, height_m: float | None) -> bool:
        """Whether its top is lower than `height_m` (something flying at that height passes over it)."""
        return height_m is not None and self.height_m is not None and self.height_m < height_m

    def edges(self) -> FloatArray:
        return polygon_edges(list(self.polygon))


@dataclass(frozen=True)
class Room:
    name: str
    centre: Point


@dataclass(frozen=True)
class Hallway:
    name: str
    centreline: tuple[Point, ...]
    width: float


@dataclass(frozen=True)
class ChargingBase:
    position: Point
    radius: float


@dataclass(frozen=True)
class HumanSpec:
    id: str
    start: Pose2D


@dataclass(frozen=True)
class Gem:
    id: str
    owner: str
    position: Point
    radius: float


@dataclass(frozen=True)
class Obstruction:
    id: str
    shape: Shape
    removed_when_human_reaches: str | None


@dataclass(frozen=True)
class World:
    name: str
    walls: tuple[Shape, ...]
    robot_start: Pose2D
    obstacles: tuple[Shape, ...] = ()
    rooms: tuple[Room, ...] = ()
    hallways: tuple[Hallway, ...] = ()
    charging_base: ChargingBase | None = None
    humans: tuple[HumanSpec, ...] = ()
    gems: tuple[Gem, ...] = ()
    obstructions: tuple[Obstruction, ...] = ()
    source: str = field(default="", compare=False)
    # the ROS map or floor plan its walls come from
    map: MapImage | None = field(default=None, compare=False, repr=False)

    def solid_shapes(self, removed: frozenset[str] = frozenset(), below: float | None = None) -> list[Shape]:
        """Walls, obstacles and the obstructions not in `removed`; with `below` (a flying robot's
        lowest clear height), without the obstacles lower than that (walls and obstructions have
        no height: always solid)."""
        live = [o.shape for o in self.obstructions if o.id not in removed]
        return [*self.walls, *self.obstacles_at(below), *live]

    def obstacles_at(self, below: float | None = None) -> list[Shape]:
        """The obstacles, less those lower than `below` (None: all)."""
        return [s for s in self.obstacles if not s.below(below)]

    def edges(
        self, removed: frozenset[str] = frozenset(), obstructions: bool = True, below: float | None = None
    ) -> FloatArray:
        """Edges (N, 4) of every solid shape; without obstructions when `obstructions` is False,
        without obstacles lower than `below` (see `solid_shapes`)."""
        shapes = self.solid_shapes(removed, below) if obstructions else [*self.walls, *self.obstacles_at(below)]
        return polygons_edges([s.polygon for s in shapes])

    def bounds(self) -> tuple[float, float, float, float]:
        """xmin, ymin, xmax, ymax over every shape and named point."""
        pts: list[Point] = [p for s in self.solid_shapes() for p in s.polygon]
        pts += [(self.robot_start.x, self.robot_start.y)]
        pts += [(h.start.x, h.start.y) for h in self.humans]
        pts += [g.position for g in self.gems] + [r.centre for r in self.rooms]
        arr = np.asarray(pts, dtype=float)
        return (
            float(arr[:, 0].min()),
            float(arr[:, 1].min()),
            float(arr[:, 0].max()),
            float(arr[:, 1].max()),
        )

    def room(self, name: str) -> Room:
        for r in self.rooms:
            if r.name == name:
                return r
        raise KeyError(name)


def packaged_world(name: str) -> Path:
    """Path of a world shipped inside haven_sim (e.g. 'small_test')."""
    return Path(str(resources.files("haven_sim") / "worlds" / f"{name}.yaml"))


def resolve_world_path(spec: str) -> Path:
    """A file path, or the name of a packaged world."""
    p = Path(spec)
    if p.suffix in (".yaml", ".yml") or p.exists():
        return p
    return packaged_world(spec)


def summary(world: World) -> str:
    """What a world holds, in words (`haven world show` and the world editor say it)."""
    counts = {
        "wall(s)": len(world.walls),
        "obstacle(s)": len(world.obstacles),
        "room(s)": len(world.rooms),
        "hallway(s)": len(world.hallways),
        "gem(s)": len(world.gems),
        "person start(s)": len(world.humans),
    }
    return ", ".join(f"{n} {what}" for what, n in counts.items())
