"""ROS mode: a participant model that hangs in the scenario node ends the recorded trial at its
deadline, and a metric that hangs in the analysis of the bag is given up at its own; the session
says `valid: false` with both reasons (session.json, metrics.json), and nothing hangs."""

from __future__ import annotations

import json
import subprocess

import pytest
from failing_plugins import PARAMS, SCENARIO, install
from ros_harness import tracebacks
from test_contained_plugins import HANG, HAVEN

pytestmark = pytest.mark.ros


def test_a_hanging_participant_model_and_metric_end_a_recorded_trial_not_valid_with_the_reasons(ros, tmp_path):
    env = {**ros.env, "PYTHONPATH": install(tmp_path / "site")["PYTHONPATH"], "LAB_METRIC": "hang"}
    (tmp_path / "hang.yaml").write_text(SCENARIO.format(model="hanger"))
    (tmp_path / "params.yaml").write_text(PARAMS)
    argv = [
        *HAVEN,
        "run",
        str(tmp_path / "hang.yaml"),
        "--params-file",
        str(tmp_path / "params.yaml"),
        "--domain-id",
        str(ros.domain_id),
    ]
    r = subprocess.run([*argv, "--sessions", str(tmp_path / "s")], env=env, capture_output=True, text=True, timeout=300)
    assert r.returncode == 0 and tracebacks(r.stderr) == [], r.stdout[-2000:] + r.stderr[-3000:]
    (session,) = (tmp_path / "s").iterdir()
    info = json.loads((session / "session.json").read_text())
    reasons = [f"participant model hanger failed ({HANG} 1 s)", f"metric flaky failed ({HANG} 10 s)"]
    assert info["valid"] is False and info["end_reason"] == "plugin_failed"
    # (a loaded machine may add its own: a bag repaired)
    assert [r for r in info["invalid_reasons"] if " failed (" in r] == reasons
    events = [json.loads(line) for line in (session / "events.jsonl").read_text().splitlines()]
    (failed,) = [e for e in events if e["type"] == "plugin_failed"]
    assert (failed["source"], failed["kind"], failed["name"]) == ("scenario", "participants", "hanger")
    assert "the session is not valid: participant model hanger failed" in r.stderr
