"""A study's results as tables: long (tidy) and wide.

Long (`study_long.csv`), one row per participant x trial x measure, the layout R's tidyverse and
pandas expect: the design columns, then `human` (empty for a measure of the trial or the robot,
the person's id for a per-person metric `<h>_x`, which becomes measure `x`, and for a
questionnaire score), `measure` and `value`. Wide (`study_wide.csv`), one row per trial: the
design columns, then one column per measure (per-person ones named `<h>_<measure>` again).
Only numeric values are measures (strings such as the robot's gem order stay in metrics.json).
Every trial with a finished session is in both, valid or not (`valid` says which to keep).
"""

from __future__ import annotations

import json
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from haven_scenarios.record.codebook import Codebook
from haven_scenarios.record.progress import TrialProgress
from haven_scenarios.record.session import METRICS_FILE, analyse, session_info
from haven_scenarios.study.questionnaires import ANSWERS_FILE
from haven_sim.robots.robot_kind import DEFAULT_ROBOT

# The order columns: `order_position` the trial's place in the participant's session (practice
# first), `block` the scenario block's place (0 for practice), `position_in_block`, and
# `previous_condition` (the trial before in the same block; empty for a block's first); `sequence`
# is the participant's sequence of the design (study/schedule.py): what a carry-over model needs.
# `robot` is the robot's name: the study's robot factor (study/study_robots.py), else the scenario's.
ORDER = ("sequence", "order_position", "block", "position_in_block", "previous_condition")
DESIGN = (
    "participant",
    "trial_id",
    *ORDER,
    "practice",
    "scenario",
    "condition",
    "robot",
    "seed",
    "valid",
    "end_reason",
    "session",
)
LONG = (*DESIGN[:1], "human", *DESIGN[1:], "measure", "unit", "value")  # unit: as in codebook.csv
NOT_MEASURES = ("seed", "valid")  # numbers in metrics.json that are design columns


@dataclass(frozen=True)
class Measure:
    human: str  # "" for the trial's or the robot's
    measure: str
    value: float

    @property
    def column(self) -> str:
        return f"{self.human}_{self.measure}" if self.human else self.measure


@dataclass(frozen=True)
class TrialResults:
    design: dict[str, Any]
    measures: tuple[Measure, ...]


def _metrics(folder: Path) -> dict[str, Any]:
    """metrics.json, or computed from the bag when there is none (flagged not valid if unreadable)."""
    try:
        data = json.loads((folder / METRICS_FILE).read_text(encoding="utf-8"))
        if isinstance(data, dict):
            return data
    except (OSError, ValueError):
        pass
    if (folder / "bag").is_dir():
        return analyse(folder)[0]
    return {"valid": False, "invalid_reasons": [f"no readable {METRICS_FILE} and no bag"]}


def _number(v: Any) -> float | None:
    return float(v) if isinstance(v, (int, float)) and not isinstance(v, bool) else None


def split_measures(metrics: dict[str, Any], humans: Sequence[str]) -> list[Measure]:
    """Numeric metrics as measures; `<h>_x` for a listed person becomes (h, x)."""
    out = []
    for key, v in metrics.items():
        value = _number(v)
        if value is None or key in NOT_MEASURES:
            continue
        human = next((h for h in sorted(humans, key=len, reverse=True) if key.startswith(h + "_")), "")
        out.append(Measure(human, key[len(human) + 1 :] if human else key, value))
    return out


def questionnaire_measures(folder: Path) -> tuple[list[Measure], str]:
    """The questionnaire scores in a session folder's ANSWERS_FILE, and what was wrong with it, if anything."""
    path = folder / ANSWERS_FILE
    if not path.exists():
        return [], ""
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as e:
        return [], f"{ANSWERS_FILE} unreadable: {str(e)[:80]}"
    out = []
    if not isinstance(data, dict):
        return [], f"{ANSWERS_FILE} is not a mapping of person to questionnaires"
    for human, sheets in sorted(data.items()):
        for _q, record in sorted(sheets.items()) if isinstance(sheets, dict) else []:
            scores = record.get("scores") if isinstance(record, dict) else None
            for name, v in sorted(scores.items()) if isinstance(scores, dict) else []:
                if _number(v) is not None:
                    out.append(Measure(str(human), str(name), float(v)))
    return out, ""


def trial_results(p: TrialProgress) -> TrialResults | None:
    """A done trial's design columns and measures; None for a trial not done."""
    folder = p.session
    if folder is None:
        return None
    t, info = p.trial, session_info(folder)
    metrics = _metrics(folder)
    humans = [str(h) for h in info.get("humans", [])]
    answers, problem = questionnaire_measures(folder)
    valid = bool(metrics.get("valid", False)) and not problem
    design = {
        "participant": t.participant,
        "trial_id": t.trial_id,
        "sequence": t.sequence,
        "order_position": t.position,
        "block": t.block,
        "position_in_block": t.position_in_block,
        "previous_condition": t.previous_condition,
        "practice": t.practice,
        "scenario": t.scenario,
        "condition": t.condition,
        # (a session from before robots: TurtleBot2)
        "robot": t.robot_name or str(info.get("robot_name", DEFAULT_ROBOT)),
        "seed": t.seed,
        "valid": valid,
        "end_reason": metrics.get("end_reason", info.get("end_reason", "")),
        "session": str(folder.relative_to(folder.parents[2])),
    }
    return TrialResults(design, (*split_measures(metrics, humans), *answers))


def long_rows(results: Sequence[TrialResults], unit: Callable[[str, str], str] | None = None) -> list[dict[str, Any]]:
    """`unit(human, measure)`: the codebook's (default: metrics and registered questionnaires)."""
    unit = unit or Codebook().unit
    return [
        {**r.design, "human": m.human, "measure": m.measure, "unit": unit(m.human, m.measure), "value": m.value}
        for r in results
        for m in r.measures
    ]


def wide_rows(results: Sequence[TrialResults]) -> list[dict[str, Any]]:
    return [{**r.design, **{m.column: m.value for m in r.measures}} for r in results]
