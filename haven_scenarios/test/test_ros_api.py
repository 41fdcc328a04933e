"""The API's example script (examples/api_pilot.py), as a user runs it: a recorded trial through
`api.recorded_trial` and a three-participant pilot study through the study calls."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest
from ros_harness import tracebacks

pytestmark = pytest.mark.ros

SCRIPT = Path(__file__).resolve().parents[2] / "examples" / "api_pilot.py"


def test_the_api_example_records_a_trial_and_runs_a_pilot_study(ros, tmp_path):
    r = ros.run([sys.executable, str(SCRIPT), str(tmp_path / "pilot")], timeout_s=600)
    assert r.returncode == 0 and tracebacks(r.stderr) == [], r.stdout[-2000:] + r.stderr[-3000:]
    (session,) = (tmp_path / "pilot" / "sessions").iterdir()
    info = json.loads((session / "session.json").read_text())
    metrics = json.loads((session / "metrics.json").read_text())
    assert (info["outcome"], info["participant"], info["seed"], info["ros_domain_id"]) == (
        "completed",
        "pilot",
        1,
        ros.domain_id,
    )
    assert metrics["valid"], metrics["invalid_reasons"]
    assert (
        f"recorded: {session.name}: completed, valid True, closest approach {metrics['min_human_centre_distance_m']} m"
        in r.stdout
    )
    assert "study: 6 trials done; 3 participant(s), 6 trials" in r.stdout
    assert (tmp_path / "pilot" / "study" / "report" / "study_wide.csv").exists()
