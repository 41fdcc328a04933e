"""Batch mode: a sweep of seeded trials without DDS, one CSV row each, on every core or a cluster.

Rows are journaled as the trials finish (`<csv>.rows.jsonl`, flushed line by line: a crash or a
Ctrl-C loses no finished trial), then the CSV is written in trial order with every column any row
has (scenarios with more participants have more columns) and the journal removed.
"""

from __future__ import annotations

import json
import sys
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Any, TextIO

from tqdm import tqdm

from haven_scenarios.record.metric_table import rows as metric_rows
from haven_scenarios.record.report import write_table
from haven_scenarios.run.grid import TrialSpec
from haven_scenarios.run.suite import SuiteConfig
from haven_scenarios.run.sweep import Row, run_rows
from haven_scenarios.study.rules import EndReason
from haven_viz.cues import CUE_SPECS, CUES

NOT_DESIGN = ("trial", "seed")  # design columns that do not make a group of the summary
MAX_SUMMARY_LINES = 24


class Progress:
    """Trials done of the total with rate and ETA: a tqdm bar on a terminal; elsewhere (a log, nohup)
    one line every `LOG_EVERY_S` and one at the end."""

    LOG_EVERY_S = 30.0

    def __init__(self, total: int, out: TextIO | None = None) -> None:
        out = out if out is not None else sys.stderr  # (the stream of the moment, not of import time)
        self.total, self.out, self.started, self.done = total, out, time.monotonic(), 0
        self.bar = tqdm(total=total, unit="trial", file=out, smoothing=0.05) if out.isatty() else None
        self.logged = self.started

    def update(self, done: int) -> None:
        if self.bar is not None:
            self.bar.update(done - self.done)
        self.done = done
        now = time.monotonic()
        if self.bar is None and now - self.logged >= self.LOG_EVERY_S and done < self.total:
            self.logged = now
            rate = done / (now - self.started)
            eta = (self.total - done) / rate if rate > 0 else float("inf")
            self.out.write(
                f"{done}/{self.total} trials in {now - self.started:.0f} s, "
                f"{rate * 60:.0f} trials/min, about {eta:.0f} s to go\n"
            )
            self.out.flush()

    def close(self, finished: bool = True) -> None:
        """`finished`: the sweep ran to its end (a log gets its one line then, not after an error)."""
        if self.bar is not None:
            self.bar.close()
        elif finished:
            self.out.write(f"{self.done}/{self.total} trials in {time.monotonic() - self.started:.1f} s\n")


def journal_path(csv_path: Path) -> Path:
    return csv_path.with_name(csv_path.name + ".rows.jsonl")


def write_csv(rows: Sequence[Row], path: Path) -> None:
    """The rows in trial order under the union of their columns, written whole (`write_table`)."""
    write_table(path, sorted(rows, key=lambda r: r["trial"]))


def run_batch(
    specs: Sequence[TrialSpec],
    csv_path: Path,
    suite: SuiteConfig | None = None,
    workers: int = 1,
    cluster: str | None = None,
    progress: Progress | None = None,
) -> list[Row]:
    """Run the sweep (`workers` processes, or on the Dask `cluster`) into the CSV; rows in trial order."""
    csv_path.parent.mkdir(parents=True, exist_ok=True)
    journal = journal_path(csv_path)
    rows: list[Row] = []
    try:
        with journal.open("w") as j:
            for row in run_rows(specs, suite, workers, cluster):
                j.write(json.dumps(row) + "\n")
                j.flush()
                rows.append(row)
                if progress is not None:
                    progress.update(len(rows))
    finally:
        if not rows:  # (nothing ran: a cluster not reached, say) no journal of nothing
            journal.unlink(missing_ok=True)
    rows.sort(key=lambda r: r["trial"])
    write_csv(rows, csv_path)
    journal.unlink()
    return rows


def summary(rows: Sequence[dict[str, Any]]) -> str:
    n = len(rows)
    done = sum(1 for r in rows if r["end_reason"] == EndReason.COMPLETED)
    # (.get: a trial a plugin ended before it began has none of these)
    times = [r["robot_time_to_finish_s"] for r in rows if r.get("robot_time_to_finish_s") is not None]
    finish = (
        f"robot finishes in {sum(times) / len(times):.1f} s on average" if times else "the robot finished in no trial"
    )
    contacts = sum(r.get("human_contacts") or 0 for r in rows)
    distances = [r["min_human_centre_distance_m"] for r in rows if r.get("min_human_centre_distance_m") is not None]
    closest = (
        f"closest approach {min(distances):.2f} m (the least of any trial)" if distances else "no person in any trial"
    )
    failed = sum(1 for r in rows if r["end_reason"] == EndReason.PLUGIN_FAILED)
    plugins = f", {failed} ended by a plugin that failed (see invalid_reasons)" if failed else ""
    return (
        f"{done}/{n} completed{plugins}, {finish}, {contacts} human "
        f"contact(s), {closest}{_people(rows)}{_exposure(rows)}"
    )


def _exposure(rows: Sequence[dict[str, Any]]) -> str:
    """How long each cue was shown, averaged over the trials (the cues shown at all)."""
    said = []
    for name in CUES:
        values = [r.get(CUE_SPECS[name].exposure) for r in rows]
        mean = sum(v for v in values if isinstance(v, (int, float))) / len(values) if values else 0.0
        if mean > 0:
            said.append(f"{name} {mean:.1f} s")
    return f"; cues shown: {', '.join(said)}" if said else "; no cue shown"


def _people(rows: Sequence[dict[str, Any]]) -> str:
    """The people's own walk, averaged over the trials and their people: time to finish, path length, hesitations."""
    trial_level = {m[0] for m in metric_rows()}  # (robot_path_length_m, hunav_path_length_m, ...: not a person's)
    said = []
    for suffix, label, unit in (
        ("_time_to_finish_s", "finish in", " s"),
        ("_path_length_m", "walk", " m"),
        ("_hesitations", "hesitate", "x"),
    ):
        values = [
            v
            for r in rows
            for k, v in r.items()
            if k.endswith(suffix) and k not in trial_level and isinstance(v, (int, float))
        ]
        if values:
            said.append(f"{label} {sum(values) / len(values):.1f}{unit}")
    return f"; people {', '.join(said)} on average" if said else ""


def group_summaries(specs: Sequence[TrialSpec], rows: Sequence[Row]) -> list[str]:
    """One summary line per design group (scenario, condition, model, robot where it varies, grid
    parameters; all seeds)."""
    groups: dict[str, list[Row]] = {}
    skip = (*NOT_DESIGN, *(("robot",) if len({s.scenario.robot.name for s in specs}) <= 1 else ()))
    for spec, row in zip(specs, rows, strict=True):
        label = ", ".join(f"{v}" if k == "scenario" else f"{k} {v}" for k, v in spec.columns().items() if k not in skip)
        groups.setdefault(label, []).append(row)
    lines = [f"{label}: {summary(g)}" for label, g in groups.items()]
    if len(lines) > MAX_SUMMARY_LINES:
        lines = [*lines[:MAX_SUMMARY_LINES], f"... and {len(lines) - MAX_SUMMARY_LINES} more groups (see the CSV)"]
    return lines
