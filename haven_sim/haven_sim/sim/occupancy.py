"""Occupancy grid rasterised from the world's solid shapes (the /map the planner and viewers use)."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np
import numpy.typing as npt

from haven_sim.common.geometry import points_in_polygon
from haven_sim.sim.world import MAP_WALL_ID, Shape, World

OCCUPIED = 100


@dataclass(frozen=True)
class OccupancyGridData:
    """Row-major cells (row = y index) as in nav_msgs/OccupancyGrid; origin is the lower-left corner."""

    resolution_m: float
    width: int
    height: int
    origin_x: float
    origin_y: float
    data: npt.NDArray[np.int8]  # shape (height, width)

    def cell_of(self, x: float, y: float) -> tuple[int, int]:
        """(row, col) of a point, possibly outside the grid."""
        return (
            math.floor((y - self.origin_y) / self.resolution_m),
            math.floor((x - self.origin_x) / self.resolution_m),
        )

    def is_occupied(self, x: float, y: float) -> bool:
        r, c = self.cell_of(x, y)
        if not (0 <= r < self.height and 0 <= c < self.width):
            return True
        return bool(self.data[r, c] >= 50)


def rasterise(
    world: World,
    resolution_m: float = 0.05,
    padding_m: float = 0.5,
    removed: frozenset[str] = frozenset(),
    below: float | None = None,
) -> OccupancyGridData:
    """The world's solid shapes as a grid; with `below`, without the obstacles lower than that
    (the map an aerial robot plans on: it flies over them). The grid's extent is the whole world's.
    A world made from a ROS map or floor plan has that map as its grid (its own resolution, as
    map_server publishes it), with what the world adds to it marked (walls, obstacles, obstructions)."""
    if resolution_m <= 0:
        raise ValueError(f"map resolution must be positive, got {resolution_m}")
    if world.map is not None:
        source = world.map.grid()
        out = replace(source, data=source.data.copy())
        for shape in world.solid_shapes(removed, below):
            if shape.id != MAP_WALL_ID:
                _mark(out, shape)
        return out
    xmin, ymin, xmax, ymax = world.bounds()
    ox = math.floor((xmin - padding_m) / resolution_m) * resolution_m
    oy = math.floor((ymin - padding_m) / resolution_m) * resolution_m
    width = math.ceil((xmax + padding_m - ox) / resolution_m)
    height = math.ceil((ymax + padding_m - oy) / resolution_m)
    grid = np.zeros((height, width), dtype=np.int8)
    out = OccupancyGridData(resolution_m, width, height, ox, oy, grid)
    for shape in world.solid_shapes(removed, below):
        _mark(out, shape)
    return out


def on_the_floor(grid: OccupancyGridData, world: World, below: float | None) -> OccupancyGridData:
    """`grid`, an aerial robot's map (without the obstacles lower than `below`), with those obstacles
    marked again: the map of the people, who walk round the furniture the robot flies over."""
    low = [s for s in world.obstacles if s.below(below)]
    if not low:
        return grid
    out = OccupancyGridData(grid.resolution_m, grid.width, grid.height, grid.origin_x, grid.origin_y, grid.data.copy())
    for shape in low:
        _mark(out, shape)
    return out


def _mark(g: OccupancyGridData, shape: Shape) -> None:
    """The cells of `shape` occupied, in place."""
    resolution_m, width, height, ox, oy, grid = g.resolution_m, g.width, g.height, g.origin_x, g.origin_y, g.data
    poly = list(shape.polygon)
    pts = np.asarray(poly)
    c0 = max(0, int((pts[:, 0].min() - ox) / resolution_m) - 1)
    c1 = min(width, int((pts[:, 0].max() - ox) / resolution_m) + 2)
    r0 = max(0, int((pts[:, 1].min() - oy) / resolution_m) - 1)
    r1 = min(height, int((pts[:, 1].max() - oy) / resolution_m) + 2)
    cols = np.arange(c0, c1)
    rows = np.arange(r0, r1)
    xs, ys = np.meshgrid(ox + (cols + 0.5) * resolution_m, oy + (rows + 0.5) * resolution_m)
    inside = points_in_polygon(xs, ys, poly)
    grid[r0:r1, c0:c1][inside] = OCCUPIED
    # Shapes thinner than a cell may contain no cell centre: also mark the cells their edges cross.
    for x0, y0, x1, y1 in shape.edges():
        n = max(2, int(math.hypot(x1 - x0, y1 - y0) / (resolution_m / 2.0)) + 1)
        sx = np.linspace(x0, x1, n)
        sy = np.linspace(y0, y1, n)
        cc = np.floor((sx - ox) / resolution_m).astype(int)
        rr = np.floor((sy - oy) / resolution_m).astype(int)
        ok = (cc >= 0) & (cc < width) & (rr >= 0) & (rr < height)
        grid[rr[ok], cc[ok]] = OCCUPIED
