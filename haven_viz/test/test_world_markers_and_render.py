import math

import matplotlib.image as mpimg
import numpy as np
import pytest

from haven_sim.common.geometry import Pose2D, polygon_area
from haven_sim.sim.world import packaged_world
from haven_sim.sim.world_file import load_world
from haven_viz.cues import ArCues
from haven_viz.render import render_scene
from haven_viz.world_markers import COLORS, body_markers, triangulate, world_markers


def test_triangulation_of_a_concave_polygon_covers_its_area():
    poly = [(0, 0), (3, 0), (3, 1), (1, 1), (1, 3), (0, 3)]  # an L
    tris = triangulate(poly)
    assert len(tris) == len(poly) - 2
    assert sum(abs(polygon_area(list(t))) for t in tris) == pytest.approx(polygon_area(poly))


def test_world_markers_colour_gems_by_owner_and_drop_collected_ones():
    world = load_world(packaged_world("small_test"))
    ms = world_markers(world)
    gems = {m.id: m for m in ms if m.ns == "gems"}
    owners = {i: g.owner for i, g in enumerate(world.gems)}
    assert all(gems[i].color == COLORS[f"{owners[i]}_gem"] for i in gems)
    assert {m.ns for m in ms} >= {"walls", "obstacles", "rooms", "gems", "gem_areas", "charging_base"}
    walls = next(m for m in ms if m.ns == "walls")
    assert len(walls.points) % 3 == 0 and len(walls.points) > 0
    after = world_markers(world, collected={world.gems[0].id})
    assert 0 not in {m.id for m in after if m.ns == "gems"}


def test_body_markers_for_robot_and_each_human():
    ms = body_markers(Pose2D(1, 2, 0.5), {"ann": Pose2D(3, 3, 0), "bob": Pose2D(4, 4, 0)})
    assert [(m.ns, m.id) for m in ms if m.ns in ("robot", "humans")] == [
        ("robot", 0),
        ("robot", 1),
        ("humans", 0),
        ("humans", 1),
    ]
    assert [m.text for m in ms if m.ns == "human_names"] == ["ann", "bob"]


def test_render_writes_a_picture_of_the_scene(tmp_path):
    world = load_world(packaged_world("small_test"))
    cues = ArCues()
    from haven_sim.nav.path_style import shape_path

    cues.set_path(shape_path([(1.0, 2.5), (6.5, 1.5)], math.pi / 2))
    robot = Pose2D(1.0, 2.5, math.pi / 2)
    markers = world_markers(world) + body_markers(robot, {"h1": Pose2D(2.0, 3.0, 0)})
    markers += cues.markers(robot, [(2.0, 3.0)], 0.3, "Going to gem r1")
    out = render_scene(
        world,
        markers,
        tmp_path / "scene.png",
        title="test",
        trails={"robot": (np.array([[0.5, 2.5], [1.0, 2.5]]), "black")},
    )
    img = mpimg.imread(out)
    assert img.shape[0] > 300 and img.shape[1] > 500
    yellow = (img[:, :, 0] > 0.85) & (img[:, :, 1] > 0.85) & (img[:, :, 2] < 0.2)
    assert yellow.sum() > 200  # the projected path is drawn
