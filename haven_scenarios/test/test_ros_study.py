"""`haven study run` through real `haven run` subprocesses (the node suite, recorded bags): a tiny
study of one participant and two shared-room trials, then its report."""

import csv
import json
import sys

import pytest
import yaml
from ros_harness import tracebacks

from haven_scenarios.run.trial import run_trial
from haven_scenarios.study.conditions import parse_condition
from haven_scenarios.study.participants import in_session
from haven_scenarios.study.scenario import load_scenario

pytestmark = pytest.mark.ros
HAVEN = [sys.executable, "-m", "haven_scenarios"]


def test_a_tiny_study_runs_each_trial_as_a_recorded_haven_run(ros, tmp_path):
    study = {
        "name": "tiny",
        "scenarios": ["shared_room"],
        "conditions": {"none": ["none"], "signals": ["turn_signals"]},
        "participants": ["p07"],
        "seeds": {"policy": "fixed", "base": 3},
    }
    path = tmp_path / "tiny.yaml"
    path.write_text(yaml.safe_dump(study))
    r = ros.run(
        [*HAVEN, "study", "run", str(path), "--participant", "p07", "--dir", str(tmp_path / "tiny")], timeout_s=240
    )
    assert r.returncode == 0, r.stdout[-2000:] + r.stderr[-2000:]
    assert tracebacks(r.stderr) == []
    assert "all 2 trials done" in r.stdout
    for position, (trial, cues) in enumerate(
        (("01_shared_room-none", ["none"]), ("02_shared_room-signals", ["turn_signals"])), 1
    ):
        (session,) = (tmp_path / "tiny" / "p07" / trial).iterdir()
        assert {"bag", "events.jsonl", "metrics.json", "session.json", "trajectory.png"} <= {
            p.name for p in session.iterdir()
        }
        info = json.loads((session / "session.json").read_text())
        assert (info["participant"], info["seed"], info["outcome"], info["clock"]) == (
            "p07",
            3,
            "completed",
            "lockstep",
        )
        metrics = json.loads((session / "metrics.json").read_text())
        # The same trial without ROS: the same simulated person (seed base 3 + participant index 0) at the same place in
        # the session.
        batch = run_trial(in_session(load_scenario("shared_room"), 3, position), 3, parse_condition(cues)).metrics
        assert metrics["min_human_centre_distance_m"] == pytest.approx(batch["min_human_centre_distance_m"], rel=0.01)
        assert metrics["robot_gem_order"] == batch["robot_gem_order"]
    rep = ros.run([*HAVEN, "study", "report", str(path), "--dir", str(tmp_path / "tiny")], timeout_s=120)
    assert rep.returncode == 0, rep.stderr
    with (tmp_path / "tiny" / "report" / "study_wide.csv").open() as f:
        rows = list(csv.DictReader(f))
    expected = [("shared_room-none", "1", "True"), ("shared_room-signals", "2", "True")]
    assert [(r["trial_id"], r["order_position"], r["valid"]) for r in rows] == expected
