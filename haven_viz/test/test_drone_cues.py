"""The drone's intent cues (Walker et al. 2018: NavPoints, Arrow, Gaze), on plain data: drawn at the
robot's altitude, only for an aerial robot, switched by the condition like HAVEN's."""

import math

import pytest

from haven_sim.common.geometry import Pose2D
from haven_sim.common.state import RobotState
from haven_sim.robots.fields import DEFAULT
from haven_sim.robots.robot_kind import resolve_robot
from haven_viz.cue_kind import TrackedPath, accept_plugin
from haven_viz.cues import CUES, PATH_NS, ArCues, CueParams, CueState, Toggles, cues_for
from haven_viz.drone_cues import ARROW_NS, GAZE_NS, NAV_NS, corners, waypoints
from haven_viz.markers import Shape
from haven_viz.viz import VizComponent, VizConfig

pytestmark = pytest.mark.unit

DRONE = resolve_robot("quadrotor")
CRUISE_Z = DRONE.flight.cruise_height_m if DRONE.flight else 0.0
STRAIGHT = [Pose2D(x * 0.5, 0.0, 0.0) for x in range(9)]  # 4 m along x
# 2 m, left, 2 m
TURNING = [Pose2D(x * 0.5, 0.0, 0.0) for x in range(5)] + [Pose2D(2.0, y * 0.5, math.pi / 2) for y in range(1, 5)]
DRONE_CUES = (NAV_NS, ARROW_NS, GAZE_NS)


def of(markers, ns, shape=None):
    return [m for m in markers if m.ns == ns and (shape is None or m.shape is shape)]


def flat(points):
    return [v for p in points for v in p]


def drone(path, altitude=CRUISE_Z):
    cues = ArCues(robot=DRONE)
    cues.set_path(path)
    return cues, altitude


def test_the_drone_cues_are_registered_for_aerial_robots_only():
    assert set(DRONE_CUES) <= set(CUES)
    assert set(DRONE_CUES) <= set(cues_for(DRONE.kinematics))
    assert not set(DRONE_CUES) & set(cues_for(DEFAULT.kinematics))
    assert set(cues_for("omni")) == set(cues_for("diff_drive"))  # HAVEN's four serve every kind


@pytest.mark.parametrize("path", [STRAIGHT, TURNING], ids=["straight", "turning"])
def test_navpoints_are_the_next_waypoints_at_flight_height_with_countdowns(path):
    cues, z = drone(path)
    frame = cues.frame(Pose2D(0.0, 0.0, 0.0), toggles=Toggles(), altitude_m=z)
    spheres, texts = of(frame.markers, NAV_NS, Shape.SPHERE), of(frame.markers, NAV_NS, Shape.TEXT_VIEW_FACING)
    n = CueParams().nav_points_ahead
    assert len(spheres) == len(texts) == n == frame.state.value(NAV_NS)
    assert all(m.position[2] == pytest.approx(CRUISE_Z) for m in spheres)
    # Every metre along the path: on a turning path the third is on the second leg.
    assert flat(m.position[:2] for m in spheres) == pytest.approx(
        flat(cues.path.line.point_at(s) for s in (1.0, 2.0, 3.0))
    )
    if path is TURNING:
        assert spheres[2].position[:2] == pytest.approx((2.0, 1.0))
    etas = [float(t.text.split()[0]) for t in texts]
    assert etas == pytest.approx([round(s / DRONE.motion.cruise_speed_mps) for s in (1.0, 2.0, 3.0)])
    line = of(frame.markers, NAV_NS, Shape.LINE_STRIP)[0]
    assert line.points[0][:2] == (0.0, 0.0) and all(p[2] == pytest.approx(CRUISE_Z) for p in line.points)
    assert frame.ways[NAV_NS] == (tuple(m.position[:2] for m in spheres), False)  # seen where they are


def test_a_corner_is_a_waypoint_and_grid_wiggle_is_not():
    # 2.3 m along x (with 1 cm cell wiggle), then 2 m along y.
    poses = [Pose2D(0.05 * i, 0.01 * (i % 2), 0.0) for i in range(47)] + [
        Pose2D(2.3, 0.05 * j, math.pi / 2) for j in range(1, 41)
    ]
    path = TrackedPath(poses, CueParams().marker_spacing_m)
    (corner,) = corners(path)
    assert path.line.point_at(corner) == pytest.approx((2.3, 0.0), abs=0.011)
    stations = [s for _, _, s in waypoints(path, CueParams())]
    # 2.0 gives way to the corner (0.35 m along)
    assert stations == pytest.approx([1.0, corner, 3.0, 4.0, path.line.length])


def test_the_countdown_decreases_as_the_drone_advances_and_reached_points_go():
    cues, z = drone(STRAIGHT)
    first = of(cues.frame(Pose2D(0.0, 0.0, 0.0), altitude_m=z).markers, NAV_NS, Shape.TEXT_VIEW_FACING)[0].text
    later = of(cues.frame(Pose2D(0.6, 0.0, 0.0), altitude_m=z).markers, NAV_NS, Shape.TEXT_VIEW_FACING)[0].text
    assert float(later.split()[0]) < float(first.split()[0])
    near_end = cues.frame(Pose2D(3.5, 0.0, 0.0), altitude_m=z)
    assert near_end.state.value(NAV_NS) == 1  # only the path's end is left


@pytest.mark.parametrize("path, target", [(STRAIGHT, (1.0, 0.0)), (TURNING, (2.0, 1.0))], ids=["straight", "turning"])
def test_the_arrow_on_the_drone_points_at_the_next_waypoint(path, target):
    cues, z = drone(path)
    robot = Pose2D(0.0, 0.0, 0.0) if path is STRAIGHT else Pose2D(1.8, 0.0, 0.0)
    frame = cues.frame(robot, altitude_m=z)
    (arrow,) = of(frame.markers, ARROW_NS)
    assert arrow.shape is Shape.ARROW and arrow.position[:2] == (robot.x, robot.y)
    m = DRONE.cues
    # on the drone, clear of signals and gauge
    assert z + m.signal_height_m + 0.05 < arrow.position[2] < z + m.gauge_height_m - 0.05
    assert arrow.yaw == pytest.approx(math.atan2(target[1] - robot.y, target[0] - robot.x))
    (way, on_robot) = frame.ways[ARROW_NS]
    assert flat(way) == pytest.approx(target) and on_robot  # seen with the robot


@pytest.mark.parametrize("path", [STRAIGHT, TURNING], ids=["straight", "turning"])
def test_the_gaze_eye_looks_along_the_path_ahead(path):
    cues, z = drone(path)
    robot = Pose2D(1.5, 0.0, 0.0)
    frame = cues.frame(robot, altitude_m=z)
    ball, pupil = of(frame.markers, GAZE_NS)
    assert (
        ball.shape is pupil.shape is Shape.SPHERE
        and ball.color[:3] == (1.0, 1.0, 1.0)
        and pupil.scale[0] < ball.scale[0]
    )
    look = cues.path.line.point_at(1.5 + CueParams().gaze_lookahead_m)
    direction = math.atan2(look[1] - ball.position[1], look[0] - ball.position[0])
    assert math.atan2(pupil.position[1] - ball.position[1], pupil.position[0] - ball.position[0]) == pytest.approx(
        direction, abs=1e-6
    )
    assert z < ball.position[2] < z + 1.0
    if path is TURNING:  # the eye looks left, round the corner, before the drone turns
        assert direction > 0.3


def test_havens_cues_and_the_projected_path_draw_at_the_drones_altitude():
    cues, z = drone(STRAIGHT, altitude=1.2)
    frame = cues.frame(Pose2D(0.0, 0.0, 0.0), battery_level=0.5, altitude_m=z)
    projected = of(frame.markers, PATH_NS)
    assert projected and all(m.position[2] == pytest.approx(1.2 + CueParams().marker_size_m / 2) for m in projected)
    assert all(m.position[2] > 1.2 for m in frame.markers if m.ns == "battery_indicator")
    ground = ArCues()
    ground.set_path(STRAIGHT)
    assert all(
        m.position[2] == pytest.approx(CueParams().marker_size_m / 2)
        for m in of(ground.frame(Pose2D(0.0, 0.0, 0.0)).markers, PATH_NS)
    )


def test_a_diff_drive_has_no_drone_cues_even_in_condition_all():
    cues = ArCues()
    cues.set_path(TURNING)
    frame = cues.frame(Pose2D(0.0, 0.0, 0.0), toggles=Toggles())
    assert not set(DRONE_CUES) & set(cues.cues) and not any(m.ns in DRONE_CUES for m in frame.markers)
    assert frame.state.cues == cues_for(DEFAULT.kinematics) and not any(frame.state.shown(c) for c in DRONE_CUES)
    published = json_keys(frame.state)
    assert not {"nav_points", "arrow", "gaze"} & set(published)  # /haven/cue_state: HAVEN's values only ...
    assert set(published["toggles"]) == set(frame.state.cues)  # ... and toggles (the console lists these)


def json_keys(state):
    import json

    return json.loads(state.to_json(0.0))


def test_toggling_a_drone_cue_switches_it_alone():
    cues, z = drone(STRAIGHT)
    robot = Pose2D(0.0, 0.0, 0.0)
    only_gaze = cues.frame(robot, toggles=Toggles.none().replaced({"gaze": True}), altitude_m=z)
    assert {m.ns for m in only_gaze.markers} == {GAZE_NS} and set(only_gaze.ways) == {GAZE_NS}
    no_arrow = cues.frame(robot, toggles=Toggles().replaced({"arrow": False}), altitude_m=z)
    assert not of(no_arrow.markers, ARROW_NS) and of(no_arrow.markers, NAV_NS) and not no_arrow.state.shown(ARROW_NS)
    assert cues.frame(robot, toggles=Toggles.none(), altitude_m=z).markers == []


def test_the_cue_state_of_a_drone_goes_through_json():
    cues, z = drone(STRAIGHT)
    state = cues.frame(Pose2D(0.0, 0.0, 0.0), altitude_m=z).state
    assert CueState.from_json(state.to_json(1.0)) == (1.0, state)
    assert state.shown(NAV_NS) and state.shown(ARROW_NS) and state.shown(GAZE_NS)


def test_the_viz_draws_the_drone_cues_at_its_altitude_from_odom():
    viz = VizComponent(VizConfig(description=DRONE))
    viz.on_plan(STRAIGHT, 0.0)
    viz.on_odom(RobotState(Pose2D(0.0, 0.0, 0.0), altitude_m=1.4), 0.0)
    frame = viz.cues.frame(Pose2D(0.0, 0.0, 0.0), altitude_m=viz.altitude_m)
    out = viz.tick(0.1)
    sent = [m for msg in out if msg.topic.endswith("ar_markers") for m in msg.data.upsert]
    assert {m.ns for m in sent} >= {NAV_NS, ARROW_NS, GAZE_NS, PATH_NS}
    assert all(m.position[2] == pytest.approx(1.4 + CueParams().marker_size_m / 2) for m in of(sent, PATH_NS))
    assert frame.state.shown(NAV_NS)


def test_a_cue_names_the_robot_kinds_it_serves():
    class Floor:
        def show(self, ctx, markers):
            return None

    assert accept_plugin("floor", Floor).kinematics == ("diff_drive", "omni", "aerial")

    class Wrong(Floor):
        kinematics = ("hovercraft",)

    with pytest.raises(ValueError, match="kinematics must be a tuple of robot kinds"):
        accept_plugin("wrong", Wrong)
