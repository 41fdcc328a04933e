"""Batch mode: many seeded trials of a scenario without DDS, one CSV row each."""

from __future__ import annotations

import csv
import sys
import time
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any, TextIO

from haven_scenarios.record.report import csv_row
from haven_scenarios.run.suite import SuiteConfig
from haven_scenarios.run.trial import TrialResult, run_trial
from haven_scenarios.study.rules import EndReason
from haven_scenarios.study.scenario import Scenario
from haven_viz.cues import Toggles


def progress_bar(done: int, total: int, started: float, out: TextIO = sys.stderr) -> None:
    elapsed = time.monotonic() - started
    if not out.isatty():  # a log, not a terminal: one line at the end
        if done == total:
            out.write(f"{done}/{total} trials in {elapsed:.1f} s\n")
        return
    width = 30
    filled = int(width * done / max(total, 1))
    eta = elapsed / done * (total - done) if done else 0.0
    out.write(f"\r[{'#' * filled}{'.' * (width - filled)}] {done}/{total} trials  {elapsed:5.1f} s  eta {eta:5.1f} s")
    if done == total:
        out.write("\n")
    out.flush()


def run_batch(
    scenario: Scenario,
    trials: int,
    seed: int,
    toggles: Toggles,
    csv_path: Path,
    on_trial: Callable[[int, TrialResult], None] | None = None,
    suite: SuiteConfig | None = None,
) -> list[dict[str, Any]]:
    """Trials with seeds seed, seed + 1, ...; the CSV is written row by row (a crash loses nothing)."""
    rows: list[dict[str, Any]] = []
    csv_path.parent.mkdir(parents=True, exist_ok=True)
    with csv_path.open("w", newline="") as f:
        writer: csv.DictWriter[str] | None = None
        for i in range(trials):
            result = run_trial(scenario, seed + i, toggles, suite)
            row = {"trial": i, "seed": seed + i, **result.metrics}
            flat = csv_row(row)
            if writer is None:
                writer = csv.DictWriter(f, fieldnames=list(flat), extrasaction="ignore")
                writer.writeheader()
            writer.writerow(flat)
            f.flush()
            rows.append(row)
            if on_trial is not None:
                on_trial(i, result)
    return rows


def summary(rows: Sequence[dict[str, Any]]) -> str:
    n = len(rows)
    done = sum(1 for r in rows if r["end_reason"] == EndReason.COMPLETED)
    times = [r["robot_time_to_finish_s"] for r in rows if r["robot_time_to_finish_s"] is not None]
    mean_t = sum(times) / len(times) if times else float("nan")
    contacts = sum(r["human_contacts"] for r in rows)
    dmin = min((r["min_human_distance_m"] for r in rows if r["min_human_distance_m"] is not None), default=float("nan"))
    return f"{done}/{n} completed, robot finishes in {mean_t:.1f} s on average, {contacts} human contact(s), closest approach {dmin:.2f} m"
