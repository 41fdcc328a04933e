import signal
import sys
import time

from haven_scenarios.tools.supervisor import ProcessSpec, Supervisor, node_argv, ros_environment

SLEEPER = [sys.executable, "-c", "import time; time.sleep(60)"]
IGNORES_SIGINT = [sys.executable, "-c", "import signal, time; signal.signal(signal.SIGINT, signal.SIG_IGN); print('ready', flush=True); time.sleep(60)"]


def test_environment_keeps_discovery_local_unless_asked():
    env = ros_environment({"PATH": "/bin"}, domain_id=42)
    assert env["ROS_AUTOMATIC_DISCOVERY_RANGE"] == "LOCALHOST"
    assert env["ROS_DOMAIN_ID"] == "42"
    assert env["FASTRTPS_DEFAULT_PROFILES_FILE"].endswith("fastdds.xml")
    assert ros_environment({}, network=True)["ROS_AUTOMATIC_DISCOVERY_RANGE"] == "SUBNET"


def test_node_argv_formats_parameters():
    argv = node_argv("haven_sim.nodes.sim_node", {"world": "w.yaml", "use_sim_time": True, "real_time_factor": 2.0})
    assert argv[1:] == ["-m", "haven_sim.nodes.sim_node", "--ros-args", "-p", "world:=w.yaml", "-p", "use_sim_time:=true", "-p", "real_time_factor:=2.0"]


def test_a_dying_child_is_reported_and_the_rest_stopped():
    with Supervisor(env={}, grace_s=2.0) as sup:
        sleeper = sup.start(ProcessSpec("sleeper", SLEEPER))
        sup.start(ProcessSpec("crasher", [sys.executable, "-c", "raise SystemExit(3)"]))
        exited = sup.wait(timeout_s=20)
        assert exited is not None and (exited.name, exited.code) == ("crasher", 3)
        codes = sup.stop()
    # Stopped by our SIGINT: -SIGINT, or 1 when it lands while Python is still starting up.
    assert codes["sleeper"] in (-signal.SIGINT, 1)
    assert sleeper.poll() is not None


def test_stop_escalates_when_sigint_is_ignored():
    with Supervisor(env={}, grace_s=0.5) as sup:
        proc = sup.start(ProcessSpec("stubborn", IGNORES_SIGINT))
        t0 = time.monotonic()
        while proc.poll() is None and time.monotonic() - t0 < 10:
            time.sleep(0.05)
            if sup.wait(timeout_s=0.5) is None:
                break
        codes = sup.stop()
    assert codes["stubborn"] == -signal.SIGTERM


def test_wait_returns_on_a_stop_request():
    with Supervisor(env={}) as sup:
        sup.start(ProcessSpec("sleeper", SLEEPER))
        sup.request_stop()
        assert sup.wait(timeout_s=10) is None
