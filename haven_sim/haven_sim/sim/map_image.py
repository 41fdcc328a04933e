"""ROS maps and floor plans as occupancy: the map_server YAML + image that nav2_map_server's
map_saver and slam_toolbox write, or a floor-plan image with a scale, read as map_server reads it.

The reading follows nav2_map_server's `map_io.cpp` (ros-navigation/navigation2, `loadMapFromFile`):
a pixel's shade is the mean of its red, green and blue (and, in trinary mode, of its opacity too)
on 0..1; its occupancy is `1 - shade` (`shade` with `negate`); in trinary mode a cell is occupied
(100) above `occupied_thresh`, free (0) below `free_thresh` and unknown (-1) between; in scale mode
a transparent pixel is unknown and the cells between the thresholds scale linearly to 1..99; in raw
mode a cell is `round(shade * 255)` when that is 0..100, else unknown. Image row 0 is the top of the
map (the largest y); `origin` is the pose of the lower-left pixel. The thresholds' defaults are
map_saver's (0.65 occupied, 0.25 free; `checkSaveParameters`).

HAVEN walks on the free cells only: occupied and unknown cells become walls (`wall_boxes`: the
cells merged into few axis-aligned rectangles, so physics, the scan, the planner and the pages
stay fast), and /map is the source map itself (`MapImage.grid`).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt

from haven_sim.common.geometry import Point
from haven_sim.common.yaml_file import file_label, one_line
from haven_sim.sim.occupancy import OccupancyGridData
from haven_sim.sim.world import WorldError
from haven_sim.sim.world_checks import MAX_EXTENT_M

MODES = ("trinary", "scale", "raw")
OCCUPIED_THRESH, FREE_THRESH = 0.65, 0.25  # map_saver's defaults (map_io.cpp checkSaveParameters)
MAX_CELLS = 4000 * 4000  # 16 M cells: a 100 m world (MAX_EXTENT_M) at 0.025 m/cell
UNKNOWN, FREE, OCCUPIED = -1, 0, 100
IMAGE_SUFFIXES = (".pgm", ".png", ".jpg", ".jpeg", ".bmp")

BoolArray = npt.NDArray[np.bool_]


@dataclass(frozen=True)
class MapImage:
    """An occupancy map: `cells` in map_server's values (100 occupied, 0 free, -1 unknown; 1..99 in
    scale mode), row 0 the image's top row; `resolution` m per cell; `origin` the lower-left
    corner (x, y) in frame `map`; `source` the image file; `settings` map_server's keys as read
    (but `image`), so a copy of the world can name its own copy of the image."""

    cells: npt.NDArray[np.int8]
    resolution: float
    origin: Point
    source: str = ""
    settings: Mapping[str, Any] = field(default_factory=dict)

    @property
    def occupied(self) -> BoolArray:
        """Occupied cells: map_server's 100, and scale mode's >= 50 (as our planner reads /map)."""
        return np.asarray(self.cells >= 50)

    @property
    def unknown(self) -> BoolArray:
        """Cells map_server publishes as unknown (-1)."""
        return np.asarray(self.cells < 0)

    @property
    def blocked(self) -> BoolArray:
        """Cells HAVEN does not walk on: occupied or unknown (what a scan never saw is not floor)."""
        return self.occupied | self.unknown

    def bounds(self) -> tuple[float, float, float, float]:
        """xmin, ymin, xmax, ymax of the map."""
        height, width = self.cells.shape
        return self.origin[0], self.origin[1], self.origin[0] + width * self.resolution, self.origin[1] + height * self.resolution

    def contains(self, x: float, y: float) -> bool:
        x0, y0, x1, y1 = self.bounds()
        return x0 <= x < x1 and y0 <= y < y1

    def grid(self) -> OccupancyGridData:
        """The map as /map publishes it (rows bottom-up, as nav_msgs/OccupancyGrid and map_io's
        `data[width * (height - y - 1) + x]`)."""
        height, width = self.cells.shape
        return OccupancyGridData(self.resolution, width, height, self.origin[0], self.origin[1], np.ascontiguousarray(self.cells[::-1]))


def _fail(source: str, key: str, message: str) -> WorldError:
    return WorldError(f"{file_label(source)}: {key}: {message}" if key else f"{file_label(source)}: {message}")


def read_image(
    path: str | Path,
    resolution: float,
    origin: Point = (0.0, 0.0),
    negate: bool = False,
    occupied_thresh: float = OCCUPIED_THRESH,
    free_thresh: float = FREE_THRESH,
    mode: str = "trinary",
    key: str = "map",
) -> MapImage:
    """An image (PGM, PNG, JPEG, BMP) read as map_server reads it; WorldError in one line naming
    the setting under `key` (`map.resolution`, `map.image`) when it cannot be."""
    check_settings(str(path), key, resolution, occupied_thresh, free_thresh, mode)
    pixels, matte = _pixels(Path(path), _key(key, "image"))
    rgb, alpha = pixels[..., :3].astype(float) / 255.0, pixels[..., 3].astype(float) / 255.0
    height, width = rgb.shape[:2]
    if width * resolution > MAX_EXTENT_M or height * resolution > MAX_EXTENT_M:
        raise _fail(str(path), _key(key, "resolution"), f"{width} x {height} cells of {resolution:g} m exceed the {MAX_EXTENT_M:g} m a world spans")
    opaque = alpha >= 1.0
    channels = [rgb[..., 0], rgb[..., 1], rgb[..., 2]]
    if mode == "trinary" and matte:
        channels.append(alpha)  # map_io averages opacity in, in trinary mode, for images with an alpha channel
    shade: npt.NDArray[np.float64] = np.mean(channels, axis=0)
    occ = shade if negate else 1.0 - shade
    cells = np.full(shade.shape, UNKNOWN, dtype=np.int8)
    if mode == "raw":
        value = np.round(shade * 255.0)
        ok = (value >= FREE) & (value <= OCCUPIED)
        cells[ok] = value[ok].astype(np.int8)
    else:
        cells[occ > occupied_thresh] = OCCUPIED
        cells[occ < free_thresh] = FREE
        if mode == "scale":
            between = (occ >= free_thresh) & (occ <= occupied_thresh)
            cells[between] = np.rint((occ[between] - free_thresh) / (occupied_thresh - free_thresh) * 100.0).astype(np.int8)
            cells[~opaque] = UNKNOWN
    settings = {"resolution": resolution, "origin": [origin[0], origin[1], 0.0], "negate": int(negate)}
    settings |= {"occupied_thresh": occupied_thresh, "free_thresh": free_thresh, "mode": mode}
    return MapImage(cells, float(resolution), (float(origin[0]), float(origin[1])), str(path), settings)


def _key(prefix: str, name: str) -> str:
    return f"{prefix}.{name}" if prefix else name


def check_settings(source: str, key: str, resolution: float, occupied_thresh: float, free_thresh: float, mode: str) -> None:
    """map_saver's rules for the thresholds (0 <= free < occupied <= 1), a positive resolution, a known mode."""
    if not (isinstance(resolution, (int, float)) and math.isfinite(resolution) and resolution > 0):
        raise _fail(source, _key(key, "resolution"), f"must be a positive number of metres per cell, got {resolution!r}")
    if mode not in MODES:
        raise _fail(source, _key(key, "mode"), f"must be one of {', '.join(MODES)}, got {mode!r}")
    if not 0.0 <= free_thresh < occupied_thresh <= 1.0:
        raise _fail(source, _key(key, "free_thresh"), f"needs 0 <= free_thresh < occupied_thresh <= 1, got {free_thresh:g} and {occupied_thresh:g}")


def _pixels(path: Path, key: str) -> tuple[npt.NDArray[np.uint8], bool]:
    """The image as (rows, cols, RGBA) bytes, and whether it has an alpha channel."""
    from PIL import Image, UnidentifiedImageError

    if path.suffix.lower() not in IMAGE_SUFFIXES:
        raise _fail(str(path), key, f"is not a map image ({', '.join(IMAGE_SUFFIXES)})")
    try:
        with Image.open(path) as img:
            if img.width * img.height > MAX_CELLS:
                raise _fail(str(path), key, f"has {img.width} x {img.height} pixels; at most {MAX_CELLS:,} cells")
            matte = img.mode in ("RGBA", "LA", "PA", "RGBa", "La") or "transparency" in img.info
            arr = np.asarray(img.convert("RGBA"))  # (8-bit images, as map_saver writes them)
    except WorldError:
        raise
    except (OSError, UnidentifiedImageError, ValueError, Image.DecompressionBombError) as e:
        raise _fail(str(path), key, f"cannot be read as an image: {one_line(str(e))}") from None
    return arr, matte


def wall_boxes(image: MapImage) -> list[tuple[Point, ...]]:
    """The blocked cells (occupied and unknown: HAVEN walks on free cells only) as few axis-aligned
    rectangles (counter-clockwise polygons in frame `map`) that cover exactly those cells, none
    overlapping: greedy maximal rectangles, top row first, each a row's run of cells not yet
    covered, grown downwards while the rows below are blocked and uncovered across its width.
    A wall is one box, and a cell a scan left stuck to its face one more (not a split wall)."""
    blocked = image.blocked
    height, _ = blocked.shape
    covered = np.zeros_like(blocked)
    res, (ox, oy) = image.resolution, image.origin
    boxes: list[tuple[int, int, int, int]] = []  # top row, end row (exclusive), first col, end col
    for r in range(height):
        for c0, c1 in _runs(blocked[r] & ~covered[r]):
            r1 = r + 1
            while r1 < height and blocked[r1, c0:c1].all() and not covered[r1, c0:c1].any():
                r1 += 1
            covered[r:r1, c0:c1] = True
            boxes.append((r, r1, c0, c1))

    def corner(row_edge: int, col: int) -> Point:
        return (ox + col * res, oy + (height - row_edge) * res)

    return [(corner(r1, c0), corner(r1, c1), corner(r0, c1), corner(r0, c0)) for r0, r1, c0, c1 in boxes]


def _runs(row: BoolArray) -> list[tuple[int, int]]:
    """[start, end) column spans of the True runs in one row."""
    padded = np.concatenate(([False], row, [False])).astype(np.int8)
    edges = np.flatnonzero(np.diff(padded))
    return [(int(a), int(b)) for a, b in zip(edges[::2], edges[1::2], strict=True)]


def image_path(value: Any, base: Path, source: str, key: str) -> Path:
    """An image file named in a map YAML or a world file, relative to that file's folder."""
    if not isinstance(value, str) or not value.strip():
        raise _fail(source, key, f"must name an image file, got {value!r:.60}")
    p = Path(value)
    return p if p.is_absolute() else base / p
