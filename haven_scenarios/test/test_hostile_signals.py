"""Signals, arguments and the inherited environment (issue 14): however `haven` ends — Ctrl-C, the
terminal closing (SIGHUP), SIGTERM, or SIGKILL — no node outlives it and the recording is closed
properly; bad arguments are one line each, before anything starts; discovery stays on this
machine whatever the shell says, unless --network."""

import json
import os
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

import pytest
from processes import alive
from rosbags.highlevel import AnyReader

from haven_scenarios.run.supervisor import ros_environment
from haven_scenarios.tools.cli import main

pytestmark = pytest.mark.integration

HAVEN = [sys.executable, "-m", "haven_scenarios.tools.cli"]
# A supervisor with one child, in a process of its own: the child's pid is written to argv[1].
SUPERVISED = """
import sys, time
from pathlib import Path
from haven_scenarios.run.supervisor import ProcessSpec, Supervisor
sup = Supervisor(env={})
child = sup.start(ProcessSpec("sleeper", [sys.executable, "-c", "import time; time.sleep(120)"]))
Path(sys.argv[1]).write_text(str(child.pid))
time.sleep(120)
"""


def wait_until(condition, timeout_s, what):
    deadline = time.monotonic() + timeout_s
    while not condition():
        assert time.monotonic() < deadline, what
        time.sleep(0.05)


def children(pid):
    return [int(c) for t in Path(f"/proc/{pid}/task").glob("*/children") for c in t.read_text().split()]


def test_a_child_dies_with_its_supervisor_even_when_the_supervisor_is_killed(tmp_path):
    pidfile = tmp_path / "child.pid"
    sup = subprocess.Popen([sys.executable, "-c", SUPERVISED, str(pidfile)], start_new_session=True)
    try:
        wait_until(lambda: pidfile.exists() and pidfile.read_text(), 30, "the supervisor never started its child")
        child = int(pidfile.read_text())
        assert alive(child)
        sup.kill()  # SIGKILL: no handler of the supervisor runs
        sup.wait()
        wait_until(lambda: not alive(child), 10, "the child outlived its killed supervisor")
    finally:
        if sup.poll() is None:
            os.killpg(sup.pid, signal.SIGKILL)


@pytest.mark.parametrize(
    "argv, says",
    [
        (["run", "--rtf", "inf"], "argument --rtf: must be a finite number, got inf"),
        (["run", "--rtf", "0"], "argument --rtf: must be positive, got 0"),
        (["sim", "--domain-id", "300"], "argument --domain-id: must be 0..232, got 300"),
        (
            ["run", "--params-file", "/no/such/params.yaml"],
            "argument --params-file: /no/such/params.yaml: no such file",
        ),
        (["run", "--params-file", "/dev"], "argument --params-file: /dev: not a regular file"),
        (["batch", "hallway", "--seed", "-1"], "argument --seed: must be 0..2147483647, got -1"),
        (["run", "--seed", "1" + "0" * 40], "argument --seed: expected an integer, got '1000000000"),
        (["run", "--seed", "10000000000"], "argument --seed: must be 0..2147483647, got 10000000000"),
        (["demo", "--laps", "99999999999999999999"], "argument --laps: must be at least 1, got 99999999999999999999"),
        (
            ["run", "--allow", "/cmd_vel_telop"],
            "--allow: /cmd_vel_telop: not a topic the suite or the metrics read (did you mean /cmd_vel_teleop?)",
        ),
        (
            ["run", "--allow", "/odom"],
            "--allow: /odom: the simulator's and the metrics' topics take no outside publisher",
        ),
        (
            ["run", "--allow", "plan"],
            "--allow: plan: the simulator's and the metrics' topics "
            "take no outside publisher (your own planner: --without",
        ),
        (["goto", "1e999", "0"], "argument x: must be a finite number, got 1e999"),
        (["bridge", "--port", "70000"], "argument --port: must be 0..65535, got 70000"),
    ],
)
def test_bad_arguments_are_one_line_before_anything_starts(argv, says, capsys):
    with pytest.raises(SystemExit) as ended:
        main(argv)
    err = capsys.readouterr().err
    assert ended.value.code == 2
    assert len(err.strip().splitlines()) == 1 and says in err


def test_an_empty_participant_id_is_refused_not_turned_into_sim(tmp_path, capsys):
    assert main(["run", "--participant", "", "--sessions", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert err.startswith("haven: error: --participant: must be 1 to 64 ASCII letters") and err.count("\n") == 1
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("command", [["bridge"], ["run", "--web"]])
def test_a_port_in_use_is_one_line(command, capsys):
    with socket.socket() as busy:
        busy.bind(("127.0.0.1", 0))
        busy.listen()
        port = busy.getsockname()[1]
        assert main([*command, "--port", str(port)]) == 2
    err = capsys.readouterr().err.strip()
    assert err == f"haven: error: --host 127.0.0.1 --port {port}: Address already in use"


def test_discovery_stays_local_whatever_the_shell_says_unless_network():
    shell = {
        "ROS_AUTOMATIC_DISCOVERY_RANGE": "SUBNET",
        "ROS_STATIC_PEERS": "192.168.1.7",
        "ROS_DISCOVERY_SERVER": "10.0.0.1:11811",
    }
    local = ros_environment(shell)
    assert local["ROS_AUTOMATIC_DISCOVERY_RANGE"] == "LOCALHOST"
    assert "ROS_STATIC_PEERS" not in local and "ROS_DISCOVERY_SERVER" not in local
    network = ros_environment(shell, network=True)
    assert network["ROS_AUTOMATIC_DISCOVERY_RANGE"] == "SUBNET" and network["ROS_STATIC_PEERS"] == "192.168.1.7"


@pytest.mark.ros
@pytest.mark.parametrize("sig", [signal.SIGHUP, signal.SIGINT, signal.SIGKILL], ids=lambda s: signal.Signals(s).name)
def test_however_haven_run_ends_no_node_outlives_it_and_the_bag_is_closed(ros, tmp_path, sig):
    """SIGHUP is what closing the terminal or the SSH session sends; SIGINT a terminal's Ctrl-C (to
    `haven` alone: the nodes run in sessions of their own); SIGKILL runs no handler at all, so the
    kernel stops the nodes (SIGTERM, as their supervisor would) and the recorder still closes its bag."""
    sessions = tmp_path / "s"
    env = {**ros.env, "ROS_AUTOMATIC_DISCOVERY_RANGE": "SUBNET"}  # inherited: must not matter
    argv = [*HAVEN, "run", "hallway", "--rtf", "2", "--sessions", str(sessions), "--domain-id", str(ros.domain_id)]
    with (tmp_path / "out").open("w") as out:
        proc = subprocess.Popen(argv, env=env, stdout=out, stderr=subprocess.STDOUT, start_new_session=True)
    ros.procs.append(proc)
    started = lambda: any('"trial_start"' in p.read_text() for p in sessions.glob("*/events.jsonl"))  # noqa: E731
    wait_until(started, 120, "the trial never started")
    nodes = children(proc.pid)
    assert len(nodes) == 2  # the recorder, and the suite (sim, mux, planner, controller, viz, scenario)
    for pid in nodes:
        environ = Path(f"/proc/{pid}/environ").read_bytes().split(b"\0")
        assert b"ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST" in environ
    os.kill(proc.pid, sig)
    proc.wait(timeout=60)
    wait_until(lambda: not any(alive(pid) for pid in nodes), 30, "a node outlived haven")
    output = (tmp_path / "out").read_text()
    assert "Traceback" not in output, output[-3000:]
    (folder,) = sessions.iterdir()
    with AnyReader([folder / "bag"]) as reader:  # metadata.yaml written: the recorder closed the bag
        assert reader.message_count > 0
    if sig != signal.SIGKILL:
        assert proc.returncode == 1, output[-3000:]  # (a trial that did not run to its end)
        assert json.loads((folder / "session.json").read_text())["outcome"].startswith("interrupted")
