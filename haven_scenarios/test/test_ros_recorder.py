"""The recorder on its own: what it cannot keep is never lost silently. A recorder frozen while a
publisher floods /haven/events through a shallow queue must say how many messages it lost, and the
session must be flagged (the metrics read the events)."""

import os
import signal

import pytest
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import String

from haven_scenarios.record.bag import lost_messages, read_recording
from haven_scenarios.record.validity import check
from haven_sim.common.events import EventKind, event

pytestmark = pytest.mark.ros

# The suite's event publishers, with a depth of 10 instead of 100.
SHALLOW = QoSProfile(
    depth=10,
    history=HistoryPolicy.KEEP_LAST,
    reliability=ReliabilityPolicy.RELIABLE,
    durability=DurabilityPolicy.TRANSIENT_LOCAL,
)


def test_messages_the_recorder_could_not_read_are_counted_and_flag_the_session(ros, tmp_path):
    rec = ros.start("haven_scenarios.nodes.recorder", {"session_dir": str(tmp_path)})
    pub = ros.node.create_publisher(String, "haven/events", SHALLOW)
    ros.wait_matched(pub, timeout_s=30)  # the recorder found the topic and subscribed

    def publish(i: int, note: str = "") -> None:
        pub.publish(String(data=event(EventKind.DWELL_STARTED, 0.01 * i, "flooder", note=note).to_json()))

    for i in range(20):
        publish(i)
    ros.spin_for(0.5)
    os.kill(rec.pid, signal.SIGSTOP)  # a recorder that falls far behind, as on a starved machine
    big = "x" * 10_000  # 30 MB in all: far beyond what transport buffers hold for a frozen reader
    try:
        for i in range(3000):
            publish(20 + i, big)
    finally:
        os.kill(rec.pid, signal.SIGCONT)
    for i in range(20):  # the stream goes on: a later message shows the reader what it missed
        publish(3020 + i)
        ros.spin_for(0.05)
    ros.spin_for(2.0)
    assert ros.stop(rec) == 0
    lost = lost_messages(tmp_path / "bag")
    assert lost.get("/haven/events", 0) > 0, lost
    recording, note = read_recording(tmp_path / "bag")
    assert note == "" and recording.lost == lost
    assert len(recording.events) < 3040 and recording.events[-1].stamp == pytest.approx(30.39)  # the last "after"
    reasons = check(recording, None)["invalid_reasons"]
    assert f"/haven/events: {lost['/haven/events']} message(s) lost before the recorder read them" in reasons


def test_the_recorder_reads_a_stream_messages_stamp_without_decoding_it():
    from geometry_msgs.msg import PoseArray
    from nav_msgs.msg import Odometry
    from rclpy.serialization import serialize_message

    from haven_scenarios.nodes.recorder import header_stamp

    for msg in (Odometry(), PoseArray()):
        msg.header.stamp.sec, msg.header.stamp.nanosec = 12, 340_000_000
        assert header_stamp(bytes(serialize_message(msg))) == pytest.approx(12.34)
