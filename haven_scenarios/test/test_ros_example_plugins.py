"""The worked plugin package in a recorded trial: the scenario node runs the lab's participant
model, the session's metrics have the lab's metric, and the recording is valid."""

from __future__ import annotations

import json
import subprocess

import pytest
from ros_harness import tracebacks
from test_example_plugins import HAVEN, SCENARIO, installed

pytestmark = pytest.mark.ros


def test_a_recorded_trial_runs_the_labs_participant_model_and_metric(ros, tmp_path):
    env = {**ros.env, "PYTHONPATH": installed(tmp_path)["PYTHONPATH"]}  # (the harness's domain, the example on the path)
    (tmp_path / "hurried.yaml").write_text(SCENARIO)
    argv = [*HAVEN, "run", str(tmp_path / "hurried.yaml"), "--domain-id", str(ros.domain_id), "--sessions", str(tmp_path / "s")]
    r = subprocess.run(argv, env=env, capture_output=True, text=True, timeout=600)
    assert r.returncode == 0 and tracebacks(r.stderr) == [], r.stdout[-2000:] + r.stderr[-3000:]
    (session,) = (tmp_path / "s").iterdir()
    metrics = json.loads((session / "metrics.json").read_text())
    assert metrics["valid"], metrics["invalid_reasons"]
    assert metrics["seconds_within_2m"] > 0 and "near_error" not in metrics
    assert "model: hurried" in (session / "scenario.yaml").read_text()
