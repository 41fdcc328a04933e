"""A sweep over every cue condition on one scenario (issue 25): each cue, HAVEN's and the
library's, is shown exactly in its own condition, and `haven batch` reports each condition's
exposure on its summary line."""

import csv
import subprocess
import sys

import pytest

from haven_sim.robots.fields import DEFAULT
from haven_viz.cues import CUE_SPECS, cues_for

pytestmark = pytest.mark.integration
HAVEN = [sys.executable, "-m", "haven_scenarios.tools.cli"]


def test_a_sweep_over_every_cue_condition_reports_each_conditions_exposure(tmp_path):
    # the TurtleBot2's: HAVEN's four and the library's (a lab's too, if installed)
    cues = [c for c in cues_for(DEFAULT.kinematics)]
    out = tmp_path / "rows.csv"
    argv = [
        *HAVEN,
        "batch",
        "hallway",
        "--seeds",
        "0",
        "--grid",
        "condition=" + ",".join(["none", *cues]),
        "--out",
        str(out),
    ]
    r = subprocess.run(argv, capture_output=True, text=True, timeout=900)
    assert r.returncode == 0, r.stderr[-3000:]
    rows = {row["condition"]: row for row in csv.DictReader(out.open())}
    assert set(rows) == {"none", *cues}
    for condition, row in rows.items():
        shown = {c for c in cues if float(row[CUE_SPECS[c].exposure]) > 0}
        assert shown == ({condition} - {"none"}), (condition, shown)
        assert row["end_reason"] == "completed" and int(row["human_contacts"]) == 0
    said = {
        line.split("condition ")[1].split(",")[0]: line
        for line in r.stderr.splitlines() + r.stdout.splitlines()
        if "condition " in line
    }
    assert "; no cue shown" in said["none"]
    for cue in cues:
        assert f"; cues shown: {cue} " in said[cue], said[cue]
