"""The cue library (library_cues.py: a path line after Chadalavada et al. 2015, projected arrows
after Han et al. 2022, a light ring after Szafir et al. 2015), on plain data: registered as a lab's
cues are, off in condition `all`, drawn where their papers draw them, saying the robot's way to
the simulated participants, and refused on a robot they do not fit."""

import math

import pytest

from haven_scenarios.study.conditions import check_fit, condition_name, parse_condition
from haven_sim.common.geometry import Pose2D
from haven_sim.robots.fields import DEFAULT
from haven_sim.robots.robot_kind import resolve_robot
from haven_viz.cue_kind import accept_plugin
from haven_viz.cues import CUES, DEFAULT_ON, ArCues, Toggles, cues_for
from haven_viz.library_cues import (
    AMBER,
    ARROWS_NS,
    BLINK_HZ,
    GREEN,
    HAN_SPACING_M,
    LIGHT_RING_LEDS,
    LINE_NS,
    MAGENTA,
    RING_NS,
    LightRing,
)
from haven_viz.markers import Shape

pytestmark = pytest.mark.unit

LIBRARY = ("path_line", "projected_arrows", "light_ring")
STRAIGHT = [Pose2D(x * 0.5, 0.0, 0.0) for x in range(9)]  # 4 m along x
# 2 m, left, 2 m
TURNING = [Pose2D(x * 0.5, 0.0, 0.0) for x in range(5)] + [Pose2D(2.0, y * 0.5, math.pi / 2) for y in range(1, 5)]


def frame(path, robot, cue, now=None, robot_desc=DEFAULT):
    cues = ArCues(robot=robot_desc)
    cues.set_path(path)
    return cues.frame(robot, toggles=parse_condition([cue]), now=now)


def test_library_cues_are_registered_and_off_in_condition_all():
    assert set(LIBRARY) <= set(CUES)
    assert not set(LIBRARY) & set(DEFAULT_ON)
    assert condition_name(Toggles()) == "all" and Toggles().names_on() == list(DEFAULT_ON)
    assert condition_name(parse_condition(["path_line"])) == "path_line"
    everything = parse_condition(list(CUES))
    assert condition_name(everything) == "+".join(CUES)  # (every cue is not `all`)


def test_default_on_is_checked_like_the_other_cue_attributes():
    class Bad:
        default_on = "yes"

        def show(self, ctx, markers):
            return None

    with pytest.raises(ValueError, match="default_on must be true or false"):
        accept_plugin("bad", Bad)


def test_the_path_line_is_a_band_on_the_floor_from_the_robot_to_the_goal():
    f = frame(STRAIGHT, Pose2D(1.0, 0.0, 0.0), "path_line")
    (band,) = [m for m in f.markers if m.ns == LINE_NS]
    assert band.shape is Shape.TRIANGLE_LIST and len(band.points) % 3 == 0
    xs = [p[0] for p in band.points]
    assert min(xs) == pytest.approx(1.0, abs=0.05) and max(xs) == pytest.approx(4.0, abs=1e-6)
    assert all(abs(p[1]) <= 0.025 + 1e-9 and 0 < p[2] < 0.05 for p in band.points)  # 5 cm wide, just above the floor
    way, on_robot = f.ways["path_line"]
    assert not on_robot and way[-1] == pytest.approx((4.0, 0.0))
    assert f.state.value("path_line") == pytest.approx(3.0, abs=0.1)  # the remaining path, m


def test_projected_arrows_follow_han_et_al():
    f = frame(TURNING, Pose2D(0.0, 0.0, 0.0), "projected_arrows")
    arrows = [m for m in f.markers if m.ns == ARROWS_NS and m.shape is Shape.ARROW]
    (goal,) = [m for m in f.markers if m.ns == ARROWS_NS and m.shape is Shape.SPHERE]
    assert goal.position[:2] == pytest.approx((2.0, 2.0)) and goal.color == GREEN
    assert len(arrows) == 20  # 4 m of path: points 0.1 m apart, paired into 0.1 m arrows with 0.1 m gaps
    assert all(a.color == MAGENTA and a.scale[0] == HAN_SPACING_M for a in arrows)
    first, last = arrows[0], arrows[-1]
    # each points along the path
    assert first.yaw == pytest.approx(0.0, abs=1e-6) and last.yaw == pytest.approx(math.pi / 2, abs=1e-6)
    assert f.state.value("projected_arrows") == 20


def test_projected_arrows_need_a_floor_the_drone_has_none():
    drone = resolve_robot("quadrotor")
    assert "projected_arrows" not in cues_for(drone.kinematics) and "path_line" in cues_for(drone.kinematics)
    with pytest.raises(
        ValueError,
        match=r"^cue projected_arrows does not fit robot quadrotor \(aerial\): it serves diff_drive, omni robots$",
    ):
        check_fit(parse_condition(["path_projection", "projected_arrows"]), drone)
    check_fit(Toggles(), drone)  # `all`: every cue the robot has
    check_fit(parse_condition(["projected_arrows"]), DEFAULT)


def test_the_light_ring_lights_the_way_ahead_and_blinks_on_the_side_of_a_turn():
    ahead = frame(STRAIGHT, Pose2D(0.0, 0.0, 0.0), "light_ring", now=0.0)
    leds = [m for m in ahead.markers if m.ns == RING_NS]
    assert len(leds) == LIGHT_RING_LEDS and all(m.shape is Shape.SPHERE for m in leds)
    assert all(m.position[2] > DEFAULT.height_m for m in leds)  # on top of the body
    lit = [m for m in leds if m.color not in (AMBER, (0.15, 0.15, 0.15, 1.0))]
    assert lit and all(m.position[0] > 0 for m in lit)  # the front of the ring: where it goes
    assert ahead.state.value("light_ring") == {"bearing_deg": 0, "blink": 0}
    # Before the left turn: the left side blinks at BLINK_HZ (on for the first half of each period).
    cue = LightRing(ArCues().params)
    robot = Pose2D(1.5, 0.0, 0.0)
    cues = ArCues()
    cues.set_path(TURNING)
    on = cues.frame(robot, toggles=parse_condition(["light_ring"]), now=0.0)
    off = cues.frame(robot, toggles=parse_condition(["light_ring"]), now=0.5 / BLINK_HZ + 0.01)
    amber_on = [m for m in on.markers if m.ns == RING_NS and m.color == AMBER]
    assert amber_on and all(m.position[1] > 0 for m in amber_on)  # the left side (+y)
    assert not [m for m in off.markers if m.ns == RING_NS and m.color == AMBER]
    assert on.state.value("light_ring")["blink"] == 1 and cue.key == "light_ring"
    assert on.ways["light_ring"][1] is True  # drawn on the robot: seen with it


def test_library_cues_show_nothing_at_the_end_of_the_path():
    for cue in LIBRARY:
        cues = ArCues()
        cues.set_path(STRAIGHT)
        for x in (1.5, 3.0, 3.9):  # (the robot's progress along the path is searched near the last)
            f = cues.frame(Pose2D(x, 0.0, 0.0), toggles=parse_condition([cue]))
        assert not [m for m in f.markers if m.ns in (LINE_NS, ARROWS_NS, RING_NS)], cue
        assert not f.state.shown(cue)


def test_the_pass_side_rule_on_plain_data():
    """A pass to the right (Manoeuvre side -1): the right side lit the whole pass, whatever the path
    does; on the way back dark until the robot heads along its path again; then HAVEN's rule."""
    from haven_viz.builtin_cues import CueParams, TurnSignals
    from haven_viz.cue_kind import Manoeuvre, TrackedPath

    left_curve = [Pose2D(x * 0.5, 0.0, 0.0) for x in range(3)] + [
        Pose2D(1.0 + y * 0.3, y * 0.5, 1.0) for y in range(1, 5)
    ]
    path = TrackedPath(left_curve, 0.4)
    robot = Pose2D(0.0, 0.0, 0.0)
    signals = TurnSignals(CueParams())
    assert signals.side(robot, path, 0.0, Manoeuvre(1, -1)) == -1  # the path turns left; the pass is to the right
    assert signals.side(robot, path, 1.0, Manoeuvre(1, -1, returning=True)) == 0  # way back: dark
    straight = TrackedPath(STRAIGHT, 0.4)
    assert signals.side(robot, straight, 2.0, Manoeuvre(1, -1, returning=True)) == 0  # back along its path: over ...
    assert signals.side(robot, path, 3.0, Manoeuvre(1, -1, returning=True)) == 1  # ... then turns are signalled again
    old = TurnSignals(CueParams(turn_signal_rule="path_turn"))
    assert old.side(robot, path, 0.0, Manoeuvre(1, -1)) == 1  # HAVEN's rule: the path's turn
    with pytest.raises(ValueError, match="turn_signal_rule must be one of pass_side, path_turn"):
        CueParams(turn_signal_rule="driver")
