"""HAVEN's segmentation: rotate vs arc by the thresholds, spacing, collision checks; and reading any
planner's path (ours, NavFn, Smac, ThetaStar shapes) back into segments."""

import itertools
import math

import numpy as np
import pytest
from foreign_paths import ARC_END_M, ARC_START_M, GOAL, STYLE, arc_path, corner_path

from haven_sim.common.geometry import Pose2D, wrap_angle
from haven_sim.common.paths import SegmentKind, read_path
from haven_sim.nav.motion_style import MotionStyle
from haven_sim.nav.path_style import ShapeParams, shape_path

R, A, S = SegmentKind.ROTATE, SegmentKind.ARC, SegmentKind.STRAIGHT


def kinds(poses):
    return [s.kind for s in read_path(poses, *STYLE).segments]


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


@pytest.mark.parametrize(
    "start_deg,expected", [(0.0, [S]), (40.0, [A, S]), (-55.0, [A, S]), (70.0, [R, S]), (180.0, [R, S])]
)
def test_start_arc_or_rotation_from_the_robot_heading(start_deg, expected):
    poses = shape_path([(0.0, 0.0), (4.0, 0.0)], math.radians(start_deg))
    assert kinds(poses) == expected
    assert poses[-1].x == pytest.approx(4.0) and poses[-1].y == pytest.approx(0.0)
    assert poses[-1].yaw == pytest.approx(math.atan2(-poses[-2].y, 4.0 - poses[-2].x), abs=1e-6)


def test_arc_is_tangent_smooth_and_removes_the_heading_change():
    poses = shape_path(corner(40.0), 0.0)
    arc = read_path(poses, *STYLE).segments[1]
    pts = poses[arc.start : arc.end + 1]
    assert pts[0].yaw == pytest.approx(0.0) and pts[-1].yaw == pytest.approx(math.radians(40.0))
    radii = []
    # circumradius of consecutive triples: constant on a circle
    for a, b, c in zip(pts, pts[1:], pts[2:], strict=False):
        ab, bc, ca = math.dist(a[:2], b[:2]), math.dist(b[:2], c[:2]), math.dist(c[:2], a[:2])
        area = abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y)) / 2
        radii.append(ab * bc * ca / (4 * area))
    assert max(radii) - min(radii) < 1e-6


def test_spacing_goal_yaw_and_endpoints():
    p = ShapeParams(marker_spacing_m=0.25)
    poses = shape_path([(0.0, 0.0), (2.0, 0.0), (2.0, 3.0)], 0.0, params=p, goal_yaw=math.pi)
    steps = [math.dist(a[:2], b[:2]) for a, b in itertools.pairwise(poses)]
    assert max(steps) <= 0.25 + 1e-9
    assert kinds(poses) == [S, R, S, R]
    assert tuple(poses[-1][:2]) == pytest.approx((2.0, 3.0)) and abs(wrap_angle(poses[-1].yaw - math.pi)) < 1e-9
    rot = read_path(poses, *STYLE).segments[1]
    yaws = [poses[i].yaw for i in range(rot.start, rot.end + 1)]
    assert all(abs(wrap_angle(b - a)) <= math.radians(15.0) + 1e-9 for a, b in itertools.pairwise(yaws))


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
    poses += [Pose2D(1.0, 1.0, math.pi / 2 + d) for d in (0.8, math.pi / 2)]
    poses += [Pose2D(1.0 - d, 1.0, math.pi) for d in (0.5, 1.0)]
    segs = read_path(poses, *STYLE).segments
    assert [s.kind for s in segs] == [A, R, S]
    assert segs[1].yaw == pytest.approx(math.pi)
    assert (segs[0].start, segs[0].end) == (0, 29)
    assert read_path([], *STYLE).segments == [] and read_path([Pose2D(0, 0, 0)], *STYLE).segments == []


def test_classify_round_trips_shape_path():
    poses = shape_path([(0, 0), (3, 0), (3, 2), (0.5, 2.2)], math.radians(30))
    segs = read_path(poses, *STYLE).segments
    assert [s.kind for s in segs] == [A, S, R, S, R, S]
    assert segs[0].start == 0 and segs[-1].end == len(poses) - 1
    assert all(a.end == b.start for a, b in itertools.pairwise(segs))


def test_invalid_style_is_refused():
    with pytest.raises(ValueError, match="marker_spacing"):
        ShapeParams(marker_spacing_m=0.0)
    with pytest.raises(ValueError, match="arc_max_angle_deg"):
        MotionStyle(arc_max_angle_deg=0.0)


# -- any planner's path, read from its geometry -------------------------------------------------
NAV2_SHAPES = {
    "navfn (5 cm, identity)": dict(spacing_m=0.05),
    "smac (5 cm, 1 deg jitter)": dict(spacing_m=0.05, orientation="tangent", yaw_jitter_deg=1.0),
    "smac (exact headings)": dict(spacing_m=0.05, orientation="tangent"),
    "sparse (0.3 m, identity)": dict(spacing_m=0.3),
    "sparse (0.5 m, jitter)": dict(spacing_m=0.5, orientation="tangent", yaw_jitter_deg=1.0),
}


@pytest.mark.parametrize("shape", NAV2_SHAPES)
def test_a_nav2_shaped_arc_reads_as_straight_arc_straight_then_the_goal_yaw(shape):
    poses = arc_path(**NAV2_SHAPES[shape])
    reading = read_path(poses, *STYLE)
    segs = reading.segments
    assert [s.kind for s in segs] == [S, A, S, R]
    # the goal yaw, at the end
    assert (segs[-1].start, segs[-1].end, segs[-1].yaw) == (len(poses) - 1, len(poses) - 1, GOAL.yaw)
    # the arc where it is (a sparse path's polygon may read as two), nothing elsewhere; a dense one to 2 cm
    if NAV2_SHAPES[shape]["spacing_m"] == 0.05:
        ((a, b),) = reading.arcs
        assert a == pytest.approx(ARC_START_M, abs=0.02) and b == pytest.approx(ARC_END_M, abs=0.02)
    assert all(ARC_START_M - 0.15 < a < b < ARC_END_M + 0.2 for a, b in reading.arcs), reading.arcs
    assert sum(b - a for a, b in reading.arcs) > 0.6 * (ARC_END_M - ARC_START_M), reading.arcs
    # the travel heading, not the identity orientations
    assert reading.headings[0] == pytest.approx(0.0, abs=0.05) and reading.headings[-1] == pytest.approx(
        math.pi / 2, abs=0.05
    )


def test_a_path_that_arrives_facing_its_goal_yaw_gets_no_final_rotation():
    poses = arc_path(orientation="tangent")
    poses[-1] = Pose2D(poses[-1].x, poses[-1].y, math.pi / 2 + math.radians(1.0))
    assert [s.kind for s in read_path(poses, *STYLE).segments] == [S, A, S]


@pytest.mark.parametrize("spacing", [0.05, None])
def test_thetastar_corners_rotate_when_havens_style_would_and_arc_otherwise(spacing):
    sharp = read_path(corner_path(90.0, spacing), *STYLE).segments
    assert [s.kind for s in sharp][:3] == [S, R, S] and sharp[1].yaw == pytest.approx(math.pi / 2, abs=0.05)
    # (its identity orientations: a goal yaw of 0, rotated to at the end)
    gentle = read_path(corner_path(30.0, spacing), *STYLE)
    assert [s.kind for s in gentle.segments] == ([S, A, S, R] if spacing else [A, R])  # (two steps: both touch the arc)
    ((a, b),) = gentle.arcs  # the arc the robot drives around the corner, centred on it
    assert a == pytest.approx(2.0 - 0.15, abs=0.02) and b == pytest.approx(2.0 + 0.15, abs=0.02)


def test_our_planners_paths_read_as_written():
    """Paths in our convention are read from their yaws: every step's kind as the yaws say (a yaw
    step under the planner's 2 deg straight tolerance may read straight)."""
    rng = np.random.default_rng(1)
    for _ in range(100):
        pts = [(0.0, 0.0)]
        for _ in range(rng.integers(2, 5)):
            pts.append((pts[-1][0] + rng.uniform(-4, 4), pts[-1][1] + rng.uniform(-4, 4)))
        poses = shape_path(pts, rng.uniform(-3, 3))
        for seg in read_path(poses, *STYLE).segments:
            for a, b in zip(poses[seg.start : seg.end], poses[seg.start + 1 : seg.end + 1], strict=False):
                moved, turned = (
                    math.hypot(b.x - a.x, b.y - a.y) > 1e-3,
                    abs(math.remainder(b.yaw - a.yaw, 2 * math.pi)) > math.radians(0.5),
                )
                small = abs(math.remainder(b.yaw - a.yaw, 2 * math.pi)) < math.radians(2.0)
                assert seg.kind is (A if moved and turned else S if moved else R) or (small and seg.kind is S)


@pytest.mark.parametrize("start_deg", [70.0, 180.0, -120.0])
def test_a_holonomic_robot_sets_off_straight_where_a_diff_drive_rotates_first(start_deg):
    holonomic = MotionStyle(rotate_in_place=False)
    poses = shape_path([(0.0, 0.0), (4.0, 0.0)], math.radians(start_deg), holonomic)
    assert kinds(poses) == [S]
    assert min(p.x for p in poses) >= 0.0 and max(abs(p.y) for p in poses) < 1e-9  # never swings away first
    assert kinds(shape_path([(0.0, 0.0), (4.0, 0.0)], math.radians(40.0), holonomic)) == [A, S]  # an arc within 60 deg
