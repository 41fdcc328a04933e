"""Session bags: written with our writer, read back by an independent reader (mcap) and by ours."""

import pytest
from mcap.reader import make_reader
from rclpy.serialization import serialize_message
from std_msgs.msg import String

from haven_scenarios.record.bag import BagWriter, not_recorded, read_messages, to_wall_time
from haven_sim.common import topics
from haven_sim.common.events import EventKind, Source, event
from haven_sim.common.geometry import Pose2D, Twist2D
from haven_sim.common.state import RobotState
from haven_sim.nodes import conversions as conv

pytestmark = pytest.mark.integration


def test_write_then_read_back(tmp_path):
    bag = tmp_path / "bag"
    odom = [RobotState(Pose2D(0.1 * i, 0.0, 0.2), Twist2D(0.5, 0, 0.1)) for i in range(5)]
    e = event(EventKind.TRIAL_START, 0.0, Source.SCENARIO, scenario="s")
    with BagWriter(bag) as w:
        assert w.add_topic("/odom", "nav_msgs/msg/Odometry") and w.add_topic("/haven/events", "std_msgs/msg/String")
        assert not w.add_topic("/x", "no_msgs/msg/Nothing")  # unknown types are refused, not written
        for i, s in enumerate(odom):
            w.write("/odom", i * 20_000_000, bytes(serialize_message(conv.odometry_msg(i * 0.02, s))))
        w.write("/haven/events", 0, bytes(serialize_message(conv.event_msg(e))))
        w.write("/haven/events", 1, bytes(serialize_message(String(data="not an event"))))
    assert (bag / "metadata.yaml").exists() and w.counts == {"/odom": 5, "/haven/events": 2}
    assert not_recorded(bag) == {"/x": "no_msgs/msg/Nothing: package no_msgs is not installed here"}
    with open(next(bag.glob("*.mcap")), "rb") as f:
        seen = [(c.topic, m.log_time) for _, c, m in make_reader(f).iter_messages()]
    assert sorted(seen) == sorted(
        [("/haven/events", 0), ("/haven/events", 1)] + [("/odom", i * 20_000_000) for i in range(5)]
    )
    back = list(read_messages(bag))
    assert [m.data for m in back if m.topic == topics.EVENTS] == [e]  # the bad string is skipped
    assert [round(m.data.pose.x, 9) for m in back if m.topic == topics.ODOM] == [round(s.pose.x, 9) for s in odom]


def test_offered_qos_is_recorded_for_replay(tmp_path):
    """`ros2 bag play` republishes with the recorded offered QoS: latched topics must stay latched."""
    from rosbags.highlevel import AnyReader

    from haven_scenarios.nodes.recorder import bag_qos
    from haven_scenarios.record.bag import TYPESTORE
    from haven_sim.nodes import qos

    bag = tmp_path / "bag"
    with BagWriter(bag) as w:
        w.add_topic("/tf_static", "std_msgs/msg/String", [bag_qos(qos.LATCHED)])
        w.add_topic("/odom", "nav_msgs/msg/Odometry", [bag_qos(qos.RELIABLE)])
        w.write("/tf_static", 0, bytes(serialize_message(String(data="x"))))
    with AnyReader([bag], default_typestore=TYPESTORE) as reader:
        offered = {c.topic: c.ext.offered_qos_profiles for c in reader.connections}
    assert [q.durability.name for q in offered["/tf_static"]] == ["TRANSIENT_LOCAL"]
    assert [q.reliability.name for q in offered["/odom"]] == ["RELIABLE"]
    assert "durability: transient_local" in (bag / "metadata.yaml").read_text()


def test_sim_time_converts_to_the_wall_clock_between_and_beyond_the_recorders_pairs():
    pairs = [(10_000_000_000, 1_700_000_000_000_000_000), (20_000_000_000, 1_700_000_002_000_000_000)]  # 5x real time
    assert to_wall_time(pairs, 15.0) == pytest.approx(1_700_000_001.0)
    assert to_wall_time(pairs, 25.0) == pytest.approx(1_700_000_003.0)  # beyond: at the nearest pace
    assert to_wall_time(pairs, 5.0) == pytest.approx(1_699_999_999.0)
    assert to_wall_time([], 5.0) is None


def test_hostile_messages_recorded_from_other_nodes_are_skipped_when_read(tmp_path):
    """A bag holds what was on the wire, a hostile node's messages too: the reader (and so the
    metrics) skips every one the live nodes would have refused, and reads the rest."""
    from hostile import hostile_messages
    from nav_msgs.msg import Odometry
    from sensor_msgs.msg import BatteryState

    from haven_sim.nodes.wire import type_name

    good = conv.odometry_msg(0.0, RobotState(Pose2D(1.0, 2.0, 0.3), Twist2D(0.2, 0, 0)))
    bag = tmp_path / "bag"
    written = 0
    with BagWriter(bag) as w:
        for topic, msg_type in (
            ("/odom", Odometry),
            ("/battery_state", BatteryState),
            ("/haven/events", String),
            ("/haven/cue_state", String),
        ):
            w.add_topic(topic, type_name(msg_type))
            for _, msg in hostile_messages(type_name(msg_type)):
                w.write(topic, written, bytes(serialize_message(msg)))
                written += 1
        w.write("/odom", written, bytes(serialize_message(good)))
    back = list(read_messages(bag))
    for m in back:
        if m.topic == topics.ODOM:
            assert abs(m.data.pose.x) <= 1e6 and abs(m.data.pose.y) <= 1e6
        if m.topic == topics.BATTERY:
            assert 0.0 <= m.data.level <= 1.0
    assert [m.data.pose.x for m in back if m.topic == topics.ODOM and m.data.pose == (1.0, 2.0, 0.3)] == [1.0]
    assert not [m for m in back if m.topic in (topics.EVENTS, topics.CUE_STATE)]  # none of the strings is one
