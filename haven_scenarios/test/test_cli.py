"""The `haven` command as a user runs it: a separate process, stopped with Ctrl-C (SIGINT)."""

import importlib.util
import json
import os
import signal
import subprocess
import sys
import time
from importlib import resources
from pathlib import Path

import pytest
from nav_msgs.msg import Odometry
from processes import alive, children_of
from ros_harness import tracebacks

from haven_sim.nodes import qos

pytestmark = pytest.mark.ros
HAVEN = [sys.executable, "-m", "haven_scenarios.tools.cli"]


def start_haven(ros, *args):
    proc = subprocess.Popen(
        [*HAVEN, *args, "--domain-id", str(ros.domain_id)],
        env=ros.env,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,
    )
    ros.procs.append(proc)
    return proc


@pytest.mark.parametrize(("processes", "suite"), [("one", 1), ("separate", 5)])
def test_sim_runs_and_ctrl_c_stops_every_process(ros, processes, suite):
    """With the packaged parameter file, which every node must accept; the suite's nodes in one
    process (the default) or in one each (sim, mux, planner, controller, viz)."""
    odom = ros.collect(Odometry, "/odom", qos.RELIABLE)
    params = resources.files("haven_sim") / "config" / "haven.yaml"
    proc = start_haven(ros, "sim", "--rtf", "2", "--params-file", str(params), "--processes", processes)
    ros.wait_for_messages(odom, 10)
    # Every node up: viz (markers), planner (plan) and controller (cmd_vel_nav), each discovered in its own time.
    assert ros.spin_until(
        lambda: all(ros.node.count_publishers(t) > 0 for t in ("/haven/ar_markers", "/plan", "/cmd_vel_nav")), 30
    )
    assert ros.node.count_publishers("/cmd_vel_nav") == 1  # one controller
    kids = children_of(proc.pid)
    nav2 = importlib.util.find_spec("nav2_msgs") is not None  # (Nav2's servers where nav2_msgs is built)
    assert len(kids) == suite + nav2  # (and Nav2's servers)
    os.killpg(proc.pid, signal.SIGINT)  # what a terminal's Ctrl-C does
    assert proc.wait(timeout=20) == 0
    assert not [k for k in kids if alive(k)]
    assert tracebacks(proc.stderr.read()) == []


def test_a_node_that_dies_takes_the_suite_down_with_a_message(ros):
    odom = ros.collect(Odometry, "/odom", qos.RELIABLE)
    proc = start_haven(ros, "sim")
    ros.wait_for_messages(odom, 1)
    kids = children_of(proc.pid)
    suite_pid = max(kids, key=lambda k: "suite_process" in Path(f"/proc/{k}/cmdline").read_text())
    os.kill(suite_pid, signal.SIGKILL)
    code = proc.wait(timeout=20)
    assert code != 0
    assert "suite exited with code -9; stopped the others" in proc.stderr.read()
    deadline = time.monotonic() + 5
    while time.monotonic() < deadline and any(alive(k) for k in kids):
        time.sleep(0.05)
    assert not [k for k in kids if alive(k)]


def test_invalid_world_is_refused_before_anything_starts(tmp_path):
    bad = tmp_path / "w.yaml"
    bad.write_text("name: w\nwalls:\n  - {segment: [[0, 0], [1, 0]], thickness: zero}\nrobot: {start: [0, 1]}\n")
    r = subprocess.run([*HAVEN, "sim", "--world", str(bad)], capture_output=True, text=True, timeout=30)
    assert r.returncode == 2
    assert r.stderr.strip() == f"haven: error: {bad}: walls[0].thickness: must be a finite number, got 'zero'"
    assert r.stdout == ""


def test_bad_arguments_get_one_line(tmp_path):
    r = subprocess.run([*HAVEN, "sim", "--rtf", "-1"], capture_output=True, text=True, timeout=30)
    assert r.returncode == 2 and "must be positive" in r.stderr.splitlines()[-1]


def test_demo_drives_a_square_and_reports(ros):
    # At 1x: the driver is a teleop client in a process of its own, which the clock does not wait
    # for; at 4x a busy machine starved it for long enough that the robot ran on into a wall (twice
    # in three runs with another suite's test beside it).
    proc = start_haven(ros, "demo", "--rtf", "1")
    out, err = proc.communicate(timeout=180)
    assert proc.returncode == 0, err
    summary = json.loads(out.strip().splitlines()[-1])
    # Only what does not depend on how promptly the driver's commands arrive (overshoot at the
    # corners varies with the machine's load):
    assert summary["legs"] == 4 and summary["contacts"] == 0, summary
    assert summary["distance_m"] >= 4 * 1.49  # every leg is driven to its full length
    assert summary["battery"] == pytest.approx(1.0 - summary["distance_m"] / 100.0, abs=0.005)  # drains per metre
    assert summary["odom_rate_hz_sim"] == pytest.approx(50.0, rel=0.01)  # one /odom per physics step


def test_goto_sends_a_goal_to_a_running_suite_and_waits_for_arrival(ros):
    odom = ros.collect(Odometry, "/odom", qos.RELIABLE)
    start_haven(ros, "sim", "--rtf", "4")
    ros.wait_for_messages(odom, 5)
    r = ros.run([*HAVEN, "goto", "6.5", "1.5", "--domain-id", str(ros.domain_id)], timeout_s=120)
    assert r.returncode == 0, r.stdout + r.stderr
    lines = r.stdout.splitlines()
    assert lines[0].startswith("goto: sent goal (6.50, 1.50")
    assert any("plan_made" in line for line in lines) and "goal_reached" in lines[-1]
    refused = ros.run([*HAVEN, "goto", "6.3", "3.8", "--domain-id", str(ros.domain_id)], timeout_s=60)
    assert refused.returncode == 1 and "inside an obstacle" in refused.stdout


def test_snapshot_saves_what_the_viewers_show(ros, tmp_path):
    alone = ros.run(
        [*HAVEN, "snapshot", str(tmp_path / "none.png"), "--timeout", "2", "--domain-id", str(ros.domain_id)],
        timeout_s=60,
    )
    assert alone.returncode == 1 and "no HAVEN suite here" in alone.stderr and alone.stderr.count("\n") == 1, (
        alone.stderr
    )
    assert not (tmp_path / "none.png").exists()
    odom = ros.collect(Odometry, "/odom", qos.RELIABLE)
    start_haven(ros, "sim", "--rtf", "2")
    ros.wait_for_messages(odom, 5)
    out = tmp_path / "snap.png"
    r = ros.run([*HAVEN, "snapshot", str(out), "--domain-id", str(ros.domain_id)], timeout_s=60)
    assert r.returncode == 0, r.stderr
    assert out.stat().st_size > 10_000 and "markers" in r.stdout


def test_graph_inspection_without_the_ros2_command(ros):
    odom = ros.collect(Odometry, "/odom", qos.RELIABLE)
    ros.start("haven_sim.nodes.sim_node")
    ros.wait_for_messages(odom, 5)
    topics = ros.run([*HAVEN, "topics", "--domain-id", str(ros.domain_id)], timeout_s=60)
    assert topics.returncode == 0
    assert "/odom [nav_msgs/msg/Odometry] publishers: 1" in topics.stdout
    echo = ros.run([*HAVEN, "echo", "/battery_state", "--count", "1", "--domain-id", str(ros.domain_id)], timeout_s=60)
    assert echo.returncode == 0 and "percentage: 1.0" in echo.stdout and "frame_id: 'base_link'" in echo.stdout
    hz = subprocess.Popen(
        [*HAVEN, "hz", "/odom", "--domain-id", str(ros.domain_id)],
        env=ros.env,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,
    )
    ros.procs.append(hz)
    deadline = time.monotonic() + 30
    lines = []
    while time.monotonic() < deadline and len([x for x in lines if "average rate" in x]) < 3:
        lines.append(hz.stdout.readline())
    os.killpg(hz.pid, signal.SIGINT)
    rates = [float(x.split(":")[1]) for x in lines if "average rate" in x]
    assert rates and 45.0 < rates[-1] < 55.0
    missing = ros.run([*HAVEN, "echo", "/nope", "--domain-id", str(ros.domain_id)], timeout_s=60)
    assert missing.returncode == 1 and "no topic /nope" in missing.stderr
