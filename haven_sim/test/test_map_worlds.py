"""Worlds from ROS maps and floor plans (map_image, map_file): map_server's reading of the image,
the walls that cover exactly the cells HAVEN does not walk on, /map equal to the source map, and
one-line refusals."""

import numpy as np
import pytest
from map_maker import ORIGIN, RESOLUTION, make_map_world, map_pixels
from PIL import Image

from haven_sim.common.geometry import points_in_polygon
from haven_sim.sim.map_image import FREE, OCCUPIED, UNKNOWN, MapImage, read_image, wall_boxes
from haven_sim.sim.occupancy import rasterise
from haven_sim.sim.world import MAP_WALL_ID, WorldError
from haven_sim.sim.world_file import load_world


def _image(tmp_path, pixels, name="m.png"):
    Image.fromarray(np.asarray(pixels, np.uint8)).save(tmp_path / name)
    return tmp_path / name


def test_trinary_reading_follows_map_server_thresholds_and_negate(tmp_path):
    # darkness p = 1 - value/255: 0 -> 1.0, 89 -> 0.651, 90 -> 0.647, 191 -> 0.251, 192 -> 0.247, 254 -> 0.004
    row = [[0, 89, 90, 191, 192, 254]]
    m = read_image(_image(tmp_path, row), 0.1)
    assert m.cells.tolist() == [[OCCUPIED, OCCUPIED, UNKNOWN, UNKNOWN, FREE, FREE]]
    neg = read_image(_image(tmp_path, row), 0.1, negate=True)  # p = value/255: white is occupied
    assert neg.cells.tolist() == [[FREE, UNKNOWN, UNKNOWN, OCCUPIED, OCCUPIED, OCCUPIED]]


def test_scale_and_raw_modes_and_alpha(tmp_path):
    rgba = np.zeros((1, 4, 4), np.uint8)
    rgba[0, :, :3] = [[0, 0, 0], [128, 128, 128], [254, 254, 254], [0, 0, 0]]
    rgba[0, :, 3] = [255, 255, 255, 0]  # the last pixel transparent
    Image.fromarray(rgba, "RGBA").save(tmp_path / "a.png")
    scale = read_image(tmp_path / "a.png", 0.1, mode="scale")
    # 128: p = 0.498 -> rint((0.498 - 0.25) / 0.4 * 100) = 62; transparent: unknown
    assert scale.cells.tolist() == [[OCCUPIED, 62, FREE, UNKNOWN]]
    # trinary: map_io averages the opacity in for an image with alpha: grey 128 -> (3 x 0.502 + 1) / 4 = 0.627 shade,
    # p = 0.373: unknown; transparent black -> p = 1: occupied
    trinary = read_image(tmp_path / "a.png", 0.1)
    assert trinary.cells.tolist() == [[OCCUPIED, UNKNOWN, FREE, OCCUPIED]]
    # grey 80: without alpha p = 0.686, occupied; with an (opaque) alpha channel p = 0.75 x 0.686 = 0.515, unknown
    Image.fromarray(np.full((1, 1, 3), 80, np.uint8)).save(tmp_path / "rgb.png")
    Image.fromarray(np.full((1, 1, 4), [80, 80, 80, 255], np.uint8), "RGBA").save(tmp_path / "rgba.png")
    assert read_image(tmp_path / "rgb.png", 0.1).cells.tolist() == [[OCCUPIED]]
    assert read_image(tmp_path / "rgba.png", 0.1).cells.tolist() == [[UNKNOWN]]
    # (scale mode leaves the alpha out)
    assert read_image(tmp_path / "rgba.png", 0.1, mode="scale").cells.tolist() == [[OCCUPIED]]
    raw = read_image(_image(tmp_path, [[0, 100, 101, 255]]), 0.1, mode="raw")
    assert raw.cells.tolist() == [[0, 100, UNKNOWN, UNKNOWN]]


def test_wall_boxes_cover_exactly_the_blocked_cells_and_are_few(tmp_path):
    rng = np.random.default_rng(3)
    pixels = np.full((120, 150), 254, np.uint8)
    for _ in range(40):
        r, c = rng.integers(0, 110, 2)
        pixels[r : r + rng.integers(1, 12), c : c + rng.integers(1, 12)] = rng.choice([0, 128])
    m = read_image(_image(tmp_path, pixels), 0.05, origin=(-2.0, 1.0))
    boxes = wall_boxes(m)
    assert len(boxes) < 200
    # every cell centre is inside a box exactly when it is blocked (occupied or unknown)
    rows, cols = np.mgrid[0 : pixels.shape[0], 0 : pixels.shape[1]]
    xs = -2.0 + (cols + 0.5) * 0.05
    ys = 1.0 + (pixels.shape[0] - rows - 0.5) * 0.05
    covered = np.zeros(pixels.shape, int)
    for box in boxes:
        covered += points_in_polygon(xs, ys, list(box))
    assert (covered <= 1).all(), "boxes overlap"
    assert ((covered == 1) == m.blocked).all()


def test_a_400_by_400_map_with_ragged_walls_gives_a_few_hundred_boxes(tmp_path):
    """A building-size map (20 m at 0.05 m/cell) as a scan makes it: walls with cells stuck to
    their faces, furniture, unknown outside. The boxes, painted back cell by cell, are its blocked cells."""
    rng = np.random.default_rng(7)
    pixels = np.full((400, 400), 128, np.uint8)  # unknown outside the building
    pixels[10:390, 10:390] = 0
    pixels[14:386, 14:386] = 254
    for k in (130, 260):  # two inner walls each way, a 1 m door in each
        pixels[14:386, k : k + 3] = 0
        pixels[k : k + 3, 14:386] = 0
        pixels[60:80, k : k + 3] = pixels[k : k + 3, 200:220] = 254
    for _ in range(30):  # furniture
        r, c = rng.integers(20, 370, 2)
        pixels[r : r + rng.integers(4, 20), c : c + rng.integers(4, 20)] = 0
    walls = pixels == 0
    face = (np.roll(walls, 1, 0) | np.roll(walls, -1, 0) | np.roll(walls, 1, 1) | np.roll(walls, -1, 1)) & ~walls
    pixels[face & (rng.random(pixels.shape) < 0.05)] = 0  # ragged faces
    m = read_image(_image(tmp_path, pixels), 0.05, origin=(-3.0, 2.0))
    boxes = wall_boxes(m)
    assert len(boxes) <= 400, len(boxes)
    painted = np.zeros(pixels.shape, int)
    for box in boxes:
        xs, ys = [p[0] for p in box], [p[1] for p in box]
        c0, c1 = round((min(xs) + 3.0) / 0.05), round((max(xs) + 3.0) / 0.05)
        r0, r1 = 400 - round((max(ys) - 2.0) / 0.05), 400 - round((min(ys) - 2.0) / 0.05)
        painted[r0:r1, c0:c1] += 1
    assert (painted <= 1).all() and ((painted == 1) == m.blocked).all()


def test_a_map_world_loads_its_walls_and_publishes_the_source_map(tmp_path):
    make_map_world(tmp_path)
    w = load_world(tmp_path / "world.yaml")
    assert w.map is not None and {s.id for s in w.walls} == {MAP_WALL_ID} and len(w.walls) < 20
    assert [r.name for r in w.rooms] == ["A", "B"]
    grid = rasterise(w)
    pixels = map_pixels()
    assert (grid.width, grid.height, grid.resolution_m) == (pixels.shape[1], pixels.shape[0], RESOLUTION)
    assert (grid.origin_x, grid.origin_y) == ORIGIN
    expected = np.where(pixels == 0, OCCUPIED, np.where(pixels == 254, FREE, UNKNOWN))[::-1]  # rows bottom-up, as /map
    assert (grid.data == expected).all()


def test_an_overlay_adds_walls_and_obstructions_to_the_map(tmp_path):
    make_map_world(tmp_path)
    text = (tmp_path / "world.yaml").read_text()
    text += "walls:\n  - {segment: [[0.5, -1.0], [0.5, -0.5]], thickness: 0.1}\n"
    text += (
        "obstructions:\n"
        "  - {id: door, segment: [[3.6, 0.6], [3.6, 1.6]], thickness: 0.1, removed_when_human_reaches: B}\n"
    )
    (tmp_path / "world.yaml").write_text(text)
    w = load_world(tmp_path / "world.yaml")
    assert rasterise(w).is_occupied(3.6, 1.0) and not rasterise(w, removed=frozenset({"door"})).is_occupied(3.6, 1.0)
    assert rasterise(w).is_occupied(0.5, -0.75)


def test_a_floor_plan_png_with_a_scale_is_a_world(tmp_path):
    make_map_world(tmp_path, suffix=".png")
    (tmp_path / "world.yaml").write_text(
        (tmp_path / "world.yaml")
        .read_text()
        .replace("map: map.yaml", "map: {image: map.png, resolution: 0.05, origin: [-1.0, -2.0]}")
    )
    assert len(load_world(tmp_path / "world.yaml").walls) == len(load_world(tmp_path / "world.yaml").walls) > 0


@pytest.mark.parametrize(
    "change, words",
    [
        (("map: map.yaml", "map: nothing.yaml"), "nothing.yaml"),
        (("map: map.yaml", "map: {image: map.pgm, resolution: -1}"), "map.resolution: must be"),
        (
            ("map: map.yaml", "map: {image: map.pgm, resolution: 0.05, origin: [0, 0, 0.5]}"),
            "map.origin: yaw must be 0",
        ),
        (("map: map.yaml", "map: {image: map.pgm, resolution: 0.05, free_thresh: 0.9}"), "free_thresh"),
        (
            ("map: map.yaml", "map: {image: map.pgm, resolution: 0.05, mode: fancy}"),
            "map.mode: must be one of trinary, scale, raw",
        ),
        (("map: map.yaml", "map: {image: map.yaml, resolution: 0.05}"), "is not a map image"),
        (("map: map.yaml", "map: {image: missing.png, resolution: 0.05}"), "cannot be read as an image"),
        (("map: map.yaml", "map: {image: map.pgm, resolution: 5.0}"), "exceed the 100 m"),
        (("start: [1.0, 0.0, 0.0]", "start: [20.0, 0.0, 0.0]"), "robot.start: (20, 0) lies outside the map"),
        (("start: [1.0, 0.0, 0.0]", "start: [-0.5, 0.0, 0.0]"), "robot.start: (-0.5, 0) lies inside a wall of the map"),
        (("centre: [1.5, 1.0]", "centre: [15, 1.0]"), "rooms[0].centre: (15, 1) lies outside the map"),
        (
            ("map: map.yaml", "map: map.pgm"),
            "map: map.pgm is an image: give its scale with it, map: {image: map.pgm, resolution:",
        ),
    ],
)
def test_bad_maps_are_refused_in_one_line(tmp_path, change, words):
    make_map_world(tmp_path)
    (tmp_path / "world.yaml").write_text((tmp_path / "world.yaml").read_text().replace(*change))
    with pytest.raises(WorldError) as e:
        load_world(tmp_path / "world.yaml")
    assert words in str(e.value) and "\n" not in str(e.value), str(e.value)


def test_a_bad_map_yaml_names_its_own_file_and_key(tmp_path):
    make_map_world(tmp_path)
    (tmp_path / "map.yaml").write_text(
        (tmp_path / "map.yaml").read_text().replace("resolution: 0.05", "resolution: fine")
    )
    with pytest.raises(WorldError, match=r"map\.yaml: resolution: must be a positive number, got .fine."):
        load_world(tmp_path / "world.yaml")


@pytest.mark.parametrize(
    "change, words",
    [
        (("resolution: 0.05", "resolution: 0"), "map.yaml: resolution: must be a positive number, got 0"),
        (
            ("resolution: 0.05", "resolutoin: 0.05"),
            "map.yaml: resolution: is required (is 'resolutoin' meant to be 'resolution'?)",
        ),
    ],
)
def test_a_map_yamls_own_mistakes_name_it(tmp_path, change, words):
    make_map_world(tmp_path)
    (tmp_path / "map.yaml").write_text((tmp_path / "map.yaml").read_text().replace(*change))
    with pytest.raises(WorldError) as e:
        load_world(tmp_path / "world.yaml")
    assert words in str(e.value), str(e.value)


def test_a_map_image_with_nothing_occupied_makes_no_world(tmp_path):
    make_map_world(tmp_path, np.full((100, 100), 254, np.uint8))
    with pytest.raises(WorldError, match="walls: needs at least one wall"):
        load_world(tmp_path / "world.yaml")


def test_map_image_grid_rows_are_bottom_up():
    m = MapImage(np.array([[100, 0], [0, -1]], np.int8), 0.5, (0.0, 0.0))
    g = m.grid()
    assert g.is_occupied(0.25, 0.75) and not g.is_occupied(0.75, 0.75) and not g.is_occupied(0.25, 0.25)
    assert m.occupied.tolist() == [[True, False], [False, False]] and m.unknown.tolist() == [
        [False, False],
        [False, True],
    ]
    assert m.blocked.tolist() == [[True, False], [False, True]]
