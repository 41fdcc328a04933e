import math

import numpy as np
import pytest

from haven_sim.common.geometry import (
    Pose2D,
    distance_point_to_edges,
    points_in_polygon,
    polygon_area,
    quaternion_to_yaw,
    segment_to_polygon,
    wrap_angle,
    yaw_to_quaternion,
)


@pytest.mark.parametrize("yaw", [0.0, 0.5, -2.0, math.pi - 1e-6, -math.pi + 1e-6])
def test_quaternion_round_trip(yaw):
    assert quaternion_to_yaw(*yaw_to_quaternion(yaw)) == pytest.approx(yaw, abs=1e-9)


def test_wrap_angle():
    assert wrap_angle(3 * math.pi / 2) == pytest.approx(-math.pi / 2)
    assert wrap_angle(-3 * math.pi / 2) == pytest.approx(math.pi / 2)
    assert wrap_angle(0.1) == pytest.approx(0.1)


def test_points_in_concave_polygon():
    # An L shape: the notch at (1.5, 1.5) is outside.
    poly = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
    xs = np.array([0.5, 1.5, 1.5, 0.5, 3.0])
    ys = np.array([0.5, 0.5, 1.5, 1.5, 0.5])
    assert points_in_polygon(xs, ys, poly).tolist() == [True, True, False, True, False]


def test_segment_polygon_covers_thickness_and_ends():
    poly = segment_to_polygon((0, 0), (2, 0), 0.2)
    assert polygon_area(poly) == pytest.approx(2.2 * 0.2)
    xs = np.array([-0.09, 2.09, 1.0, 1.0])
    ys = np.array([0.0, 0.0, 0.099, 0.11])
    assert points_in_polygon(xs, ys, poly).tolist() == [True, True, True, False]


def test_distance_point_to_edges():
    edges = np.array([[0.0, 0.0, 2.0, 0.0], [0.0, 0.0, 0.0, 2.0]])
    assert distance_point_to_edges(1.0, 0.5, edges) == pytest.approx(0.5)
    assert distance_point_to_edges(-1.0, -1.0, edges) == pytest.approx(math.sqrt(2))
    assert Pose2D(0, 0).distance_to((3, 4)) == pytest.approx(5.0)
