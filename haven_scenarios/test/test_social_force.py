"""The social-force model of the simulated people: toward their goal, round the robot and each
other, keeping right, along walls, never closing in on the robot."""

import math

import numpy as np

from haven_scenarios.study.participant_kind import make_walker
from haven_scenarios.study.participants import HUMAN_PLANNER, Stop
from haven_scenarios.study.perception import Sight, perceive
from haven_scenarios.study.social_force import Body, SocialForce, robot_body
from haven_sim.common.bodies import HUMAN_BODY
from haven_sim.nav.planner import GridPlanner
from haven_sim.robots.fields import DEFAULT as ROBOT_BODY
from haven_sim.sim.occupancy import rasterise
from haven_sim.sim.simulation import Simulation
from haven_sim.sim.world_file import parse_world

HALL = {  # a 2 m wide, 12 m long hallway along x (HAVEN's hallway width)
    "name": "hall",
    "walls": [
        {"segment": s, "thickness": 0.1}
        for s in ([[0, 0], [12, 0]], [[12, 0], [12, 2]], [[12, 2], [0, 2]], [[0, 2], [0, 0]])
    ],
    "robot": {"start": [6.0, 1.0, math.pi]},
    "humans": [{"id": "h1", "start": [1.0, 1.0, 0.0]}],
}


def open_space(start, direction, max_m=10.0):
    """No wall anywhere: a `RayFn` (one direction, or an (N, 2) array of them)."""
    return np.full(np.shape(direction)[:-1], max_m) if isinstance(direction, np.ndarray) else max_m


def glide(force, start, desired, others_at, seconds, dt=0.1):
    """Integrate a person's position kinematically; `others_at(t)` gives the bodies around."""
    x, y = start
    track = []
    for k in range(int(seconds / dt)):
        vx, vy = force.step((x, y), desired, others_at(k * dt), dt)
        x, y = x + vx * dt, y + vy * dt
        track.append((x, y))
    return track


def test_free_walker_reaches_its_desired_speed():
    track = glide(SocialForce(open_space), (0.0, 0.0), (1.0, 0.0), lambda t: [], 4.0)
    assert abs(track[-1][0] - track[-2][0] - 0.1) < 1e-3 and abs(track[-1][1]) < 1e-9


def test_keeps_right_of_an_oncoming_robot_and_never_closes_in_on_it():
    def robot(t):
        return [robot_body(6.0 - 0.4 * t, 0.0, -0.4, 0.0, ROBOT_BODY.radius_m)]

    track = glide(SocialForce(open_space), (0.0, 0.0), (1.0, 0.0), robot, 8.0)
    robot_x = [6.0 - 0.4 * (k + 1) * 0.1 for k in range(len(track))]
    passing = [y for (x, y), rx in zip(track, robot_x, strict=True) if abs(x - rx) < 0.5]
    assert passing and max(passing) < -0.3  # to the walker's right (heading +x: right is -y)
    gaps = [math.hypot(x - rx, y) for (x, y), rx in zip(track, robot_x, strict=True)]
    assert min(gaps) > ROBOT_BODY.radius_m + HUMAN_BODY.radius_m + 0.1


def test_walking_straight_at_a_standing_robot_stops_short_of_it():
    force = SocialForce(open_space)
    track = glide(force, (0.0, 0.0), (1.0, 0.0), lambda t: [robot_body(3.0, 0.0, 0.0, 0.0, ROBOT_BODY.radius_m)], 10.0)
    gap = min(math.hypot(x - 3.0, y) for x, y in track) - ROBOT_BODY.radius_m - HUMAN_BODY.radius_m
    assert gap >= force.p.personal_m - 0.05


def test_two_people_pass_each_other():
    a, b = SocialForce(open_space), SocialForce(open_space)
    pa, pb = (0.0, 0.0), (6.0, 0.05)
    closest = math.inf
    for _ in range(80):
        va = a.step(pa, (1.0, 0.0), [Body(pb[0], pb[1], b.v[0], b.v[1], HUMAN_BODY.radius_m)], 0.1)
        vb = b.step(pb, (-1.0, 0.0), [Body(pa[0], pa[1], a.v[0], a.v[1], HUMAN_BODY.radius_m)], 0.1)
        pa, pb = (pa[0] + va[0] * 0.1, pa[1] + va[1] * 0.1), (pb[0] + vb[0] * 0.1, pb[1] + vb[1] * 0.1)
        closest = min(closest, math.hypot(pa[0] - pb[0], pa[1] - pb[1]))
    assert pa[0] > 6.0 and pb[0] < 0.0
    assert closest > 2 * HUMAN_BODY.radius_m


def test_a_walker_passes_a_robot_standing_in_a_hallway_without_touching_it():
    world = parse_world(HALL)
    sim = Simulation(world)
    planner = GridPlanner(rasterise(world), HUMAN_PLANNER)
    person = make_walker("walker", "h1", [Stop(11.0, 1.0)], planner, 1.0, seed=1)
    sight = Sight(rasterise(world))
    closest = math.inf
    for k in range(30 * 50):
        if k % 5 == 0:
            me, robot = sim.human_poses()["h1"], sim.robot_pose()
            sim.command_human(
                "h1", person.command(sim.time, me, robot, perceive(person.params, sight, sim.time, me, robot, None))
            )
        sim.step()
        closest = min(closest, sim.human_poses()["h1"].distance_to((6.0, 1.0)))
        if person.done:
            break
    assert person.done
    assert closest > ROBOT_BODY.radius_m + HUMAN_BODY.radius_m + 0.1
    assert sim.robot_pose().distance_to((6.0, 1.0)) < 0.01  # nobody pushed the robot


def test_walls_push_and_a_walk_into_a_wall_slides_along_it():
    world = parse_world(HALL)
    planner = GridPlanner(rasterise(world), HUMAN_PLANNER)
    force = SocialForce(planner.free_run)
    track = glide(force, (2.0, 1.5), (1.0, 1.0), lambda t: [], 3.0)  # aimed 45 deg into the y = 2 wall
    assert max(y for _, y in track) < 2.0 - 0.05 - HUMAN_BODY.radius_m + 0.03
    assert track[-1][0] > 3.5  # still moving along the wall
