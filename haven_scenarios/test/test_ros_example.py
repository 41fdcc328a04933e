"""The docs' "Using your own planner or controller" page (docs/howto/own-planner.md), as a user would do it: `haven sim
--without planner` and the example planner (examples/nodes/nav2_style_planner.py: Nav2's /plan QoS, NavFn-shaped paths)
in its own process; a goal from RViz's QoS. The robot reaches the goal pose, the path projection shows cubes on the arc,
and the plan's QoS is Nav2's. And a recorded study session with that planner in place of ours, in a world of the
user's."""

import json
import math
import subprocess
import sys
from pathlib import Path

import pytest
from geometry_msgs.msg import PoseStamped
from mcap.reader import make_reader
from nav_msgs.msg import Odometry
from rclpy.qos import DurabilityPolicy
from visualization_msgs.msg import Marker, MarkerArray

from haven_sim.common.geometry import Pose2D
from haven_sim.common.state import Goal
from haven_sim.nodes import conversions as conv, qos

pytestmark = pytest.mark.ros
HAVEN = [sys.executable, "-m", "haven_scenarios.tools.cli"]
EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "nodes" / "nav2_style_planner.py"
# from the robot's start (1.0, 2.5, facing east): a left turn, a straight, a turn to the goal yaw
GOAL = (2.2, 4.2, 2.6)


def test_the_example_planner_drives_the_suite_to_the_goal_pose_with_cubes_on_its_arc(ros):
    odom = ros.collect(Odometry, "/odom", qos.RELIABLE)
    cues = ros.collect(MarkerArray, "/haven/ar_markers", qos.RELIABLE)
    for argv in (
        [*HAVEN, "sim", "--without", "planner", "--rtf", "2", "--domain-id", str(ros.domain_id)],
        [sys.executable, str(EXAMPLE)],
    ):
        ros.procs.append(subprocess.Popen(argv, env=ros.env, start_new_session=True, stderr=subprocess.PIPE, text=True))
    goal = ros.node.create_publisher(PoseStamped, "/goal_pose", 10)  # RViz's 2D Goal Pose: default QoS
    ros.wait_for_messages(odom, 5)

    def planner_listens():  # the example's goal reader is matched (not only some other node's)
        readers = ros.node.get_subscriptions_info_by_topic("/goal_pose")
        return "nav2_style_planner" in {r.node_name for r in readers} and goal.get_subscription_count() >= len(readers)

    # (the Nav2 servers publish /plan too, for follow_path; a node's name can come after its writer)
    def planner_publishes():
        return [p for p in ros.node.get_publishers_info_by_topic("/plan") if p.node_name == "nav2_style_planner"]

    assert ros.spin_until(
        lambda: planner_listens() and planner_publishes() and ros.node.count_subscribers("/plan") >= 2, 60
    )
    # (the cues come as deltas: a reader matched late could miss the arc's cubes, gone once it is driven)
    ros.wait_matched(cues)
    (plan_pub,) = planner_publishes()
    assert plan_pub.qos_profile.durability == DurabilityPolicy.VOLATILE
    goal.publish(conv.goal_msg(0.0, Goal(Pose2D(*GOAL), "map")))

    def at_goal():
        p = conv.pose_from_msg(odom[-1].pose.pose)
        return (
            math.hypot(p.x - GOAL[0], p.y - GOAL[1]) <= 0.15
            and abs(math.remainder(p.yaw - GOAL[2], 2 * math.pi)) <= 0.15
            and odom[-1].twist.twist.angular.z == 0.0
        )

    assert ros.spin_until(at_goal, 60), conv.pose_from_msg(odom[-1].pose.pose)
    shapes = {m.type for frame in cues for m in frame.markers if m.ns == "path_projection" and m.action == Marker.ADD}
    assert shapes == {Marker.SPHERE, Marker.CUBE}  # spheres on the straight, cubes on the arc


BOX = """name: open_box
walls:
  - {segment: [[0, 0], [8, 0]], thickness: 0.1}
  - {segment: [[8, 0], [8, 6]], thickness: 0.1}
  - {segment: [[8, 6], [0, 6]], thickness: 0.1}
  - {segment: [[0, 6], [0, 0]], thickness: 0.1}
rooms:
  - {name: room, centre: [4.0, 3.0]}
charging_base: {position: [0.8, 0.8], radius: 0.5}
robot: {start: [1.0, 1.5, 0.0]}
humans:
  - {id: h1, start: [7.0, 5.0, 3.14159]}
gems:
  - {id: r1, owner: robot, position: [4.0, 3.5], radius: 0.3}
  - {id: m1, owner: human, position: [6.0, 5.0], radius: 0.4}
"""
SCENARIO = """name: own_planner
world: small_test
kind: retrieval
timeout_s: 120
robot: {order: nearest, battery: {mode: off}}
humans: [{id: h1, model: walker, speed_mps: 0.8}]
dwell_time_s: 1.0
"""


def test_a_study_session_is_recorded_with_the_users_own_planner_in_another_world(ros, tmp_path):
    """`haven run --without planner --world`: the example planner plans, the session is recorded."""
    (tmp_path / "box.yaml").write_text(BOX)
    (tmp_path / "own.yaml").write_text(SCENARIO)
    planner = subprocess.Popen(
        [sys.executable, str(EXAMPLE)], env=ros.env, start_new_session=True, stderr=subprocess.PIPE, text=True
    )
    ros.procs.append(planner)
    argv = [*HAVEN, "run", str(tmp_path / "own.yaml"), "--without", "planner", "--world", str(tmp_path / "box.yaml")]
    r = ros.run([*argv, "--sessions", str(tmp_path / "s"), "--domain-id", str(ros.domain_id)], timeout_s=240)
    assert r.returncode == 0, r.stdout[-2000:] + r.stderr[-2000:]
    assert "haven: completed" in r.stdout
    (folder,) = (tmp_path / "s").iterdir()
    session = json.loads((folder / "session.json").read_text())
    assert session["without"] == ["planner"] and session["clock"] == "free-running" and session["valid"] is True
    assert "name: open_box" in (folder / "world.yaml").read_text()
    with open(next((folder / "bag").glob("*.mcap")), "rb") as f:
        summary = make_reader(f).get_summary()
    (plan,) = [c for c in summary.channels.values() if c.topic == "/plan"]
    assert "durability: volatile" in plan.metadata["offered_qos_profiles"]  # Nav2's QoS, as offered, for replay
