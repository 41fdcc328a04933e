import signal
import sys
import time

import pytest

from haven_scenarios.run.supervisor import ProcessSpec, Supervisor, node_argv, ros_environment

pytestmark = pytest.mark.integration

# Children that say they are ready (their signal handling is set up) by creating the file named
# in argv[1], so the tests signal them only then: no race with the interpreter's start-up.
SLEEPER = "import pathlib, sys, time; pathlib.Path(sys.argv[1]).touch(); time.sleep(60)"
IGNORES_SIGTERM = (
    "import pathlib, signal, sys, time; signal.signal(signal.SIGTERM, signal.SIG_IGN); "
    "pathlib.Path(sys.argv[1]).touch(); time.sleep(60)"
)


def child(code, ready):
    return [sys.executable, "-c", code, str(ready)]


def wait_ready(ready, timeout_s=30.0):
    deadline = time.monotonic() + timeout_s
    while not ready.exists():
        assert time.monotonic() < deadline, "the child never got ready"
        time.sleep(0.01)


def test_environment_keeps_discovery_local_unless_asked():
    env = ros_environment({"PATH": "/bin"}, domain_id=42)
    assert env["ROS_AUTOMATIC_DISCOVERY_RANGE"] == "LOCALHOST"
    assert env["ROS_DOMAIN_ID"] == "42"
    assert env["FASTRTPS_DEFAULT_PROFILES_FILE"].endswith("fastdds.xml")
    assert ros_environment({}, network=True)["ROS_AUTOMATIC_DISCOVERY_RANGE"] == "SUBNET"


def test_node_argv_formats_parameters():
    argv = node_argv("haven_sim.nodes.sim_node", {"world": "w.yaml", "use_sim_time": True, "real_time_factor": 2.0})
    assert argv[1:] == [
        "-m",
        "haven_sim.nodes.sim_node",
        "--ros-args",
        "-p",
        "world:=w.yaml",
        "-p",
        "use_sim_time:=true",
        "-p",
        "real_time_factor:=2.0",
    ]


def test_a_dying_child_is_reported_and_the_rest_stopped(tmp_path):
    with Supervisor(env={}, grace_s=10.0) as sup:
        sleeper = sup.start(ProcessSpec("sleeper", child(SLEEPER, tmp_path / "ready")))
        wait_ready(tmp_path / "ready")
        sup.start(ProcessSpec("crasher", [sys.executable, "-c", "raise SystemExit(3)"]))
        exited = sup.wait(timeout_s=30)
        assert exited is not None and (exited.name, exited.code) == ("crasher", 3)
        codes = sup.stop()
    assert codes["sleeper"] == -signal.SIGTERM  # stopped by our SIGTERM, the first and gentlest step
    assert sleeper.poll() is not None


def test_stop_escalates_when_sigterm_is_ignored(tmp_path):
    with Supervisor(env={}, grace_s=0.5) as sup:
        sup.start(ProcessSpec("stubborn", child(IGNORES_SIGTERM, tmp_path / "ready")))
        wait_ready(tmp_path / "ready")
        codes = sup.stop()
    assert codes["stubborn"] == -signal.SIGKILL


def test_wait_returns_on_a_stop_request(tmp_path):
    with Supervisor(env={}) as sup:
        sup.start(ProcessSpec("sleeper", child(SLEEPER, tmp_path / "ready")))
        sup.request_stop()
        assert sup.wait(timeout_s=10) is None


def test_some_children_stop_while_the_others_run_on_until_a_condition_holds(tmp_path):
    """As after a trial with questionnaires: the trial's nodes stop, the recorder and the web node
    run on; their stopping does not end the wait, which ends when `until` holds or one of the
    others exits."""
    with Supervisor(env={}) as sup:
        for name in ("sim", "web"):
            sup.start(ProcessSpec(name, child(SLEEPER, tmp_path / name)))
            wait_ready(tmp_path / name)
        sup.stop_some(["sim"])
        assert sup.procs["sim"].poll() == -signal.SIGTERM and sup.procs["web"].poll() is None
        checks = []

        def third_check():
            checks.append(1)
            return len(checks) == 3

        assert sup.wait(until=third_check) is None  # (not ended by the stopped child)
        assert len(checks) == 3 and sup.procs["web"].poll() is None
        sup.start(ProcessSpec("recorder", [sys.executable, "-c", "raise SystemExit(0)"]))
        exited = sup.wait(until=lambda: False)
        assert exited is not None and (exited.name, exited.code) == ("recorder", 0)
