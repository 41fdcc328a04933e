"""Core types <-> ROS messages, round trip (no processes: the message classes only)."""

import math

import numpy as np
import pytest

from haven_sim.common.events import EventError, EventKind, Source, event
from haven_sim.common.geometry import Pose2D, Twist2D
from haven_sim.common.state import Goal, RobotState
from haven_sim.nodes import conversions as conv
from haven_sim.sim.battery import BatteryReading, PowerStatus
from haven_sim.sim.occupancy import rasterise
from haven_sim.sim.world import packaged_world
from haven_sim.sim.world_file import load_world

pytestmark = pytest.mark.integration


def close(a, b):
    return a.distance_to(b) < 1e-12 and abs(math.remainder(a.yaw - b.yaw, 2 * math.pi)) < 1e-12


def test_poses_twists_odometry_goals_and_paths():
    p = Pose2D(1.5, -2.25, 2.5)
    assert close(conv.pose_from_msg(conv.pose_msg(p)), p)
    nan = conv.pose_from_msg(conv.pose_msg(Pose2D(1, 2, math.nan)))
    assert math.isnan(nan.yaw)  # "any heading" survives as the all-zero quaternion
    t = Twist2D(0.3, -0.1, 0.7)
    assert conv.twist_from_msg(conv.twist_msg(t)) == t
    state = conv.odometry_from_msg(conv.odometry_msg(3.0, RobotState(p, t)))
    assert close(state.pose, p) and state.twist == t
    goal = conv.goal_from_msg(conv.goal_msg(1.0, Goal(p, "odom")))
    assert close(goal.pose, p) and goal.frame == "odom"
    path = [Pose2D(0, 0, 0), Pose2D(0, 0, 1.0), Pose2D(1, 1, 1.0)]
    assert all(close(a, b) for a, b in zip(conv.path_from_msg(conv.path_msg(2.0, path)), path))


def test_time_stamps_humans_and_events():
    assert conv.time_from_msg(conv.time_msg(12.345678901)) == pytest.approx(12.345678901, abs=1e-9)
    d = conv.duration_msg(2.5)
    assert (d.sec, d.nanosec) == (2, 500_000_000) and conv.duration_msg(-1.0).sec == 0  # (a Nav2 feedback's times)
    humans = {"ann": Pose2D(1, 2, 0.5), "bob": Pose2D(3, 4, -1.0)}
    back = conv.humans_from_msg(conv.humans_msg(1.0, humans), ["ann", "bob"])
    assert list(back) == ["ann", "bob"] and all(close(back[k], humans[k]) for k in humans)
    assert list(conv.humans_from_msg(conv.humans_msg(1.0, humans))) == ["h0", "h1"]  # ids unknown: by index
    e = event(EventKind.GEM_COLLECTED, 5.0, Source.SCENARIO, gem="g1", by="h1")
    assert conv.event_from_msg(conv.event_msg(e)) == e
    with pytest.raises(EventError):
        conv.event_from_msg(type(conv.event_msg(e))(data="{"))


def test_battery_and_map():
    r = BatteryReading(0.25, PowerStatus.CHARGING, 14.1, 0.55, 2.2, 25.0)
    back = conv.battery_from_msg(conv.battery_msg(1.0, r))
    assert back.level == pytest.approx(0.25) and back.status is PowerStatus.CHARGING
    grid = rasterise(load_world(packaged_world("small_test")))
    g = conv.occupancy_from_msg(conv.occupancy_msg(0.0, grid))
    assert (g.width, g.height, g.origin_x, g.origin_y) == (grid.width, grid.height, grid.origin_x, grid.origin_y)
    assert np.array_equal(g.data, grid.data) and g.resolution_m == pytest.approx(grid.resolution_m)
