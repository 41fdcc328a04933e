"""The world as markers: walls, obstacles, obstructions, rooms and their names, gems coloured by
owner (blue robot, red human), the charging base; and the moving bodies (robot, humans)."""

from __future__ import annotations

import math
from collections.abc import Collection, Mapping, Sequence

from haven_sim.common.bodies import HUMAN_BODY
from haven_sim.common.geometry import Point, Pose2D, polygon_area
from haven_sim.robots.description import RobotDescription
from haven_sim.robots.fields import DEFAULT
from haven_sim.sim.world import World
from haven_viz.markers import Color, MarkerSpec, Point3, Shape

WALL_HEIGHT_M = 0.5
COLORS: dict[str, Color] = {
    "wall": (0.55, 0.57, 0.62, 1.0),
    "obstacle": (0.45, 0.35, 0.25, 1.0),
    "obstruction": (0.9, 0.4, 0.1, 0.9),
    "robot_gem": (0.1, 0.35, 1.0, 1.0),
    "human_gem": (0.9, 0.1, 0.1, 1.0),
    "base": (0.55, 0.3, 0.85, 0.6),  # purple: not the red of the human gems' areas
    "room_text": (0.2, 0.2, 0.2, 1.0),
    "robot": (0.2, 0.2, 0.22, 1.0),
    "human": (0.85, 0.2, 0.2, 0.8),
}


def triangulate(polygon: Sequence[Point]) -> list[tuple[Point, Point, Point]]:
    """Ear clipping of a simple polygon (any winding) into triangles."""
    pts = list(polygon) if polygon_area(list(polygon)) > 0 else list(polygon)[::-1]
    idx = list(range(len(pts)))
    tris: list[tuple[Point, Point, Point]] = []

    def cross(o: Point, a: Point, b: Point) -> float:
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    guard = 0
    while len(idx) > 3 and guard < 10 * len(pts):
        guard += 1
        for k in range(len(idx)):
            i0, i1, i2 = idx[k - 1], idx[k], idx[(k + 1) % len(idx)]
            a, b, c = pts[i0], pts[i1], pts[i2]
            if cross(a, b, c) <= 1e-12:
                continue  # reflex or degenerate corner: not an ear
            if any(
                cross(a, b, pts[j]) >= 0 and cross(b, c, pts[j]) >= 0 and cross(c, a, pts[j]) >= 0
                for j in idx
                if j not in (i0, i1, i2)
            ):
                continue
            tris.append((a, b, c))
            idx.pop(k)
            break
    if len(idx) == 3:
        tris.append((pts[idx[0]], pts[idx[1]], pts[idx[2]]))
    return tris


def _prism(polygon: Sequence[Point], height: float) -> tuple[Point3, ...]:
    """Triangles (TRIANGLE_LIST points) of a vertical prism over the polygon: top and sides."""
    out: list[Point3] = []
    for a, b, c in triangulate(polygon):
        out += [(a[0], a[1], height), (b[0], b[1], height), (c[0], c[1], height)]
    n = len(polygon)
    for i in range(n):
        (x0, y0), (x1, y1) = polygon[i], polygon[(i + 1) % n]
        out += [(x0, y0, 0.0), (x1, y1, 0.0), (x1, y1, height), (x0, y0, 0.0), (x1, y1, height), (x0, y0, height)]
    return tuple(out)


def world_markers(world: World, collected: Collection[str] = (), removed: Collection[str] = ()) -> list[MarkerSpec]:
    """Static scene: re-sent only when a gem is collected or an obstruction removed."""
    out: list[MarkerSpec] = []
    for kind, shapes in (("wall", world.walls), ("obstacle", world.obstacles)):
        # (one pass: a map world has thousands)
        tris = tuple(p for s in shapes for p in _prism(s.polygon, WALL_HEIGHT_M))
        if tris:
            out.append(MarkerSpec(f"{kind}s", 0, Shape.TRIANGLE_LIST, color=COLORS[kind], points=tris))
    for i, o in enumerate(world.obstructions):
        if o.id not in removed:
            out.append(
                MarkerSpec(
                    "obstructions",
                    i,
                    Shape.TRIANGLE_LIST,
                    color=COLORS["obstruction"],
                    points=_prism(o.shape.polygon, WALL_HEIGHT_M),
                )
            )
    for i, r in enumerate(world.rooms):
        x, y = r.centre
        out.append(
            MarkerSpec(
                "rooms", i, Shape.TEXT_VIEW_FACING, (x, y, 0.05), 0.0, (0.0, 0.0, 0.3), COLORS["room_text"], r.name
            )
        )
    for i, g in enumerate(world.gems):
        if g.id in collected:
            continue
        color = COLORS["robot_gem" if g.owner == "robot" else "human_gem"]
        x, y = g.position
        out.append(MarkerSpec("gems", i, Shape.CUBE, (x, y, 0.25), math.pi / 4, (0.18, 0.18, 0.18), color))
        area = (color[0], color[1], color[2], 0.25)
        out.append(
            MarkerSpec("gem_areas", i, Shape.CYLINDER, (x, y, 0.005), 0.0, (2 * g.radius, 2 * g.radius, 0.01), area)
        )
    if world.charging_base is not None:
        (bx, by), br = world.charging_base.position, world.charging_base.radius
        out.append(
            MarkerSpec("charging_base", 0, Shape.CYLINDER, (bx, by, 0.02), 0.0, (2 * br, 2 * br, 0.04), COLORS["base"])
        )
    return out


def body_markers(
    robot: Pose2D, humans: Mapping[str, Pose2D], description: RobotDescription = DEFAULT, z: float = 0.0
) -> list[MarkerSpec]:
    """The robot (a cylinder of its footprint's size, with a heading arrow; `z` above the floor)
    and each human (a tall cylinder)."""
    r, rh = description.radius_m, description.height_m
    out = [
        MarkerSpec(
            "robot", 0, Shape.CYLINDER, (robot.x, robot.y, z + rh / 2), robot.yaw, (2 * r, 2 * r, rh), COLORS["robot"]
        ),
        MarkerSpec(
            "robot",
            1,
            Shape.ARROW,
            (robot.x, robot.y, z + rh + 0.02),
            robot.yaw,
            (0.25, 0.05, 0.05),
            (1.0, 1.0, 1.0, 1.0),
        ),
    ]
    h, hh = HUMAN_BODY.radius_m, HUMAN_BODY.height_m
    for i, (hid, p) in enumerate(humans.items()):
        out.append(
            MarkerSpec("humans", i, Shape.CYLINDER, (p.x, p.y, hh / 2), p.yaw, (2 * h, 2 * h, hh), COLORS["human"])
        )
        out.append(
            MarkerSpec(
                "human_names",
                i,
                Shape.TEXT_VIEW_FACING,
                (p.x, p.y, hh + 0.2),
                0.0,
                (0.0, 0.0, 0.2),
                (0.1, 0.1, 0.1, 1.0),
                hid,
            )
        )
    return out
