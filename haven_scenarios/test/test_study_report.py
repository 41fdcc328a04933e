"""The study report's pure parts: measures split per person, finished outcomes, long vs wide, summary statistics."""

from __future__ import annotations

import statistics
from pathlib import Path

import pytest

from haven_scenarios.record.progress import finished
from haven_scenarios.record.study_summary import summary_rows
from haven_scenarios.record.study_table import Measure, TrialResults, long_rows, split_measures, wide_rows


def test_per_person_metrics_become_human_and_measure_and_strings_are_not_measures() -> None:
    metrics = {"min_human_centre_distance_m": 1.2, "h1_detour_m": 0.4, "h12_detour_m": 0.9, "h1_contacts": 0,
               "robot_gem_order": "rg1 rg2", "valid": True, "seed": 4, "pass_signal_lead_s_median": None,
               "end_reason": "completed"}  # fmt: skip
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
        ("plugin_failed", True),  # it ended, not valid with the reason: the study goes on (a plugin fails again)
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
    design = {
        "participant": participant,
        "trial_id": f"s-{condition}",
        "practice": practice,
        "scenario": "s",
        "condition": condition,
        "valid": valid,
    }
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
    results += [
        result("p9", "none", 100.0, valid=False),
        result("p1", "all", 3.0),
        result("p1", "none", 50.0, practice=True),
    ]
    rows = summary_rows(results, ["none", "all"])
    assert [(r["condition"], r["human"], r["measure"]) for r in rows] == [
        ("none", "", "x_m"),
        ("none", "h1", "nasa_tlx_raw"),
        ("all", "", "x_m"),
        ("all", "h1", "nasa_tlx_raw"),
    ]
    none = rows[0]
    assert (none["n"], none["n_invalid"]) == (3, 1)
    assert (
        none["mean"] == pytest.approx(statistics.fmean(values))
        and none["sd"] == pytest.approx(statistics.stdev(values))
        and none["median"] == 2.5
    )
    assert rows[2]["n"] == 1 and rows[2]["sd"] is None  # one trial: no spread


def test_summary_pairs_participants_against_the_reference_with_intervals_and_d_z() -> None:
    none, cued = [1.0, 2.0, 3.0, 4.0], [1.5, 2.0, 4.0, 5.5]  # paired differences 0.5, 0, 1, 1.5
    results = [result(f"p{k}", "none", v) for k, v in enumerate(none)] + [
        result(f"p{k}", "all", v) for k, v in enumerate(cued)
    ]
    results.append(result("p9", "all", 9.0))  # no reference trial: in the condition's mean, not in the pairs
    rows = {(r["condition"], r["measure"]): r for r in summary_rows(results, ["none", "all"])}
    ref, row = rows[("none", "x_m")], rows[("all", "x_m")]
    assert ref["participants"] == 4 and "diff_mean" not in ref
    assert ref["ci_low"] == pytest.approx(2.5 - 3.1824 * statistics.stdev(none) / 2, abs=1e-3)  # t(0.975, 3) = 3.1824
    diffs = [0.5, 0.0, 1.0, 1.5]
    assert row["reference"] == "none" and row["diff_n"] == 4 and row["diff_mean"] == pytest.approx(0.75)
    assert row["d_z"] == pytest.approx(0.75 / statistics.stdev(diffs), abs=1e-4)
    half = 3.1824 * statistics.stdev(diffs) / 2
    assert (row["diff_ci_low"], row["diff_ci_high"]) == (
        pytest.approx(0.75 - half, abs=1e-3),
        pytest.approx(0.75 + half, abs=1e-3),
    )
    assert rows[("all", "x_m")]["participants"] == 5


def test_summary_axes_keep_a_least_span_and_questionnaires_their_scale() -> None:
    from haven_scenarios.record.study_summary import Panel, _limits

    low, high = _limits(Panel("hesitations", True, "", None, 2.0), 0.0, 0.0, nonnegative=True)
    # equal values: not an axis of +-0.04, and no negative counts
    assert high - low >= 2.0 and low <= 0.0 and low > -0.2
    low, high = _limits(Panel("detour_m", True, "", None, 0.5), 1.0, 1.01, nonnegative=True)
    assert high - low == pytest.approx(0.55) and low < 1.0 < 1.01 < high
    assert _limits(Panel("nasa_tlx_raw", True, "", (0.0, 100.0)), 40.0, 41.0, nonnegative=True) == (-5.0, 105.0)


def test_summary_picture_is_drawn_with_lines_per_participant(tmp_path: Path) -> None:
    from haven_scenarios.record.study_summary import draw

    results = [result(f"p{k}", c, k + (0.5 if c == "all" else 0.0)) for k in range(4) for c in ("none", "all")]
    # x_m is not a main measure: nothing to draw
    assert draw(results, ["none", "all"], [], tmp_path / "s.png", "t") is None
    results = [TrialResults(r.design, (Measure("h1", "detour_m", r.measures[0].value),)) for r in results]
    out = draw(results, ["none", "all"], [], tmp_path / "s.png", "t")
    assert out is not None and out.stat().st_size > 10_000
