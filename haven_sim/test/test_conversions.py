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
    assert all(close(a, b) for a, b in zip(conv.path_from_msg(conv.path_msg(2.0, path)), path, strict=True))


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


def test_the_shared_decoder_reads_rclpy_and_rosbags_messages_alike_with_sensor_msgs_own_status_codes():
    from rclpy.serialization import serialize_message
    from rosbags.typesys import Stores, get_typestore
    from sensor_msgs.msg import BatteryState

    from haven_sim.runtime import decode

    assert decode.BATTERY_STATUS == {
        PowerStatus.CHARGING: BatteryState.POWER_SUPPLY_STATUS_CHARGING,
        PowerStatus.DISCHARGING: BatteryState.POWER_SUPPLY_STATUS_DISCHARGING,
        PowerStatus.FULL: BatteryState.POWER_SUPPLY_STATUS_FULL,
    }
    store = get_typestore(Stores.ROS2_JAZZY)
    for msg in (conv.battery_msg(2.0, BatteryReading(0.5, PowerStatus.CHARGING, 12.0, 2.0, 4.0, math.nan)),
                conv.odometry_msg(2.0, RobotState(Pose2D(1.0, 2.0, 0.5), Twist2D(0.3, 0.0, 0.1))),
                conv.goal_msg(2.0, Goal(Pose2D(3.0, 4.0, 1.0), "map"))):  # fmt: skip
        name = type(msg).__module__.split(".")[0] + "/msg/" + type(msg).__name__
        bag_msg = store.deserialize_cdr(serialize_message(msg), name)  # (what the bag reader gets)
        read = {
            BatteryState: decode.battery_from_msg,
            conv.Odometry: decode.odometry_from_msg,
            conv.PoseStamped: decode.goal_from_msg,
        }[type(msg)]
        assert read(bag_msg) == read(msg) and decode.stamp_of(bag_msg) == decode.stamp_of(msg) == 2.0
