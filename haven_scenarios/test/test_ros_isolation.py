"""No silent corruption (issue 21): two suites on one ROS domain, a node flooding the suite's
topics, somebody resetting the world or changing a node's parameters mid-trial. A trial either
stays its own (and equal to the same trial alone) or says in its session why it is not valid."""

from __future__ import annotations

import contextlib
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from independent_scorer import score
from ros_harness import tracebacks
from test_ros_trial import CROSSING, assert_same_trial, metrics_of, only_session

from haven_scenarios.run.trial import run_trial
from haven_scenarios.study.scenario import load_scenario

pytestmark = pytest.mark.ros
HAVEN = [sys.executable, "-m", "haven_scenarios"]

FLOOD = str(Path(__file__).resolve().parent / "flood.py")  # goals at a rate, from another node


def start(ros, argv, env=None):
    proc = subprocess.Popen(
        argv, env=env or ros.env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True
    )
    ros.procs.append(proc)
    return proc


def finish(proc, timeout_s=300):
    out, err = proc.communicate(timeout=timeout_s)
    assert tracebacks(err) == [], tracebacks(err)[0]
    return proc.returncode, out, err


def crossing(tmp_path):
    path = tmp_path / "crossing.yaml"
    path.write_text(CROSSING)
    return path


def test_two_suites_started_at_once_without_a_domain_id_each_take_their_own(ros, tmp_path):
    """Both inherit the same ROS_DOMAIN_ID: the first takes it, the other a free one (and says
    which); both trials complete, valid, equal to each other and to the same trial in batch mode."""
    scenario = crossing(tmp_path)
    runs = [start(ros, [*HAVEN, "run", str(scenario), "--sessions", str(tmp_path / name)]) for name in ("a", "b")]
    said = [finish(p) for p in runs]
    assert [code for code, _, _ in said] == [0, 0], said
    moved = [out for _, out, _ in said if "this suite runs on ROS domain" in out]
    assert len(moved) == 1 and f"ROS domain {ros.domain_id}: another HAVEN suite runs on it" in moved[0]
    domains = {
        json.loads((only_session(tmp_path / n) / "session.json").read_text())["ros_domain_id"] for n in ("a", "b")
    }
    assert len(domains) == 2 and ros.domain_id in domains
    a, b = (metrics_of(only_session(tmp_path / n)) for n in ("a", "b"))
    assert a["valid"] and b["valid"], (a["invalid_reasons"], b["invalid_reasons"])
    assert_same_trial(a, b)
    assert_same_trial(a, run_trial(load_scenario(str(scenario)), 0).metrics, rel=0.01)


def test_a_second_suite_on_an_explicit_shared_domain_is_refused_in_one_line_whichever_starts_first(ros, tmp_path):
    scenario = crossing(tmp_path)
    domain = ["--domain-id", str(ros.domain_id)]
    # Two at once: exactly one runs.
    runs = [start(ros, [*HAVEN, "run", str(scenario), *domain, "--sessions", str(tmp_path / n)]) for n in ("a", "b")]
    said = [finish(p) for p in runs]
    codes = sorted(code for code, _, _ in said)
    assert codes == [0, 2], said
    (refused,) = [err for code, _, err in said if code == 2]
    assert (
        refused.count("\n") == 1
        and f"haven: error: ROS domain {ros.domain_id}: another HAVEN suite runs on it (pid " in refused
    )
    assert len([p for p in tmp_path.glob("*/*") if p.is_dir()]) == 1  # the refused run made no session
    # A simulator someone started by hand (no `haven`, so no lock) is found on the graph.
    sim = ros.start("haven_sim.nodes.sim_node")
    assert ros.spin_until(lambda: "sim_node" in {n for n, _ in ros.node.get_node_names_and_namespaces()}, 30)
    code, _, err = finish(start(ros, [*HAVEN, "sim", *domain, "--duration", "30"]))
    assert code == 2 and err.count("\n") == 1 and "HAVEN suite nodes already run on it (sim_node;" in err, err
    ros.stop(sim)


def test_a_goal_flood_a_reset_and_a_parameter_change_leave_a_lockstep_trial_its_own(ros, tmp_path):
    """1 kHz of goals from another node for 10 s: the planner never sees them (the lockstep clock
    tells the suite's goals by digest), the trial equals the batch trial and stays valid, and the
    session and the study log say what was ignored; /haven/reset and setting use_sim_time mid-trial
    are refused, each an event."""
    from rclpy.parameter import Parameter
    from rclpy.parameter_client import AsyncParameterClient
    from std_srvs.srv import Trigger

    scenario = crossing(tmp_path)
    flood = start(ros, [sys.executable, FLOOD, "1000", "10"])
    trial = start(
        ros, [*HAVEN, "run", str(scenario), "--domain-id", str(ros.domain_id), "--sessions", str(tmp_path / "s")]
    )
    reset = ros.node.create_client(Trigger, "/haven/reset")
    assert reset.wait_for_service(timeout_sec=60)
    answer = reset.call_async(Trigger.Request())
    assert ros.spin_until(answer.done, 30) and not answer.result().success and "refused" in answer.result().message
    params = AsyncParameterClient(ros.node, "controller")
    assert params.wait_for_services(timeout_sec=60)
    tried = params.set_parameters([Parameter("use_sim_time", value=False)])
    assert ros.spin_until(tried.done, 30) and not tried.result().results[0].successful
    code, out, err = finish(trial)
    assert code == 0, out[-2000:] + err[-3000:]
    assert "flood:" in finish(flood)[1]
    folder = only_session(tmp_path / "s")
    m = metrics_of(folder)
    assert m["valid"], m["invalid_reasons"]
    assert (
        "/goal_pose: published by goal_flood from outside the suite, ignored on the lockstep clock"
        in m["outside_publishers"]
    )
    assert_same_trial(m, run_trial(load_scenario(str(scenario)), 0).metrics, rel=0.01)
    s = score(folder / "bag")
    assert m["min_human_centre_distance_m"] == pytest.approx(s.min_human_centre_distance_m, abs=0.02)
    events = [json.loads(line) for line in (folder / "events.jsonl").read_text().splitlines()]
    ignored = sum(e.get("ignored", 0) for e in events if e["type"] == "outside_input" and e["topic"] == "/goal_pose")
    assert ignored > 100
    refused = {(e["source"], e["request"]) for e in events if e["type"] == "request_refused"}
    assert ("sim_node", "service") in refused and ("controller", "parameter") in refused


def test_an_outside_publisher_on_a_free_running_trial_makes_it_not_valid_unless_allowed(ros, tmp_path):
    """On the free-running clock nothing tells outside goals from the scenario's: the planner
    coalesces a storm (one warning, a goal_storm event) and the session says it is not valid,
    naming the node; with `--allow /goal_pose` the same run is valid. (The goals take the robot
    away from its task: the trial ends on its timeout, honestly.)"""
    scenario = tmp_path / "short.yaml"
    scenario.write_text(CROSSING.replace("timeout_s: 120", "timeout_s: 30"))
    for allow, sessions in ((["--allow", "/goal_pose"], "allowed"), ([], "s")):
        flood = start(ros, [sys.executable, FLOOD, "200", "2"])
        trial = start(ros, [*HAVEN, "run", str(scenario), "--free-running", "--rtf", "8",
                            "--domain-id", str(ros.domain_id), *allow,
                            "--sessions", str(tmp_path / sessions)])  # fmt: skip
        _code, _out, err = finish(trial)
        finish(flood)
        m = metrics_of(only_session(tmp_path / sessions))
        events = (only_session(tmp_path / sessions) / "events.jsonl").read_text()
        assert '"goal_storm"' in events and err.count("goal storm: goals closer together") == 1, err[-3000:]
        if allow:
            assert m["valid"] is True, m["invalid_reasons"]
            assert "goal_flood from outside the suite, on a topic the run opened to it" in m["outside_publishers"]
        else:
            assert (
                m["valid"] is False
                and "/goal_pose: published by goal_flood from outside the suite" in m["invalid_reasons"]
            )
            assert err.count("haven run --allow TOPIC") == 1  # (said once, whatever the number of outsiders)
            assert "/goal_pose: published by goal_flood from outside the suite: the session will not be valid" in err


def test_a_study_participant_already_being_run_is_refused_before_anything_starts(ros, tmp_path):
    """`haven study run` (ROS mode) on a participant another runner holds: one line naming it."""
    from haven_scenarios.conduct.study_run import RUNNER_LOCK
    from haven_scenarios.run.locks import FileLock

    study = tmp_path / "pilot.yaml"
    study.write_text("name: pilot\nscenarios: [shared_room]\nconditions: {all: [all]}\nparticipants: 1\n")
    with FileLock(tmp_path / "studies" / "pilot" / "p01" / RUNNER_LOCK, "haven study run pilot.yaml --participant p01"):
        argv = [*HAVEN, "study", "run", str(study), "--participant", "p01", "--domain-id", str(ros.domain_id)]
        r = subprocess.run(argv, env=ros.env, cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert r.returncode == 2 and r.stderr.count("\n") == 1
    assert (
        "participant p01 of study pilot is already being run (pid "
        f"{os.getpid()}, haven study run pilot.yaml --participant p01" in r.stderr
    )
    assert not list((tmp_path / "studies" / "pilot" / "p01").glob("*/*/session.json"))


def test_with_a_range_of_domains_a_second_and_third_suite_stay_inside_it(ros, tmp_path):
    """`--domains A-(A+2)` with A held by another suite (its lock) and the inherited domain outside
    the range: two suites started at once take A+1 and A+2, say so, and every node of each runs
    there (its ROS_DOMAIN_ID, read from /proc)."""
    from haven_scenarios.run.domains import lock_path
    from haven_scenarios.run.locks import FileLock

    first = 200 + 3 * (ros.domain_id % 10)  # (a range no test harness hands out: they take 1..100)
    lab = f"{first}-{first + 2}"
    scenario = crossing(tmp_path)
    with FileLock(lock_path(first), "haven run (the first suite)").acquire():
        runs = [
            start(ros, [*HAVEN, "run", str(scenario), "--domains", lab, "--sessions", str(tmp_path / n)])
            for n in ("a", "b")
        ]
        seen: dict[int, set[str]] = {}
        for proc in runs:
            nodes = lambda p=proc: [  # noqa: E731
                int(c) for t in Path(f"/proc/{p.pid}/task").glob("*/children") for c in t.read_text().split()
            ]
            started = ros.spin_until(lambda nodes=nodes, proc=proc: len(nodes()) == 2 or proc.poll() is not None, 120)
            assert started, "the suite never started its nodes"
            for pid in nodes():
                with contextlib.suppress(OSError):
                    if b"--ros-args" not in Path(f"/proc/{pid}/cmdline").read_bytes():
                        continue  # (not a node: `git` asked for the commit, say)
                    env = dict(
                        v.split(b"=", 1) for v in Path(f"/proc/{pid}/environ").read_bytes().split(b"\0") if b"=" in v
                    )
                    seen.setdefault(proc.pid, set()).add(env[b"ROS_DOMAIN_ID"].decode())
        said = [finish(p) for p in runs]
    assert [code for code, _, _ in said] == [0, 0], said
    taken = sorted(
        json.loads((only_session(tmp_path / n) / "session.json").read_text())["ros_domain_id"] for n in ("a", "b")
    )
    assert taken == [first + 1, first + 2]
    # one domain per suite, its nodes all there
    assert sorted(d for ds in seen.values() for d in ds) == [str(first + 1), str(first + 2)]
    for _, out, _ in said:
        assert (
            f"haven: ROS domain {ros.domain_id}: outside --domains {lab}; this suite runs on ROS domain {first + 1}"
            in out
            or (f"outside --domains {lab}; this suite runs on ROS domain {first + 2}" in out)
        ), out
