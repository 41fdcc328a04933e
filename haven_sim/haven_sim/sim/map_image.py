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

Bounded, as a map may come from anyone: the image is opened only when it is a regular file of at
most `MAX_IMAGE_FILE_BYTES` (`yaml_file.open_regular`: a FIFO is refused, never opened blocking),
decoded only by the PNG, JPEG, PGM and BMP decoders and only once its header says it has at most
`MAX_CELLS` pixels; the merge is linear in the cells and stops at `MAX_WALL_BOXES` boxes.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable, Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass, field
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, Any, BinaryIO

import numpy as np
import numpy.typing as npt

from haven_sim.common.geometry import Point
from haven_sim.common.yaml_file import NotReadable, file_label, one_line, open_regular
from haven_sim.sim.occupancy import OccupancyGridData
from haven_sim.sim.world import WorldError
from haven_sim.sim.world_checks import MAX_EXTENT_M

if TYPE_CHECKING:
    from PIL import Image

MODES = ("trinary", "scale", "raw")
OCCUPIED_THRESH, FREE_THRESH = 0.65, 0.25  # map_saver's defaults (map_io.cpp checkSaveParameters)
MAX_CELLS = 4000 * 4000  # 16 M cells: a 100 m world (MAX_EXTENT_M) at 0.025 m/cell
UNKNOWN, FREE, OCCUPIED = -1, 0, 100
IMAGE_SUFFIXES = (".pgm", ".png", ".jpg", ".jpeg", ".bmp")
# PIL's decoders for them (PPM reads PGM): no other decoder sees the bytes
IMAGE_FORMATS = ("PNG", "JPEG", "PPM", "BMP")
MAX_IMAGE_FILE_BYTES = 100 << 20  # a 4000 x 4000 RGBA BMP, the largest map image, is 64 MB
MAX_WALL_BOXES = 10_000  # see `wall_boxes`
BAND_ROWS = 256  # rows converted at a time (about 30 MB of working arrays at 4,000 columns)

BoolArray = npt.NDArray[np.bool_]
IntArray = npt.NDArray[np.int64]


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
        return (
            self.origin[0],
            self.origin[1],
            self.origin[0] + width * self.resolution,
            self.origin[1] + height * self.resolution,
        )

    def contains(self, x: float, y: float) -> bool:
        x0, y0, x1, y1 = self.bounds()
        return x0 <= x < x1 and y0 <= y < y1

    def grid(self) -> OccupancyGridData:
        """The map as /map publishes it (rows bottom-up, as nav_msgs/OccupancyGrid and map_io's
        `data[width * (height - y - 1) + x]`)."""
        height, width = self.cells.shape
        return OccupancyGridData(
            self.resolution, width, height, self.origin[0], self.origin[1], np.ascontiguousarray(self.cells[::-1])
        )


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
    the setting under `key` (`map.resolution`, `map.image`) when it cannot be. Only a regular file
    is opened, its size is checked from its header before it is decoded, and it is converted
    `BAND_ROWS` rows at a time (a 4,000 x 4,000 RGBA image: about 180 MB at its peak, 5 s)."""
    check_settings(str(path), key, resolution, occupied_thresh, free_thresh, mode)
    source, image_key = str(path), _key(key, "image")
    if Path(path).suffix.lower() not in IMAGE_SUFFIXES:
        raise _fail(source, image_key, f"is not a map image ({', '.join(IMAGE_SUFFIXES)})")
    try:
        data = open_regular(path, "map image", MAX_IMAGE_FILE_BYTES)
    except NotReadable as e:
        raise _fail(source, image_key, f"cannot be read as an image: {e.reason}") from None
    with data, open_image(data, source, image_key) as img:
        width, height = img.size
        if width * resolution > MAX_EXTENT_M or height * resolution > MAX_EXTENT_M:
            raise _fail(
                source,
                _key(key, "resolution"),
                f"{width} x {height} cells of {resolution:g} m exceed the {MAX_EXTENT_M:g} m a world spans",
            )
        try:
            cells = _image_cells(
                img, partial(_cells, negate=negate, occupied_thresh=occupied_thresh, free_thresh=free_thresh, mode=mode)
            )
        except (OSError, ValueError) as e:
            raise _fail(source, image_key, f"cannot be read as an image: {one_line(str(e))}") from None
    settings = {"resolution": resolution, "origin": [origin[0], origin[1], 0.0], "negate": int(negate)}
    settings |= {"occupied_thresh": occupied_thresh, "free_thresh": free_thresh, "mode": mode}
    return MapImage(cells, float(resolution), (float(origin[0]), float(origin[1])), source, settings)


def _image_cells(
    img: Image.Image, cells_of: Callable[[npt.NDArray[np.uint8], bool], npt.NDArray[np.int8]]
) -> npt.NDArray[np.int8]:
    """The decoded image's cells: an 8-bit grey image (a PGM, as map_saver writes) through a table
    of its 256 shades, anything else as RGBA `BAND_ROWS` rows at a time (the same arithmetic)."""
    width, height = img.size
    matte = img.mode in ("RGBA", "LA", "PA", "RGBa", "La") or "transparency" in img.info
    img.load()
    if img.mode == "L" and not matte:
        shades = np.repeat(np.arange(256, dtype=np.uint8), 4).reshape(1, 256, 4)
        shades[..., 3] = 255
        table = cells_of(shades, False)[0]
        grey: npt.NDArray[np.int8] = table[np.asarray(img)]
        return grey
    cells = np.empty((height, width), dtype=np.int8)
    for r0 in range(0, height, BAND_ROWS):
        # (8-bit, as map_saver writes)
        band = np.asarray(img.crop((0, r0, width, min(height, r0 + BAND_ROWS))).convert("RGBA"))
        cells[r0 : r0 + BAND_ROWS] = cells_of(band, matte)
    return cells


def _cells(
    pixels: npt.NDArray[np.uint8], matte: bool, *, negate: bool, occupied_thresh: float, free_thresh: float, mode: str
) -> npt.NDArray[np.int8]:
    """map_io's values for (rows, cols, RGBA) pixels (the module docstring)."""
    rgb, alpha = pixels[..., :3].astype(float) / 255.0, pixels[..., 3].astype(float) / 255.0
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
            cells[between] = np.rint((occ[between] - free_thresh) / (occupied_thresh - free_thresh) * 100.0).astype(
                np.int8
            )
            cells[alpha < 1.0] = UNKNOWN
    return cells


def _key(prefix: str, name: str) -> str:
    return f"{prefix}.{name}" if prefix else name


def check_settings(
    source: str, key: str, resolution: float, occupied_thresh: float, free_thresh: float, mode: str
) -> None:
    """map_saver's rules for the thresholds (0 <= free < occupied <= 1), a positive resolution, a known mode."""
    if not (isinstance(resolution, (int, float)) and math.isfinite(resolution) and resolution > 0):
        raise _fail(
            source, _key(key, "resolution"), f"must be a positive number of metres per cell, got {resolution!r}"
        )
    if mode not in MODES:
        raise _fail(source, _key(key, "mode"), f"must be one of {', '.join(MODES)}, got {mode!r}")
    if not 0.0 <= free_thresh < occupied_thresh <= 1.0:
        raise _fail(
            source,
            _key(key, "free_thresh"),
            f"needs 0 <= free_thresh < occupied_thresh <= 1, got {free_thresh:g} and {occupied_thresh:g}",
        )


@contextmanager
def open_image(data: BinaryIO, source: str, key: str) -> Iterator[Image.Image]:
    """An image opened from its header only (nothing decoded yet), held to `MAX_CELLS` pixels:
    WorldError in one line (`source: key: problem`, no key when it is "") for anything else, a
    decompression bomb included (PIL refuses one of more than twice `Image.MAX_IMAGE_PIXELS`
    before we see its size, and warns above that: we judge the size ourselves)."""
    from PIL import Image, UnidentifiedImageError

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", Image.DecompressionBombWarning)  # (the size is ours to judge, just below)
            img = Image.open(data, formats=IMAGE_FORMATS)
    except Image.DecompressionBombError:
        bomb = (
            f"has more than {2 * (Image.MAX_IMAGE_PIXELS or 0):,} "
            f"pixels (a decompression bomb?); at most {MAX_CELLS:,} cells"
        )
        raise _fail(source, key, bomb) from None
    except (OSError, UnidentifiedImageError, ValueError) as e:
        raise _fail(source, key, f"cannot be read as an image: {one_line(str(e))}") from None
    with img:
        if img.width * img.height > MAX_CELLS:
            raise _fail(source, key, f"has {img.width} x {img.height} pixels; at most {MAX_CELLS:,} cells")
        yield img


def wall_boxes(image: MapImage, limit: int = MAX_WALL_BOXES) -> list[tuple[Point, ...]]:
    """The blocked cells (occupied and unknown: HAVEN walks on free cells only) as few axis-aligned
    rectangles (counter-clockwise polygons in frame `map`) that cover exactly those cells, none
    overlapping (`wall_rectangles`); WorldError in one line when they would be more than `limit`.

    The limit, `MAX_WALL_BOXES` (10,000), is what the simulator holds at the speed a trial needs:
    each box is four pymunk segments, four edges the scan casts against, a prism of the 3D scene
    and a patch of the pictures. At 10,000 boxes (bench/map_walls.py) loading the world, building
    its physics and scan, and drawing it each take about 2-3 s; a building's SLAM map makes far
    fewer (the 20 m W1 map with ragged walls: 254), while a dithered or noise-filled image makes
    millions (a 4,000 x 4,000 checkerboard: 8 million), refused after its first rows."""
    height = image.cells.shape[0]
    res, (ox, oy) = image.resolution, image.origin
    try:
        boxes = wall_rectangles(image.blocked, limit)
    except TooManyBoxes as e:
        raise _fail(
            image.source,
            "",
            f"its occupied and unknown cells make more than {limit:,} wall boxes (by row {e.rows} of {height}): "
            "too fragmented to simulate (a dithered or noisy image? clean it, or save it at a coarser resolution)",
        ) from None

    def corner(row_edge: int, col: int) -> Point:
        return (ox + col * res, oy + (height - row_edge) * res)

    return [(corner(r1, c0), corner(r1, c1), corner(r0, c1), corner(r0, c0)) for r0, r1, c0, c1 in boxes.tolist()]


class TooManyBoxes(Exception):
    """More rectangles than the limit; `rows` rows were merged when it was reached."""

    def __init__(self, rows: int) -> None:
        super().__init__(rows)
        self.rows = rows


def wall_rectangles(blocked: BoolArray, limit: int = MAX_WALL_BOXES) -> IntArray:
    """Greedy maximal rectangles, top row first: each row's run of blocked cells not yet covered
    is grown downwards while the rows below are blocked across its width (a wall is one box, and
    a cell a scan left stuck to its face one more, not a split wall). Rows of (top row, end row,
    first col, end col), ordered by top row then column; `TooManyBoxes` past `limit`.

    Linear in the cells: a box growing down is never stopped by another (one started above that
    reached its rows would cover its top row too), so each row needs only the boxes still open
    (whether the row is blocked across each: one prefix sum) and the runs they leave uncovered,
    a few numpy passes over the row."""
    height, width = blocked.shape
    growing = np.zeros((0, 3), dtype=np.int64)  # top row, first col, end col of the boxes still growing
    done: list[IntArray] = []
    made = 0
    repeats = np.concatenate(([False], (blocked[1:] == blocked[:-1]).all(axis=1), [False]))
    for r in range(height + 1):
        if repeats[r]:
            continue  # the boxes open cover the row above, the same as this one: they all grow, none starts
        row = blocked[r] if r < height else np.zeros(width, dtype=bool)
        gaps = np.concatenate(([0], np.cumsum(~row, dtype=np.int64)))  # free cells before each column
        grows = gaps[growing[:, 2]] == gaps[growing[:, 1]]
        ended = growing[~grows]
        done.append(np.column_stack((ended[:, 0], np.full(len(ended), r), ended[:, 1], ended[:, 2])))
        growing = growing[grows]
        if r == height:
            break
        edges = np.zeros(width + 1, dtype=np.int64)
        edges[growing[:, 1]] += 1
        edges[growing[:, 2]] -= 1
        starts, ends = _run_edges(row & ~(np.cumsum(edges[:-1]) > 0))
        made += len(starts)
        if made > limit:
            raise TooManyBoxes(r + 1)
        growing = np.vstack((growing, np.column_stack((np.full(len(starts), r), starts, ends))))
    boxes = np.vstack(done)
    ordered: IntArray = boxes[np.lexsort((boxes[:, 2], boxes[:, 0]))]
    return ordered


def _run_edges(row: BoolArray) -> tuple[IntArray, IntArray]:
    """[start, end) column spans of the True runs in one row."""
    padded = np.concatenate(([False], row, [False])).astype(np.int8)
    edges = np.flatnonzero(np.diff(padded)).astype(np.int64)
    return edges[::2], edges[1::2]


def image_path(value: Any, base: Path, source: str, key: str) -> Path:
    """An image file named in a map YAML or a world file, relative to that file's folder."""
    if not isinstance(value, str) or not value.strip():
        raise _fail(source, key, f"must name an image file, got {value!r:.60}")
    p = Path(value)
    return p if p.is_absolute() else base / p
