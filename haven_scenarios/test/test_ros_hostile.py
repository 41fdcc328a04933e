"""Hostile messages on every topic the suite reads, and hostile values for every parameter (issue 14): NaN, ±inf and
±1e308 in every float field, strings that are not JSON or are JSON of the wrong shape or 100k deep, empty and 10k-long
sequences, integer extremes, maps whose size disagrees with their data, negative clocks. No node may stop; afterwards
the suite still does its job (a goal is reached; a recorded trial ends with its metrics and `haven report` reads it)."""

import json
import socket
import sys
import time

import pytest
from hostile import publish_hostile, set_hostile_parameters, subscribed_topics
from ros_harness import tracebacks
from std_msgs.msg import String
from test_cli import start_haven

from haven_sim.nodes import conversions as conv, qos
from haven_viz.cues import CUES

pytestmark = pytest.mark.ros
HAVEN = [sys.executable, "-m", "haven_scenarios.tools.cli"]
SUITE = {"sim_node", "velocity_mux", "planner", "controller", "viz"}
CROSSING = """name: crossing
world: small_test
kind: retrieval
timeout_s: 40
robot: {order: nearest}
humans: [{id: h1, model: walker, speed_mps: 0.8}]
"""


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def output(proc):
    """All a stopped (or failed) `haven` process said, stdout and stderr."""
    return proc.stdout.read() + proc.stderr.read()


def nodes(ros):
    return {n for n, _ in ros.node.get_node_names_and_namespaces()} - {"haven_test_probe"}


def attack(ros, proc, names, required, only=None, keep=None, spin_s=0.002):
    """Wait for the nodes `names` and what they read (at least `required`; the graph is learnt a
    piece at a time, so also until it has not grown for 2 s), then send every hostile message on
    every topic they read; each node must still be on the graph afterwards and the supervising
    `haven` still running."""
    assert ros.spin_until(lambda: names <= nodes(ros) and required <= set(subscribed_topics(ros.node, names)), 90), (
        nodes(ros)
    )
    wanted, since = subscribed_topics(ros.node, names), time.monotonic()
    while time.monotonic() - since < 2.0:
        ros.spin_for(0.2)
        if len(now := subscribed_topics(ros.node, names)) > len(wanted):
            wanted, since = now, time.monotonic()
    sent = publish_hostile(ros, {t: ty for t, ty in wanted.items() if only is None or t in only}, spin_s, keep)
    assert sent > 50
    ros.spin_for(1.0)
    assert proc.poll() is None, output(proc)[-3000:]
    assert names <= nodes(ros)
    return wanted


def test_the_free_running_suite_and_the_bridge_survive_every_hostile_message_and_still_reach_a_goal(ros):
    port = free_port()
    suite = start_haven(ros, "sim")
    bridge = start_haven(ros, "bridge", "--port", str(port))
    attack(
        ros,
        suite,
        SUITE | {"haven_bridge"},
        {"/goal_pose", "/map", "/odom", "/plan", "/haven/events", "/clock", "/haven/estop", "/cmd_vel_teleop"},
    )
    assert bridge.poll() is None, output(bridge)[-3000:]
    for name in sorted(SUITE):  # parameters: refused at run time, but for the cue toggles (booleans)
        tried, accepted = set_hostile_parameters(ros, name)
        assert tried > 0 and all(a.split("=")[0] in CUES and a.endswith("=True") for a in accepted), (name, accepted)
    assert suite.poll() is None and nodes(ros) >= SUITE
    goto = ros.run([*HAVEN, "goto", "2.0", "1.0", "--timeout", "60", "--domain-id", str(ros.domain_id)], timeout_s=240)
    if goto.returncode != 0:
        ros.stop(suite)
        raise AssertionError(goto.stdout[-2000:] + output(suite)[-6000:])
    for proc in (suite, bridge):
        ros.stop(proc)
        out = output(proc)
        assert tracebacks(out) == [], tracebacks(out)[0]
        assert "ignored a message on /goal_pose" in out or proc is bridge


def test_a_recorded_trial_survives_every_hostile_message_and_is_scored(ros, tmp_path):
    scenario = tmp_path / "crossing.yaml"
    scenario.write_text(CROSSING)
    sessions = tmp_path / "s"
    trial = start_haven(
        ros,
        "run",
        str(scenario),
        "--web",
        "--port",
        str(free_port()),
        "--researcher-start",
        "--sessions",
        str(sessions),
    )
    attack(
        ros,
        trial,
        SUITE | {"scenario", "recorder", "web"},
        {"/goal_pose", "/haven/events", "/haven/trial_control", "/haven/lockstep/ack", "/odom"},
    )
    control = ros.node.create_publisher(String, "/haven/trial_control", qos.RELIABLE)
    ros.wait_matched(control)
    control.publish(String(data="start"))
    out = "".join(trial.communicate(timeout=600))
    assert trial.returncode == 0, out[-3000:]
    assert tracebacks(out) == [], tracebacks(out)[0]
    assert "exited with code" not in out
    (session,) = [p for p in sessions.iterdir() if p.is_dir()]
    metrics = json.loads((session / "metrics.json").read_text())
    assert metrics["end_reason"] in ("completed", "timeout"), metrics["end_reason"]
    report = ros.run([*HAVEN, "report", str(session), "--out", str(tmp_path / "r.csv")])
    assert report.returncode == 0 and tracebacks(report.stderr) == [], report.stderr[-2000:]


def test_a_lockstep_trial_still_completes_when_another_node_sends_unreadable_messages_on_the_suites_topics(
    ros, tmp_path
):
    """The lockstep clock names the suite's messages on its topics (/goal_pose, /plan, /odom) by
    digest: another writer's messages, readable or not, must never be taken for the suite's (a
    participant would then wait for ever for the suite's next goal); they are ignored and counted
    (test_ros_isolation.py floods valid goals)."""
    decoders = {"/goal_pose": conv.goal_from_msg, "/plan": conv.path_from_msg, "/odom": conv.odometry_from_msg}

    def unreadable(topic, msg):
        try:
            decoders[topic](msg)
        except ValueError:
            return True
        return False

    scenario = tmp_path / "crossing.yaml"
    scenario.write_text(CROSSING.replace("timeout_s: 40", "timeout_s: 300"))
    sessions = tmp_path / "s"
    trial = start_haven(ros, "run", str(scenario), "--rtf", "1", "--sessions", str(sessions))
    going = lambda: any('"target_selected"' in p.read_text() for p in sessions.glob("*/events.jsonl"))  # noqa: E731
    assert ros.spin_until(going, 120), "the robot never set off"
    attack(
        ros, trial, SUITE | {"scenario", "recorder"}, set(decoders), only=set(decoders), keep=unreadable, spin_s=0.03
    )
    out = "".join(trial.communicate(timeout=600))
    assert trial.returncode == 0 and tracebacks(out) == [], out[-3000:]
    (session,) = [p for p in sessions.iterdir() if p.is_dir()]
    assert json.loads((session / "metrics.json").read_text())["end_reason"] == "completed", out[-3000:]
