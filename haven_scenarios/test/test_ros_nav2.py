"""Nav2's own way of scripting a robot drives the simulated one: a nav2_simple_commander script
(nav2/drive.py: waitUntilNav2Active, getPath, followPath, goToPose, followWaypoints, cancelTask
and a goal off the map) against `haven sim`'s Nav2 servers, with the AR cues showing on every
drive. The script runs with BasicNavigator itself where nav2_simple_commander is installed (it
comes with Nav2 from apt; there is no wheel), and always with nav2/commander.py, a stand-in that
does on the wire what BasicNavigator does."""

import importlib.util
import json
import math
import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest
from geometry_msgs.msg import PoseWithCovarianceStamped
from nav_msgs.msg import Odometry
from ros_harness import tracebacks
from visualization_msgs.msg import Marker, MarkerArray

from haven_sim.nodes import conversions as conv, qos

pytestmark = pytest.mark.ros
nav2_actions = pytest.importorskip(
    "nav2_msgs.action", reason="nav2_msgs is not built here (scripts/build_interfaces.py)"
)
HAVEN = [sys.executable, "-m", "haven_scenarios.tools.cli"]
DRIVE = Path(__file__).parent / "nav2" / "drive.py"
sys.path.insert(0, str(DRIVE.parent))
from drive import FAR, THROUGH  # noqa: E402


def clients():
    yield pytest.param("--ours", id="stand_in")
    installed = importlib.util.find_spec("nav2_simple_commander") is not None
    skip = pytest.mark.skipif(
        not installed, reason="nav2_simple_commander is not installed (apt: ros-jazzy-nav2-simple-commander)"
    )
    yield pytest.param("", id="basic_navigator", marks=skip)


@pytest.mark.parametrize("which", list(clients()))
def test_a_nav2_simple_commander_script_drives_the_robot_with_its_cues_showing(ros, which, tmp_path):
    odom: list[Odometry] = []
    arrived: list[float] = []  # (when each of odom came)
    ros.node.create_subscription(
        Odometry, "/odom", lambda m: (odom.append(m), arrived.append(time.monotonic())), qos.RELIABLE
    )
    arrivals: list[tuple[float, MarkerArray]] = []  # (when, what): the cues as they came
    ros.node.create_subscription(
        MarkerArray, "/haven/ar_markers", lambda m: arrivals.append((time.monotonic(), m)), qos.RELIABLE
    )
    log = (tmp_path / "sim.log").open("w")
    sim = subprocess.Popen(
        [*HAVEN, "sim", "--rtf", "2", "--domain-id", str(ros.domain_id)],
        env=ros.env,
        start_new_session=True,
        stderr=log,
    )
    ros.procs.append(sim)
    # the servers are active
    ros.wait_for_messages(ros.collect(PoseWithCovarianceStamped, "/amcl_pose", qos.LATCHED), timeout_s=60)
    script = subprocess.Popen(
        [sys.executable, str(DRIVE), *([which] if which else [])],
        env=ros.env,
        stdout=subprocess.PIPE,
        text=True,
        start_new_session=True,
    )
    ros.procs.append(script)
    steps: list[tuple[float, dict]] = []
    reader = threading.Thread(
        target=lambda: steps.extend(
            (time.monotonic(), json.loads(line)) for line in script.stdout if line.startswith("{")
        )
    )
    reader.start()
    assert ros.spin_until(lambda: script.poll() is not None, 300), [s for _, s in steps]
    reader.join(5)
    got = {s["step"]: s for _, s in steps}
    steps_run = [
        "active",
        "getPath",
        "getPathInAnotherFrame",
        "followPath",
        "goToPose",
        "followWaypoints",
        "goThroughPoses",
        "cancelTask",
        "offMap",
    ]
    steps_run.append("throughPosesOffMap")
    assert script.returncode == 0 and list(got) == steps_run, got
    # compute_path_to_pose: our planner's arcs and straights
    assert got["getPath"]["poses"] > 2 and got["getPathInAnotherFrame"]["refused"]
    for step in ("followPath", "goToPose", "followWaypoints", "goThroughPoses"):
        assert got[step]["result"] == "SUCCEEDED" and got[step]["error_code"] == 0, got[step]
    assert got["followWaypoints"]["current_waypoint"] == 1
    distances = got["goToPose"]["distances"]  # navigate_to_pose's feedback: the distance left falls to the goal
    assert distances and max(distances) > 1.0 and distances[-1] < 0.3, distances
    # navigate_through_poses passed its first pose without slowing to stop there (within 0.5 m of it,
    # a robot braking at 0.4 m/s^2 to stop on it would be slower than 0.3 m/s at its last 0.11 m).
    (start, end) = [t for t, s in steps if s["step"] in ("followWaypoints", "goThroughPoses")]
    via = THROUGH[0]
    during = [m for t, m in zip(arrived, odom, strict=False) if start <= t <= end]
    passing = [
        abs(m.twist.twist.linear.x)
        for m in during
        if math.dist((m.pose.pose.position.x, m.pose.pose.position.y), via[:2]) < 0.5
    ]
    assert passing and min(passing) > 0.3, passing
    assert got["cancelTask"]["result"] == "CANCELED"
    assert (
        got["offMap"]["result"] == "FAILED"
        and got["offMap"]["error_code"] == nav2_actions.ComputePathToPose.Result.GOAL_OUTSIDE_MAP
    )
    through = got["throughPosesOffMap"]  # refused before the robot moves, with the through-poses planner's code
    assert (
        through["result"] == "FAILED"
        and through["error_code"] == nav2_actions.ComputePathThroughPoses.Result.GOAL_OUTSIDE_MAP
    )

    # The cancel stopped the robot short of the far goal; the final goal of the waypoints was reached.
    ros.spin_until(lambda: abs(odom[-1].twist.twist.linear.x) < 0.01, 10)
    here = conv.pose_from_msg(odom[-1].pose.pose)
    assert math.hypot(here.x - FAR[0], here.y - FAR[1]) > 1.0 and abs(odom[-1].twist.twist.linear.x) < 0.01

    # The AR cues showed on every drive: path projection markers came during each moving task.
    bounds = [t for t, _ in steps]
    for i, (_, s) in enumerate(steps):
        if s["step"] in ("followPath", "goToPose", "followWaypoints", "goThroughPoses", "cancelTask"):
            during = [m for t, m in arrivals if bounds[i - 1] <= t <= bounds[i]]
            shown = [mk for m in during for mk in m.markers if mk.ns == "path_projection" and mk.action == Marker.ADD]
            assert shown, f"no path projection during {s['step']}"

    # Ctrl-C stops the Nav2 servers (and the rest) cleanly.
    os.killpg(sim.pid, signal.SIGINT)
    assert sim.wait(timeout=30) == 0 and tracebacks((tmp_path / "sim.log").read_text()) == []


@pytest.mark.parametrize("which", list(clients()))
def test_ten_goals_on_a_busy_machine_end_within_the_goal_checkers_tolerances_in_the_bag(ros, which, tmp_path):
    """Four busy processes beside the suite on the free-running clock: every navigate_to_pose goal
    that ends SUCCEEDED has the robot within 0.1 m and 0.1 rad of it in the recorded /odom, read
    with rosbags, when `goal_reached` is said and until the next goal (no overshoot, no over-turn).
    The load slows simulated time instead (`clock_held`)."""
    from rosbags.highlevel import AnyReader

    from haven_scenarios.record.bag import TYPESTORE

    sys.path.insert(0, str(DRIVE.parent))
    from goals import GOALS

    busy = [subprocess.Popen([sys.executable, "-c", "while True: pass"]) for _ in range(4)]
    ros.procs.extend(busy)
    log = (tmp_path / "sim.log").open("w")
    argv = [*HAVEN, "sim", "--rtf", "2", "--record", "--sessions", str(tmp_path), "--domain-id", str(ros.domain_id)]
    sim = subprocess.Popen(argv, env=ros.env, start_new_session=True, stderr=log)
    ros.procs.append(sim)
    ros.wait_for_messages(ros.collect(PoseWithCovarianceStamped, "/amcl_pose", qos.LATCHED), timeout_s=120)
    done = ros.run([sys.executable, str(DRIVE.parent / "goals.py"), *([which] if which else [])], timeout_s=600)
    steps = [json.loads(line) for line in done.stdout.splitlines() if line.startswith("{")]
    assert done.returncode == 0 and [s["result"] for s in steps[1:]] == ["SUCCEEDED"] * len(GOALS), (
        steps,
        done.stderr[-2000:],
    )
    os.killpg(sim.pid, signal.SIGINT)
    assert sim.wait(timeout=60) == 0
    for p in busy:
        p.kill()

    (bag,) = tmp_path.glob("*/bag")
    odom, events = [], []
    with AnyReader([bag], default_typestore=TYPESTORE) as reader:
        for conn, stamp, raw in reader.messages(
            [c for c in reader.connections if c.topic in ("/odom", "/haven/events")]
        ):
            msg = reader.deserialize(raw, conn.msgtype)
            if conn.topic == "/odom":
                q = msg.pose.pose.orientation
                odom.append(
                    (stamp * 1e-9, msg.pose.pose.position.x, msg.pose.pose.position.y, 2 * math.atan2(q.z, q.w))
                )
            else:
                events.append(json.loads(msg.data))
    reached = [e for e in events if e["type"] == "goal_reached"]
    sent = [e["stamp"] for e in events if e["type"] == "plan_made"] + [math.inf]
    assert len(reached) == len(GOALS), [e["type"] for e in events]
    for goal, said in zip(GOALS, reached, strict=True):
        until = min(t for t in sent if t > said["stamp"])  # the next goal's plan
        resting = [p for p in odom if said["stamp"] - 1e-6 <= p[0] < until]
        assert resting, said
        for _, x, y, yaw in resting:
            off = (math.hypot(x - goal[0], y - goal[1]), abs(math.remainder(yaw - goal[2], math.tau)))
            assert off[0] <= 0.1 and off[1] <= 0.1, (goal, said, off)
