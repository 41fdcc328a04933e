"""One batch-mode trial (simulated participants in this process, no ROS) written as a session
folder: session.json, metrics.json and events.jsonl as `haven run` writes them, without the bag.

session.json is written first with the outcome unknown, so a trial stopped part-way leaves a
folder that says so (a study then runs it again), and completed when the trial has ended; a stop
signal (KeyboardInterrupt) during the trial writes the outcome "interrupted" before it goes on up.
Every file is written whole (atomically): a stop or a crash never leaves half a file.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from haven_scenarios.record.session import (
    EVENTS_FILE,
    METRICS_FILE,
    SESSION_FILE,
    new_session_dir,
    trial_record,
    write_json,
)
from haven_scenarios.run.suite import SuiteConfig
from haven_scenarios.run.trial import run_trial
from haven_scenarios.study.conditions import parse_condition
from haven_scenarios.study.scenario import Scenario
from haven_sim.common import atomic

NO_OUTCOME = "unknown: the batch trial ended before it wrote the outcome"
INTERRUPTED = "interrupted (stopped by a signal)"  # as a recorded trial's (conduct/outcomes.py)


def run_batch_session(
    scenario: Scenario,
    participant: str,
    cues: tuple[str, ...],
    seed: int,
    sessions: Path,
    extra: dict[str, Any],
    suite: SuiteConfig | None = None,
) -> tuple[Path, dict[str, Any]]:
    """Run the trial into a new session folder under `sessions`; (the folder, its metrics)."""
    if any(h.teleoperated for h in scenario.humans):
        raise ValueError(f"scenario {scenario.name} has a teleoperated participant: a batch trial needs simulated ones")
    toggles = parse_condition(cues)
    folder = new_session_dir(sessions, scenario.name, participant)
    info: dict[str, Any] = {
        **trial_record(participant, toggles, seed, scenario),
        "clock": "batch",
        **extra,
        "outcome": NO_OUTCOME,
    }
    write_json(folder / SESSION_FILE, info)
    try:
        result = run_trial(scenario, seed, toggles, suite)
    except KeyboardInterrupt:
        write_json(folder / SESSION_FILE, {**info, "outcome": INTERRUPTED})
        raise
    atomic.write_text(folder / EVENTS_FILE, "".join(e.to_json() + "\n" for e in result.recording.events))
    metrics = {**result.metrics, "participant": participant, "session": folder.name}
    write_json(folder / METRICS_FILE, metrics)
    info.update(
        end_reason=str(result.end_reason),
        duration_s=metrics["duration_s"],
        valid=metrics["valid"],
        outcome=str(result.end_reason),
    )
    info.update(invalid_reasons=metrics.get("invalid_reasons", []))  # (as a recorded trial's session.json says them)
    write_json(folder / SESSION_FILE, info)
    return folder, metrics
