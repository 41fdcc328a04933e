"""An aerial robot in the simulator core: take-off before it moves, landing and charging on its pad,
flying over low furniture but not through walls or tall obstacles, hover drain only in the air,
the map it plans on, its height on /odom and TF, and its distance from people in the navigator."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest
from helpers import box_world

from haven_sim.common import topics
from haven_sim.common.events import EventKind
from haven_sim.common.geometry import Pose2D, Twist2D
from haven_sim.nav.follower import FollowerParams, PathFollower
from haven_sim.nav.motion_style import MotionStyle
from haven_sim.nav.navigator import Navigator
from haven_sim.nav.navigator_params import WAIT_MARGIN_M, NavigatorParams
from haven_sim.nav.planner import PlannerParams
from haven_sim.robots.fields import DEFAULT, with_robot
from haven_sim.robots.robot_kind import resolve_robot
from haven_sim.sim.battery import BatteryParams
from haven_sim.sim.flight import FlightPhase
from haven_sim.sim.simulation import SimConfig, Simulation
from haven_sim.sim.simulator import SimulatorComponent, SimulatorConfig
from haven_sim.sim.world import WorldError
from haven_sim.sim.world_file import parse_world

DRONE = resolve_robot(str(Path(__file__).parent / "data" / "quadrotor.yaml"))
CRUISE = DRONE.flight.cruise_height_m if DRONE.flight else 0.0
CLIMB_S = CRUISE / (DRONE.flight.climb_rate_mps if DRONE.flight else 1.0)
LOW_TABLE = {"polygon": [[4.0, 3.0], [5.0, 3.0], [5.0, 7.0], [4.0, 7.0]], "height": 0.75}
TALL_SHELF = {"polygon": [[4.0, 3.0], [5.0, 3.0], [5.0, 7.0], [4.0, 7.0]], "height": 1.8}
PILLAR = {"polygon": [[4.0, 3.0], [5.0, 3.0], [5.0, 7.0], [4.0, 7.0]]}  # no height: to the ceiling


def sim_for(world, robot=DRONE, **battery):
    config = with_robot(SimConfig(), robot)
    if battery:
        config = replace(config, battery=replace(config.battery, **battery))
    return Simulation(world, config)


def fly(sim, cmd, seconds):
    for _ in range(round(seconds / sim.config.step_s)):
        if cmd is not None:
            sim.command_robot(cmd)
        sim.step()


def kinds(sim):
    return [e.kind for e in sim.pop_events()]


def room(*obstacles, base=True):
    extra = {"obstacles": list(obstacles), "robot": {"start": [2.0, 5.0, 0.0]}}
    if base:
        extra["charging_base"] = {"position": [2.0, 5.0], "radius": 0.5}
    return box_world(10.0, **extra)


def test_takes_off_before_it_moves_sideways():
    sim = sim_for(room())
    fly(sim, Twist2D(0.5, 0.0, 0.0), 1.0)
    assert kinds(sim) == [EventKind.TOOK_OFF]
    assert sim.altitude.phase is FlightPhase.CLIMBING
    assert sim.altitude.altitude_m == pytest.approx(0.5, abs=0.02)  # climb_rate 0.5 m/s
    assert sim.robot_pose().x == pytest.approx(2.0, abs=1e-6)  # held on the pad while it climbs
    fly(sim, Twist2D(0.5, 0.0, 0.0), CLIMB_S)
    assert sim.altitude.phase is FlightPhase.CRUISING and sim.altitude.altitude_m == pytest.approx(CRUISE)
    assert sim.robot_pose().x > 2.3  # cruising: it moves


def test_starts_on_its_pad_and_a_ground_robot_where_the_world_says():
    world = box_world(10.0, charging_base={"position": [1.0, 1.0], "radius": 0.5}, robot={"start": [3.0, 4.0, 1.0]})
    assert sim_for(world).robot_pose() == Pose2D(1.0, 1.0, 1.0)
    assert sim_for(world, DEFAULT).robot_pose() == Pose2D(3.0, 4.0, 1.0)


def test_lands_when_stopped_on_its_pad_and_charges_only_landed():
    sim = sim_for(room(), initial_level=0.5)
    fly(sim, Twist2D(0.0, 0.0, 0.2), CLIMB_S + 0.2)  # up, turning on the spot
    kinds(sim)
    level = sim.battery.level
    fly(sim, None, 0.9)  # stopped, still in the air: no charge, the hover drains
    assert sim.altitude.phase is FlightPhase.CRUISING and sim.battery.level < level
    fly(sim, None, CLIMB_S + 1.0)  # (the command goes stale after 0.5 s, then 1 s stopped, then down)
    assert kinds(sim) == [EventKind.LANDED]
    assert sim.altitude.altitude_m == 0.0
    level = sim.battery.level
    fly(sim, None, 2.0)
    assert sim.battery.level > level + 0.05  # charging at 0.05 a second


def test_stopped_off_its_pad_it_hovers_and_does_not_charge():
    sim = sim_for(room(), initial_level=0.5)
    fly(sim, Twist2D(0.5, 0.0, 0.0), CLIMB_S + 3.0)  # up and 1.5 m away from the pad
    level = sim.battery.level
    fly(sim, None, 5.0)
    assert sim.altitude.phase is FlightPhase.CRUISING and sim.altitude.altitude_m == pytest.approx(CRUISE)
    assert EventKind.LANDED not in kinds(sim)
    assert sim.battery.level < level


def test_hover_drains_only_in_the_air_and_a_ground_robot_idles_as_before():
    drain = DRONE.battery.idle_drain_per_s
    sim = sim_for(room(base=False))
    fly(sim, None, 10.0)  # landed on its start: switched off
    assert sim.battery.level == 1.0
    fly(sim, Twist2D(0.0, 0.0, 0.0001), CLIMB_S)
    fly(sim, None, 0.9)  # in the air, not moving
    assert 1.0 - sim.battery.level == pytest.approx(drain * (CLIMB_S + 0.9), rel=0.05)
    ground = sim_for(room(base=False), DEFAULT, idle_drain_per_s=drain)
    fly(ground, None, 10.0)
    assert 1.0 - ground.battery.level == pytest.approx(drain * 10.0, rel=1e-3)


@pytest.mark.parametrize(("obstacle", "passes"), [(LOW_TABLE, True), (TALL_SHELF, False), (PILLAR, False)])
def test_flies_over_a_low_table_but_not_a_tall_obstacle(obstacle, passes):
    sim = sim_for(room(obstacle))
    fly(sim, Twist2D(0.5, 0.0, 0.0), CLIMB_S + 8.0)
    x = sim.robot_pose().x
    assert (x > 5.5) is passes, x
    assert ("wall" in [e.data.get("other") for e in sim.pop_events()]) is not passes
    if not passes:
        assert x < 4.0 - DRONE.radius_m + 0.05  # stopped at its face, never through


def test_a_ground_robot_stops_at_the_low_table():
    sim = sim_for(room(LOW_TABLE), DEFAULT)
    fly(sim, Twist2D(0.5, 0.0, 0.0), 8.0)
    assert sim.robot_pose().x < 4.0 - DEFAULT.radius_m + 0.05


def test_stops_at_a_wall_in_flight():
    sim = sim_for(room())
    fly(sim, Twist2D(0.0, 0.5, 0.0), CLIMB_S + 14.0)  # sideways, north, into the wall at y = 10
    assert sim.robot_pose().y == pytest.approx(10.0 - 0.05 - DRONE.radius_m, abs=0.05)


def test_the_drone_s_scan_and_map_leave_out_the_low_table_only():
    world = room(LOW_TABLE)
    drone, ground = sim_for(world), sim_for(world, DEFAULT)
    for sim, expect in ((drone, False), (ground, True)):
        grid = sim.occupancy()
        assert grid.is_occupied(4.5, 5.0) is expect  # the table's middle
        assert grid.is_occupied(10.0, 5.0)  # the east wall, for both
    ahead = int(DRONE.lidar.beams / 2)  # the beam along +x (angle_min is -pi)
    assert drone.scan()[ahead] > 3.4 and ground.scan()[ahead] == pytest.approx(2.0, abs=0.05)  # the table 2 m ahead


def test_altitude_goes_out_on_odom_and_tf():
    config = with_robot(SimulatorConfig(), DRONE)
    sim = SimulatorComponent(room(), config)
    sim.sim.command_robot(Twist2D(0.5, 0.0, 0.0))
    for _ in range(50):
        sim.advance()
    out = {m.topic: m.data for m in sim.sense()}
    assert out[topics.ODOM].altitude_m == pytest.approx(0.5, abs=0.02)
    frame = next(f for f in out[topics.TF] if f.child == config.base_frame)
    assert frame.z == out[topics.ODOM].altitude_m


def test_obstacle_heights_in_world_files():
    world = room(LOW_TABLE, PILLAR)
    assert [o.height_m for o in world.obstacles] == [0.75, None]
    assert [len(world.solid_shapes(below=1.2)), len(world.solid_shapes())] == [5, 6]
    bad = {"name": "x", "walls": [{"segment": [[0, 0], [4, 0]], "thickness": 0.1}], "robot": {"start": [1, 1]}}
    with pytest.raises(WorldError, match=r"obstacles\[0\]\.height.*positive"):
        parse_world({**bad, "obstacles": [{**LOW_TABLE, "height": -1}]}, "w.yaml")
    with pytest.raises(WorldError, match=r"walls\[0\].*height"):
        parse_world({**bad, "walls": [{"segment": [[0, 0], [4, 0]], "thickness": 0.1, "height": 1.0}]}, "w.yaml")


def test_the_drone_passes_people_at_its_person_distance():
    ground, drone = NavigatorParams(), with_robot(NavigatorParams(), DRONE)
    assert (ground.pass_gap_m, ground.min_pass_gap_m) == (ground.pass_clearance_m, ground.min_pass_clearance_m)
    assert drone.pass_gap_m == drone.min_pass_gap_m == 0.5
    assert drone.path_gap_m == ground.path_gap_m == ground.path_clearance_m


def test_a_drone_brakes_where_it_may_still_replan_round_the_person_it_waits_for():
    # Braking at wait_gap_m (1.2 m), nearer than the arm's length it keeps (its radius, a person's,
    # 0.5 m), a drone could neither pass nor re-plan: it waited for ever (shared_room, blocker).
    grid = sim_for(room(), DEFAULT).occupancy()
    ground = NavigatorParams()
    drone = Navigator(grid, with_robot(PlannerParams(), DRONE), params=with_robot(NavigatorParams(), DRONE))
    assert ground.wait_distance_m == ground.wait_gap_m
    assert drone.params.wait_distance_m == pytest.approx(drone._need(drone.params.pass_gap_m) + WAIT_MARGIN_M)
    assert drone.params.wait_distance_m > drone.params.wait_gap_m


def test_a_holonomic_robot_corrects_sideways_and_a_diff_drive_does_not():
    path = [Pose2D(0.0, 1.0, 0.0), Pose2D(5.0, 1.0, 0.0)]  # the robot is 1 m to the right of it
    for robot, sideways in ((DRONE, True), (DEFAULT, False)):
        follower = PathFollower(with_robot(FollowerParams(), robot), with_robot(MotionStyle(), robot))
        follower.set_path(path)
        cmd = follower.command(Pose2D(0.0, 0.0, 0.0))
        assert (cmd.vy > 0.1) is sideways, (robot.name, cmd)
        assert (cmd.vx > 0.1) is sideways  # the diff drive turns toward the path first


def test_a_ground_robot_ignores_heights_and_has_no_flight():
    sim = sim_for(room(LOW_TABLE), DEFAULT, initial_level=0.5)
    fly(sim, None, 1.0)
    assert sim.altitude.altitude_m == 0.0 and sim.battery.level > 0.5  # charges on the base as before
    assert BatteryParams().idle_drain_per_s == DEFAULT.battery.idle_drain_per_s


def test_the_people_plan_round_the_furniture_the_drone_flies_over() -> None:
    from haven_sim.sim.flight import clear_height
    from haven_sim.sim.occupancy import on_the_floor, rasterise
    from haven_sim.sim.world_file import load_world

    world = load_world(
        Path(__file__).resolve().parents[2] / "haven_scenarios" / "haven_scenarios" / "worlds" / "shared_room.yaml"
    )
    below = clear_height(resolve_robot("quadrotor"))
    table = (6.3, 2.4)  # the middle of a 0.75 m table
    drone_map = rasterise(world, below=below)
    assert not drone_map.is_occupied(*table)
    floor = on_the_floor(drone_map, world, below)
    assert floor.is_occupied(*table) and (floor.data == rasterise(world).data).all()
    ground = rasterise(world)
    # a ground robot's map is the people's
    assert clear_height(DEFAULT) is None and on_the_floor(ground, world, None) is ground
