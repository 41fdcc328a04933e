"""A recorded session played back looks like the live run: a viewer that joins late (RViz with the
shipped config: reliable, transient local) gets /tf_static, /map and the world markers again,
because the bag keeps the QoS each topic was offered with (as `ros2 bag play` reads it too)."""

import os
import signal
import subprocess
import sys

import pytest
from nav_msgs.msg import OccupancyGrid
from rosgraph_msgs.msg import Clock
from visualization_msgs.msg import MarkerArray

from haven_sim.nodes import qos

pytestmark = pytest.mark.ros
HAVEN = [sys.executable, "-m", "haven_scenarios.tools.cli"]


def test_a_replayed_session_relatches_static_tf_the_map_and_the_world(ros, tmp_path):
    tf2 = pytest.importorskip("tf2_msgs.msg", reason="tf2_msgs not built on this machine (scripts/build_interfaces.py)")
    clock = ros.collect(Clock, "/clock", qos.CLOCK)
    live = subprocess.Popen(
        [*HAVEN, "sim", "--record", "--rtf", "2", "--sessions", str(tmp_path), "--domain-id", str(ros.domain_id)],
        env=ros.env,
        start_new_session=True,
    )
    ros.procs.append(live)
    assert ros.spin_until(
        lambda: "recorder" in {i.node_name for i in ros.node.get_subscriptions_info_by_topic("/clock")}, 60
    )
    del clock[:]
    ros.wait_for_messages(clock, 200, timeout_s=60)  # 4 s of sim time recorded, however slowly the suite started
    os.killpg(live.pid, signal.SIGINT)  # Ctrl-C
    assert live.wait(timeout=60) == 0
    (folder,) = tmp_path.iterdir()
    assert (folder / "bag" / "metadata.yaml").is_file() and (folder / "world.yaml").is_file()
    del clock[:]
    player = subprocess.Popen(
        [*HAVEN, "play", str(folder), "--hold", "--domain-id", str(ros.domain_id)], env=ros.env, start_new_session=True
    )
    ros.procs.append(player)
    # playing, past the latched messages at the bag's start: the viewer below joins late
    ros.wait_for_messages(clock, 10, timeout_s=60)
    rviz = qos.LATCHED  # the shipped RViz config's Map, World and TF (static) QoS
    late = {
        topic: ros.collect(t, topic, rviz)
        for topic, t in (("/tf_static", tf2.TFMessage), ("/map", OccupancyGrid), ("/haven/world_markers", MarkerArray))
    }
    for got in late.values():
        ros.wait_for_messages(got, 1, timeout_s=30)
    assert {(t.header.frame_id, t.child_frame_id) for t in late["/tf_static"][0].transforms} >= {
        ("map", "odom"),
        ("base_footprint", "base_link"),
    }
    assert late["/map"][0].info.width > 0 and len(late["/haven/world_markers"][0].markers) > 4


def test_a_message_type_the_recording_library_does_not_know_is_recorded_from_its_installed_package(ros, tmp_path):
    """nav_msgs/msg/Goals (new in Jazzy, not in rosbags' store; a lab's own message is the same case)
    published during `haven sim --record`: in the bag with its definition, readable by rosbags."""
    import json
    import time

    from geometry_msgs.msg import PoseStamped
    from nav_msgs.msg import Goals
    from rosbags.highlevel import AnyReader

    clock = ros.collect(Clock, "/clock", qos.CLOCK)
    goals = ros.node.create_publisher(Goals, "/lab/goals", 10)
    live = subprocess.Popen(
        [*HAVEN, "sim", "--record", "--rtf", "2", "--sessions", str(tmp_path), "--domain-id", str(ros.domain_id)],
        env=ros.env,
        start_new_session=True,
    )
    ros.procs.append(live)
    ros.wait_for_messages(clock, 10, timeout_s=60)
    assert ros.spin_until(lambda: goals.get_subscription_count() > 0, 30)  # the recorder found the topic
    msg = Goals(goals=[PoseStamped(), PoseStamped()])
    msg.goals[1].pose.position.x = 2.5
    for _ in range(3):
        goals.publish(msg)
        time.sleep(0.1)
    ros.spin_for(1.0)
    os.killpg(live.pid, signal.SIGINT)
    assert live.wait(timeout=60) == 0
    (folder,) = tmp_path.iterdir()
    with AnyReader([folder / "bag"]) as reader:
        got = [reader.deserialize(raw, c.msgtype) for c, _, raw in reader.messages() if c.topic == "/lab/goals"]
    assert len(got) == 3 and got[0].goals[1].pose.position.x == 2.5
    assert "not_recorded" not in json.loads((folder / "session.json").read_text())
