"""A lab's plugin that raises or hangs ends its own trial, not the sweep (haven_sim/common/contain.py):
a raising and a hanging participant model, and a raising and a hanging metric, each leave a
complete CSV with that trial not valid and the reason, well within a minute; the other trials are
as without them. (The plugins: failing_plugins.py, installed as a lab's are; deadlines from a
parameter file, as a lab would set them.)"""

from __future__ import annotations

import csv
import subprocess
import sys
import time
from pathlib import Path

import pytest
from failing_plugins import PARAMS, SCENARIO, install

pytestmark = pytest.mark.integration

HAVEN = [sys.executable, "-m", "haven_scenarios"]
HANG = "took longer than its deadline of"


def batch(
    tmp_path: Path, env: dict[str, str], grid: str, workers: int, name: str
) -> tuple[list[dict[str, str]], float]:
    """The rows of a `haven batch` of the short scenario over `grid`, and its wall time."""
    (tmp_path / "short.yaml").write_text(SCENARIO.format(model="walker"))
    (tmp_path / "params.yaml").write_text(PARAMS)
    out = tmp_path / f"{name}.csv"
    argv = [
        *HAVEN,
        "batch",
        str(tmp_path / "short.yaml"),
        "--grid",
        grid,
        "--seeds",
        "0",
        "--workers",
        str(workers),
        "--out",
        str(out),
    ]
    started = time.monotonic()
    r = subprocess.run(
        [*argv, "--params-file", str(tmp_path / "params.yaml")], env=env, capture_output=True, text=True, timeout=300
    )
    took = time.monotonic() - started
    assert r.returncode == 0 and "Traceback" not in r.stderr, r.stderr[-3000:]
    assert not (tmp_path / f"{name}.csv.rows.jsonl").exists()  # (the journal gave way to the CSV)
    with out.open() as f:
        return list(csv.DictReader(f)), took


def test_a_raising_and_a_hanging_participant_model_end_their_own_trials_not_the_sweep(tmp_path):
    env = install(tmp_path / "site")
    rows, took = batch(tmp_path, env, "model=walker,raiser,hanger,stuck", 2, "people")
    by_model = {row["model"]: row for row in rows}
    assert list(by_model) == ["walker", "raiser", "hanger", "stuck"] and took < 60.0
    # One stuck where no deadline can interrupt it: its worker process is ended, the row says why.
    stuck = by_model.pop("stuck")
    assert stuck["valid"] == "False" and stuck["end_reason"] == "plugin_failed" and stuck["duration_s"] == ""
    assert (
        stuck["invalid_reasons"]
        == "participant model stuck failed (still running 4 s past its deadline of 1 s, where it cannot be interrupted)"
    )
    assert by_model["walker"]["valid"] == "True" and by_model["walker"]["end_reason"] == "completed"
    assert (
        by_model["raiser"]["invalid_reasons"] == "participant model raiser failed (RuntimeError: the lab's model broke)"
    )
    assert by_model["hanger"]["invalid_reasons"] == f"participant model hanger failed ({HANG} 1 s)"
    for failed in (by_model["raiser"], by_model["hanger"]):
        assert failed["valid"] == "False" and failed["end_reason"] == "plugin_failed"
        assert 1.0 <= float(failed["duration_s"]) < 2.0  # (it walked its FAIL_AFTER_S, then its trial ended)


@pytest.mark.parametrize(("mode", "error"), [("raise", "ValueError: no numbers today"), ("hang", f"{HANG} 10 s")])
def test_a_raising_and_a_hanging_metric_leave_the_row_not_valid_with_the_reason(tmp_path, mode, error):
    env = {**install(tmp_path / "site"), "LAB_METRIC": mode}
    rows, took = batch(tmp_path, env, "model=walker", 1, mode)
    (row,) = rows
    assert took < 60.0 and row["end_reason"] == "completed" and row["valid"] == "False"
    assert row["invalid_reasons"] == f"metric flaky failed ({error})" and row["flaky_error"] == error
    assert float(row["robot_time_to_finish_s"]) > 0  # (the other metrics stand)
