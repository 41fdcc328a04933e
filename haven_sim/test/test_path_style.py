"""HAVEN's segmentation: rotate vs arc by the thresholds, spacing, collision checks, classification."""

import math

import numpy as np
import pytest

from haven_sim.common.geometry import Pose2D, wrap_angle
from haven_sim.common.paths import SegmentKind, classify
from haven_sim.nav.motion_style import MotionStyle
from haven_sim.nav.path_style import ShapeParams, shape_path

R, A, S = SegmentKind.ROTATE, SegmentKind.ARC, SegmentKind.STRAIGHT


def kinds(poses):
    return [s.kind for s in classify(poses)]


def corner(deg, leg=3.0):
    """A polyline (0,0) -> (3,0) -> then `leg` metres at `deg` degrees left."""
    t = math.radians(deg)
    return [(0.0, 0.0), (3.0, 0.0), (3.0 + leg * math.cos(t), leg * math.sin(t))]


@pytest.mark.parametrize("deg,expected", [(59.0, [S, A, S]), (61.0, [S, R, S]), (-45.0, [S, A, S]), (-90.0, [S, R, S])])
def test_corner_arc_or_rotate_by_the_60_degree_rule(deg, expected):
    assert kinds(shape_path(corner(deg), start_yaw=0.0)) == expected


def test_short_next_leg_rotates_in_place():
    style = MotionStyle(too_close_distance_m=0.5)
    assert kinds(shape_path(corner(30.0, leg=0.4), 0.0, style)) == [S, R, S]
    assert kinds(shape_path(corner(30.0, leg=0.6), 0.0, style)) == [S, A, S]


@pytest.mark.parametrize("start_deg,expected", [(0.0, [S]), (40.0, [A, S]), (-55.0, [A, S]), (70.0, [R, S]), (180.0, [R, S])])
def test_start_arc_or_rotation_from_the_robot_heading(start_deg, expected):
    poses = shape_path([(0.0, 0.0), (4.0, 0.0)], math.radians(start_deg))
    assert kinds(poses) == expected
    assert poses[-1].x == pytest.approx(4.0) and poses[-1].y == pytest.approx(0.0)
    assert poses[-1].yaw == pytest.approx(math.atan2(-poses[-2].y, 4.0 - poses[-2].x), abs=1e-6)


def test_arc_is_tangent_smooth_and_removes_the_heading_change():
    poses = shape_path(corner(40.0), 0.0)
    arc = classify(poses)[1]
    pts = poses[arc.start : arc.end + 1]
    assert pts[0].yaw == pytest.approx(0.0) and pts[-1].yaw == pytest.approx(math.radians(40.0))
    radii = []
    for a, b, c in zip(pts, pts[1:], pts[2:]):  # circumradius of consecutive triples: constant on a circle
        ab, bc, ca = math.dist(a[:2], b[:2]), math.dist(b[:2], c[:2]), math.dist(c[:2], a[:2])
        area = abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y)) / 2
        radii.append(ab * bc * ca / (4 * area))
    assert max(radii) - min(radii) < 1e-6


def test_spacing_goal_yaw_and_endpoints():
    p = ShapeParams(marker_spacing_m=0.25)
    poses = shape_path([(0.0, 0.0), (2.0, 0.0), (2.0, 3.0)], 0.0, params=p, goal_yaw=math.pi)
    steps = [math.dist(a[:2], b[:2]) for a, b in zip(poses, poses[1:])]
    assert max(steps) <= 0.25 + 1e-9
    assert kinds(poses) == [S, R, S, R]
    assert tuple(poses[-1][:2]) == pytest.approx((2.0, 3.0)) and abs(wrap_angle(poses[-1].yaw - math.pi)) < 1e-9
    rot = classify(poses)[1]
    yaws = [poses[i].yaw for i in range(rot.start, rot.end + 1)]
    assert all(abs(wrap_angle(b - a)) <= math.radians(15.0) + 1e-9 for a, b in zip(yaws, yaws[1:]))


def test_arc_that_would_hit_something_shrinks_or_becomes_a_rotation():
    calls = []

    def never_clear(pts):
        calls.append(len(pts))
        return False

    assert kinds(shape_path(corner(40.0), 0.0, is_clear=never_clear)) == [S, R, S]
    assert len(calls) >= 2  # tried smaller radii first

    def clear_if_small(pts):  # only arcs hugging the corner are allowed
        return bool(np.max(np.hypot(pts[:, 0] - 3.0, pts[:, 1])) < 0.2)

    poses = shape_path(corner(40.0), 0.0, is_clear=clear_if_small)
    assert kinds(poses) == [S, A, S]


def test_classify_reads_a_foreign_path():
    """A path made by someone else: dense points on a circle with tangent yaws, then a spin."""
    poses = [Pose2D(math.sin(t), 1 - math.cos(t), t) for t in np.linspace(0, math.pi / 2, 30)]
    poses += [Pose2D(1.0, 1.0, math.pi / 2 + d) for d in (0.3, 0.6)]
    poses += [Pose2D(1.0 - d, 1.0, math.pi / 2 + 0.6) for d in (0.5, 1.0)]
    segs = classify(poses)
    assert [s.kind for s in segs] == [A, R, S]
    assert (segs[0].start, segs[0].end) == (0, 29)
    assert classify([]) == [] and classify([Pose2D(0, 0, 0)]) == []


def test_classify_round_trips_shape_path():
    poses = shape_path([(0, 0), (3, 0), (3, 2), (0.5, 2.2)], math.radians(30))
    segs = classify(poses)
    assert [s.kind for s in segs] == [A, S, R, S, R, S]
    assert segs[0].start == 0 and segs[-1].end == len(poses) - 1
    assert all(a.end == b.start for a, b in zip(segs, segs[1:]))


def test_invalid_style_is_refused():
    with pytest.raises(ValueError, match="marker_spacing"):
        ShapeParams(marker_spacing_m=0.0)
    with pytest.raises(ValueError, match="arc_max_angle_deg"):
        MotionStyle(arc_max_angle_deg=0.0)
