"""The worked plugin package in a recorded trial: the scenario node runs the lab's participant
model, the viz node draws the lab's cue (in the bag, read with rosbags: its markers and its value on
/haven/cue_state), the session's metrics have the lab's metric and the cue's exposure, and the
recording is valid."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path

import pytest
from ros_harness import tracebacks
from rosbags.highlevel import AnyReader
from test_example_plugins import HAVEN, SCENARIO, installed

pytestmark = pytest.mark.ros


def test_a_recorded_trial_runs_the_labs_participant_model_cue_and_metric(ros, tmp_path):
    # (the harness's domain, the example on the path)
    env = {**ros.env, "PYTHONPATH": installed(tmp_path)["PYTHONPATH"]}
    (tmp_path / "hurried.yaml").write_text(SCENARIO)
    argv = [
        *HAVEN,
        "run",
        str(tmp_path / "hurried.yaml"),
        "--domain-id",
        str(ros.domain_id),
        "--sessions",
        str(tmp_path / "s"),
    ]
    r = subprocess.run(argv, env=env, capture_output=True, text=True, timeout=600)
    assert r.returncode == 0 and tracebacks(r.stderr) == [], r.stdout[-2000:] + r.stderr[-3000:]
    (session,) = (tmp_path / "s").iterdir()
    metrics = json.loads((session / "metrics.json").read_text())
    assert metrics["valid"], metrics["invalid_reasons"]
    assert metrics["seconds_within_2m"] > 0 and "near_error" not in metrics
    assert "model: hurried" in (session / "scenario.yaml").read_text()
    assert metrics["floor_arrows_shown_s"] > 0 and metrics["turn_signal_shown_s"] > 0
    shown, drawn = cue_in_bag(session / "bag")
    assert shown > 0 and drawn > 0


def cue_in_bag(bag: Path) -> tuple[int, int]:
    """(/haven/cue_state messages with floor arrows down, /haven/ar_markers messages with a floor arrow)."""
    shown = drawn = 0
    with AnyReader([bag]) as reader:
        wanted = [c for c in reader.connections if c.topic in ("/haven/cue_state", "/haven/ar_markers")]
        for conn, _, raw in reader.messages(connections=wanted):
            msg = reader.deserialize(raw, conn.msgtype)
            if conn.topic == "/haven/cue_state":
                shown += json.loads(msg.data).get("floor_arrows", 0) > 0
            else:
                drawn += any(m.ns == "floor_arrows" and m.action == 0 for m in msg.markers)
    return shown, drawn
