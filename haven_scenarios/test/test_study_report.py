"""The study report's pure parts: measures split per person, finished outcomes, long vs wide, summary statistics."""

from __future__ import annotations

import statistics

import pytest

from haven_scenarios.record.study_summary import summary_rows
from haven_scenarios.record.study_table import Measure, TrialResults, long_rows, split_measures, wide_rows
from haven_scenarios.study.progress import finished


def test_per_person_metrics_become_human_and_measure_and_strings_are_not_measures() -> None:
    metrics = {"min_human_centre_distance_m": 1.2, "h1_detour_m": 0.4, "h12_detour_m": 0.9, "h1_contacts": 0, "robot_gem_order": "rg1 rg2",
               "valid": True, "seed": 4, "pass_signal_lead_s_median": None, "end_reason": "completed"}  # fmt: skip
    got = split_measures(metrics, ["h1", "h12"])
    assert got == [
        Measure("", "min_human_centre_distance_m", 1.2),
        Measure("h1", "detour_m", 0.4),
        Measure("h12", "detour_m", 0.9),
        Measure("h1", "contacts", 0.0),
    ]
    assert [m.column for m in got] == ["min_human_centre_distance_m", "h1_detour_m", "h12_detour_m", "h1_contacts"]


@pytest.mark.parametrize(
    "outcome, done",
    [
        ("completed", True),
        ("timeout", True),
        ("stopped", True),
        ("contact; bag repaired (120 messages recovered)", True),
        ("aborted", False),  # the researcher called it off: it runs again
        ("interrupted (stopped by a signal)", False),
        ("cut short: planner exited with code 1", False),
        ("unknown: haven run ended before it wrote the outcome", False),
        (None, False),
    ],
)
def test_finished_outcomes(outcome: object, done: bool) -> None:
    assert finished(outcome) is done


def result(participant: str, condition: str, value: float, valid: bool = True, practice: bool = False) -> TrialResults:
    design = {"participant": participant, "trial_id": f"s-{condition}", "practice": practice, "scenario": "s", "condition": condition, "valid": valid}
    return TrialResults(design, (Measure("", "x_m", value), Measure("h1", "nasa_tlx_raw", value * 10)))


def test_long_and_wide_hold_the_same_values() -> None:
    results = [result("p1", "none", 1.0), result("p1", "all", 2.0)]
    long, wide = long_rows(results), wide_rows(results)
    assert len(long) == 4 and len(wide) == 2
    for row in long:  # pivoting the long table gives the wide one
        column = f"{row['human']}_{row['measure']}" if row["human"] else row["measure"]
        assert next(w for w in wide if w["trial_id"] == row["trial_id"])[column] == row["value"]


def test_summary_leaves_out_practice_counts_invalid_apart_and_keeps_the_condition_order() -> None:
    values = [1.0, 2.5, 4.0]
    results = [result(f"p{k}", "none", v) for k, v in enumerate(values)]
    results += [result("p9", "none", 100.0, valid=False), result("p1", "all", 3.0), result("p1", "none", 50.0, practice=True)]
    rows = summary_rows(results, ["none", "all"])
    assert [(r["condition"], r["human"], r["measure"]) for r in rows] == [
        ("none", "", "x_m"),
        ("none", "h1", "nasa_tlx_raw"),
        ("all", "", "x_m"),
        ("all", "h1", "nasa_tlx_raw"),
    ]
    none = rows[0]
    assert (none["n"], none["n_invalid"]) == (3, 1)
    assert none["mean"] == pytest.approx(statistics.fmean(values)) and none["sd"] == pytest.approx(statistics.stdev(values)) and none["median"] == 2.5
    assert rows[2]["n"] == 1 and rows[2]["sd"] is None  # one trial: no spread
