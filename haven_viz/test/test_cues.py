"""Every AR cue rule, on plain data."""

import math

import pytest
from foreign_paths import ARC_END_M, ARC_START_M, arc_path

from haven_sim.common.geometry import Pose2D
from haven_sim.nav.path_style import shape_path
from haven_viz.cues import BATTERY_NS, PATH_NS, SIGNAL_NS, THOUGHT_NS, ArCues, CueParams, Toggles, battery_color
from haven_viz.markers import MarkerDiff, Shape

STRAIGHT = [Pose2D(x * 0.4, 0.0, 0.0) for x in range(11)]  # 4 m along x


def of(markers, ns):
    return [m for m in markers if m.ns == ns]


def test_path_markers_every_spacing_and_consumed_as_the_robot_passes():
    cues = ArCues(CueParams(marker_spacing_m=0.4, consume_distance_m=0.2))
    cues.set_path(STRAIGHT)
    # (in turn: each call consumes the markers passed; the last one: backing up does not bring markers back)
    counts = [len(of(cues.markers(Pose2D(x, 0.05, 0.0)), PATH_NS)) for x in (0.0, 0.5, 1.0, 2.0, 3.0, 3.9, 1.0)]
    assert counts[0] == 10  # at 0.4, 0.8, ..., 4.0 (none at the start)
    assert counts == sorted(counts, reverse=True) and counts[-1] == counts[-2] == 0
    ids = [m.id for m in of(cues.markers(Pose2D(3.0, 0.0, 0.0)), PATH_NS)]
    assert ids == [], "consumed markers stay consumed"


def test_spheres_on_straights_cubes_on_arcs_and_steps_ahead():
    poses = shape_path([(0, 0), (4, 0), (7, 2.5)], 0.0, goal_yaw=None)
    cues = ArCues(CueParams(marker_spacing_m=0.2, steps_ahead=0))
    cues.set_path(poses)
    ms = of(cues.markers(Pose2D(0, 0, 0)), PATH_NS)
    shapes = [m.shape for m in ms]
    assert Shape.CUBE in shapes and Shape.SPHERE in shapes
    first_cube = shapes.index(Shape.CUBE)
    assert all(s is Shape.SPHERE for s in shapes[:first_cube])
    for m in ms:  # cubes sit where the path turns
        if m.shape is Shape.CUBE:
            assert 2.5 < m.position[0] < 5.0
    limited = ArCues(CueParams(marker_spacing_m=0.2, steps_ahead=5))
    limited.set_path(poses)
    assert [m.id for m in of(limited.markers(Pose2D(0, 0, 0)), PATH_NS)] == [m.id for m in ms[:5]]
    assert all(m.scale == (0.2, 0.2, 0.2) for m in ms)


@pytest.mark.parametrize(
    "shape",
    [dict(spacing_m=0.05), dict(spacing_m=0.05, orientation="tangent", yaw_jitter_deg=1.0), dict(spacing_m=0.3)],
)
def test_any_planners_arc_shows_cubes_on_the_arc_and_spheres_elsewhere(shape):
    """NavFn, Smac, sparse: cubes on the arc, spheres on the straights (within 0.15 m of where the
    arc begins and ends, either)."""
    cues = ArCues(CueParams(marker_spacing_m=0.2))
    cues.set_path(arc_path(**shape))
    ms = of(cues.markers(Pose2D(0, 0, 0)), PATH_NS)
    assert len(ms) == 23  # (the first is used up where the robot stands)
    for m in ms:
        s = (m.id + 1) * 0.2
        if ARC_START_M + 0.15 < s < ARC_END_M - 0.15:
            assert m.shape is Shape.CUBE, s
        elif not ARC_START_M - 0.15 < s < ARC_END_M + 0.15:
            assert m.shape is Shape.SPHERE, s


@pytest.mark.parametrize("deg,expected", [(0.0, []), (10.0, []), (12.0, [0]), (-12.0, [1]), (45.0, [0])])
def test_turn_signal_side_and_threshold(deg, expected):
    cues = ArCues()
    cues.set_path([Pose2D(0, 0, 0), Pose2D(5, 0, 0)])
    robot = Pose2D(0.0, 0.0, -math.radians(deg))  # the path ahead is deg to the left
    ms = of(cues.markers(robot), SIGNAL_NS)
    assert [m.id for m in ms] == expected  # id 0 = left arrow, 1 = right arrow
    if ms:
        side = 1 if expected == [0] else -1
        assert math.cos(ms[0].yaw - (robot.yaw + side * math.pi / 2)) > 0.99  # points outward


def test_turn_signal_lit_while_rotating_in_place_then_off():
    poses = shape_path([(0, 0), (0, 3)], 0.0)  # rotate 90 deg left first
    cues = ArCues()
    cues.set_path(poses)
    assert [m.id for m in of(cues.markers(Pose2D(0, 0, 0.0)), SIGNAL_NS)] == [0]
    assert [m.id for m in of(cues.markers(Pose2D(0, 0, 1.2)), SIGNAL_NS)] == [0]
    assert of(cues.markers(Pose2D(0, 0, math.pi / 2 - 0.05)), SIGNAL_NS) == []


def test_thought_bubble_appears_near_a_human_with_hysteresis():
    cues = ArCues(CueParams(thought_radius_m=3.0, thought_hysteresis_m=0.5))
    robot = Pose2D(0, 0, 0)
    shown = []
    for d in (4.0, 3.2, 2.9, 3.3, 3.49, 3.6, 3.2, 3.0):
        ms = of(cues.markers(robot, [(d, 0.0)], thought="Collecting gem 3"), THOUGHT_NS)
        shown.append(bool(ms))
    assert shown == [False, False, True, True, True, False, False, True]
    text = of(cues.markers(robot, [(1.0, 0.0)], thought="Collecting gem 3"), THOUGHT_NS)
    assert text[0].shape is Shape.TEXT_VIEW_FACING and text[0].text == "Collecting gem 3"
    assert text[0].position[2] > 0.5  # above the robot
    assert of(cues.markers(robot, [(1.0, 0.0)], thought=""), THOUGHT_NS) == []  # nothing to say


@pytest.mark.parametrize(
    "level,band", [(1.0, 0), (0.81, 0), (0.8, 1), (0.61, 1), (0.6, 2), (0.41, 2), (0.21, 3), (0.2, 4), (0.0, 4)]
)
def test_battery_colour_bands_follow_havens_thresholds(level, band):
    colors = [battery_color(x) for x in (0.9, 0.7, 0.5, 0.3, 0.1)]
    assert battery_color(level) == colors[band]


def test_battery_bar_length_and_percentage():
    ms = of(ArCues().markers(Pose2D(1, 1, 0), battery_level=0.25), BATTERY_NS)
    frame, bar, text = sorted(ms, key=lambda m: m.id)
    assert bar.scale[0] == pytest.approx(0.25 * 0.4)
    assert bar.position[0] - bar.scale[0] / 2 == pytest.approx(frame.position[0] - 0.2)  # filled from the left end
    assert text.text == "25 %"


def test_switching_a_cue_off_deletes_its_markers_explicitly():
    cues = ArCues()
    cues.set_path(STRAIGHT)
    diff = MarkerDiff()
    robot = Pose2D(0, 0.0, 0.3)
    first = diff.update(cues.markers(robot, [(1, 0)], 0.9, "hello"))
    assert {m.ns for m in first.upsert} == {PATH_NS, SIGNAL_NS, THOUGHT_NS, BATTERY_NS} and not first.delete
    assert not diff.update(cues.markers(robot, [(1, 0)], 0.9, "hello"))  # nothing changed, nothing sent
    off = diff.update(cues.markers(robot, [(1, 0)], 0.9, "hello", Toggles(path_projection=False, thought_bubble=False)))
    assert off.upsert == []
    assert {ns for ns, _ in off.delete} == {PATH_NS, THOUGHT_NS}
    assert len([k for k in off.delete if k[0] == PATH_NS]) == 10
    back = diff.update(cues.markers(robot, [(1, 0)], 0.9, "hello"))
    assert {m.ns for m in back.upsert} == {PATH_NS, THOUGHT_NS}


def test_sub_millimetre_motion_is_not_resent():
    diff = MarkerDiff()
    cues = ArCues()
    diff.update(cues.markers(Pose2D(1.0, 1.0, 0.0), battery_level=0.5))
    assert not diff.update(cues.markers(Pose2D(1.0002, 1.0, 0.0), battery_level=0.5))
    assert diff.update(cues.markers(Pose2D(1.01, 1.0, 0.0), battery_level=0.5))


def test_invalid_params_are_refused():
    with pytest.raises(ValueError, match="scheme"):
        ArCues(CueParams(scheme="pink"))
    with pytest.raises(ValueError, match="steps_ahead"):
        ArCues(CueParams(steps_ahead=-1))


def test_a_full_resend_still_carries_the_deletes():
    cues = ArCues()
    cues.set_path(STRAIGHT)
    diff = MarkerDiff()
    robot = Pose2D(0, 0.0, 0.0)
    diff.update(cues.markers(robot, battery_level=0.9))
    again = diff.update(cues.markers(robot, battery_level=0.9, toggles=Toggles(path_projection=False)), resend_all=True)
    assert {m.ns for m in again.upsert} == {BATTERY_NS}
    assert len([k for k in again.delete if k[0] == PATH_NS]) == 10


def test_turn_signal_shows_the_side_of_a_curve_ahead_before_it_begins():
    # Straight to x = 3, then an arc to the right (y < 0).
    poses = shape_path([(0, 0), (4, 0), (7, -2.5)], 0.0, goal_yaw=None)
    cues = ArCues()
    cues.set_path(poses)
    arc_start = next(p.x for p in poses if abs(p.yaw) > 1e-3)
    lit_at = next(x / 10 for x in range(0, 40) if cues.frame(Pose2D(x / 10, 0.0, 0.0)).state.turn_signal != 0)
    assert cues.frame(Pose2D(lit_at, 0.0, 0.0)).state.turn_signal == -1
    assert arc_start - lit_at >= 0.5 * cues.params.signal_lookahead_m  # lit well before the curve


def test_turn_signal_has_hysteresis_so_a_wobbling_heading_does_not_flicker():
    cues = ArCues()
    cues.set_path(STRAIGHT)
    # Heading errors around the 11 deg threshold: lit at 12, stays lit down to the 6 deg release.
    sides = [cues.signal_side(Pose2D(0.5, 0.0, math.radians(-a))) for a in (12, 9, 7, 10, 8, 12, 9)]
    assert sides == [1] * 7
    assert cues.signal_side(Pose2D(0.5, 0.0, math.radians(-4))) == 0
    assert cues.signal_side(Pose2D(0.5, 0.0, math.radians(-9))) == 0  # below the threshold: stays dark


def test_a_frame_without_markers_shows_the_same_cue_state():
    """Batch mode asks for the state only (no one reads the markers): the same state at every step."""
    poses = shape_path([(0, 0), (4, 0), (7, 2.5)], 0.0, goal_yaw=None)
    full, bare = ArCues(CueParams(marker_spacing_m=0.2)), ArCues(CueParams(marker_spacing_m=0.2))
    full.set_path(poses)
    bare.set_path(poses)
    states = set()
    for k in range(60):
        robot, now = Pose2D(0.12 * k, 0.02 * k * k / 60, 0.01 * k), 0.1 * k
        a = full.frame(robot, [(2.0, 0.5)], 0.01 * k, "going", Toggles(), now)
        b = bare.frame(robot, [(2.0, 0.5)], 0.01 * k, "going", Toggles(), now, markers=False)
        assert b.state == a.state and b.markers == [] and a.markers
        states.add((a.state.path_markers, a.state.turn_signal, a.state.thought))
    assert len(states) > 3  # the state changed along the way
