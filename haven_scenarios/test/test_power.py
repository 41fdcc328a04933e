"""Power by resampling a pool: on synthetic pools whose effect is known, and on the shipped study."""

from __future__ import annotations

import csv
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from haven_scenarios.record.mixed_model import Observation
from haven_scenarios.record.power import Question, cell, draw, estimate, pool_effect, wilson
from haven_scenarios.study.schedule import williams

CONDITIONS = ("none", "path_projection", "turn_signals", "all")
ORDERS = [tuple(CONDITIONS[i] for i in row) for row in williams(4)]


def pool(
    people: int,
    effect: float,
    participant_sd: float = 1.0,
    residual_sd: float = 0.5,
    seed: int = 3,
    effect_sd: float = 0.0,
) -> list[Observation]:
    """A simulated pool: participant k ran Williams order k mod 4; `all` is `effect` above the rest
    (`effect_sd`: how much that effect varies between participants)."""
    rng = np.random.default_rng(seed)
    out = []
    for k in range(people):
        level, own = rng.normal(0.0, participant_sd), effect + rng.normal(0.0, effect_sd)
        for position, c in enumerate(ORDERS[k % 4], 1):
            out.append(
                Observation(
                    f"p{k:02d}", c, position, 5.0 + level + (own if c == "all" else 0.0) + rng.normal(0.0, residual_sd)
                )
            )
    return out


def question(effect: float, reps: int = 200) -> Question:
    return Question("x_m", False, "all", "none", effect, CONDITIONS, alpha=0.05, reps=reps, seed=1)


def slots(n: int) -> list[tuple[str, ...]]:
    return [ORDERS[k % 4] for k in range(n)]


def test_the_pool_is_shifted_to_the_effect_asked_keeping_its_spread() -> None:
    raw = pool(40, effect=0.7)
    c = cell(question(2.0), "s", 8, slots(8), raw)
    assert c.pool_size == 40 and abs(c.pool_effect - pool_effect(raw, question(2.0))) < 1e-12
    shifted = [o for trials in c.pool.values() for k, person in enumerate(trials) for o in c.shifted(person, k, 2.0)]
    assert abs(pool_effect(shifted, question(2.0)) - 2.0) < 1e-9
    for name in ("none", "turn_signals"):  # other conditions untouched, spread kept
        assert sorted(o.value for o in shifted if o.condition == name) == sorted(
            o.value for o in raw if o.condition == name
        )
    assert np.std([o.value for o in shifted if o.condition == "all"]) == pytest.approx(
        np.std([o.value for o in raw if o.condition == "all"])
    )


@pytest.mark.integration  # (a Monte Carlo of hundreds of model fits)
def test_no_effect_is_detected_about_alpha_of_the_time_and_a_huge_one_always() -> None:
    raw = pool(48, effect=0.0)
    null = estimate(cell(question(0.0, reps=100), "s", 12, slots(12), raw))
    assert null.failed == 0 and null.singular < 10
    # alpha 0.05 (the Wald test of 12 participants runs a little over it); 100 replicates: 2 binomial SDs is 0.045
    assert 0.0 <= null.power <= 0.15
    assert null.false_positives == null.detected and not null.anticonservative()  # (at E = 0 both fits are the same)
    huge = estimate(cell(question(5.0, reps=20), "s", 12, slots(12), raw))
    assert huge.power == 1.0 and huge.mean_estimate == pytest.approx(5.0, abs=0.3)
    small_n = estimate(cell(question(0.4, reps=40), "s", 4, slots(4), raw))
    large_n = estimate(cell(question(0.4, reps=40), "s", 24, slots(24), raw))
    assert small_n.power < large_n.power


@pytest.mark.integration  # (a Monte Carlo of hundreds of model fits)
def test_deterministic_participants_give_singular_fits_counted() -> None:
    raw = pool(16, effect=1.0, participant_sd=0.0)
    got = estimate(cell(question(1.0, reps=20), "s", 8, slots(8), raw))
    assert got.singular > 0 and got.row()["singular"] == got.singular


def test_an_order_missing_from_the_pool_is_a_one_line_error() -> None:
    with pytest.raises(ValueError, match=r"no pool participant ran the order .* use a larger --pool"):
        cell(question(1.0), "s", 4, slots(4), pool(3, effect=1.0))
    with pytest.raises(ValueError, match="no valid trial of x_m in condition all"):
        pool_effect([o for o in pool(4, 1.0) if o.condition != "all"], question(1.0))


def test_wilson_interval() -> None:
    low, high = wilson(8, 10)  # Wilson (1927): 0.8 of 10 -> 0.490..0.943
    assert low == pytest.approx(0.4902, abs=1e-3) and high == pytest.approx(0.9433, abs=1e-3)
    assert wilson(0, 200)[0] == 0.0 and wilson(200, 200)[1] == pytest.approx(1.0)


@pytest.mark.integration
def test_power_on_the_shipped_study_prints_four_participant_counts(tmp_path: Path) -> None:
    cmd = [sys.executable, "-m", "haven_scenarios.tools.cli", "study", "power", "haven_paper",
           "--metric", "time_to_finish_s", "--effect", "-2", "--scenario", "hallway",
           "--participants", "4,8,12,16", "--reps", "10", "--pool", "4", "--out", str(tmp_path)]  # fmt: skip
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    out = done.stdout
    # (--scenario: its 4 trials each, no others)
    assert "pool: 4 simulated participant(s) (16 trial(s) simulated now)" in out
    for n in (4, 8, 12, 16):
        assert any(line.split()[:2] == ["hallway", str(n)] for line in out.splitlines()), out
    rows = list(csv.DictReader((tmp_path / "power_time_to_finish_s_all-none_E-2.csv").open()))
    assert {int(r["participants"]) for r in rows} == {4, 8, 12, 16} and all(
        0.0 <= float(r["power"]) <= 1.0 for r in rows
    )
    assert (tmp_path / "power_time_to_finish_s_all-none_E-2.png").stat().st_size > 10_000
    again = subprocess.run(cmd, capture_output=True, text=True, timeout=600)  # the pool is reused, the numbers repeat
    assert again.stdout.split("pool:")[1] == out.split("pool:")[1].replace(
        "(16 trial(s) simulated now)", "(0 trial(s) simulated now)"
    )


@pytest.mark.integration  # (a Monte Carlo of hundreds of model fits)
def test_a_test_that_finds_absent_effects_too_often_is_flagged() -> None:
    # The effect of `all` varies between people (sd 3) far beyond the trial-to-trial spread (0.2): a
    # random-intercept model's one residual understates the C - R contrast's spread.
    varied = pool(48, effect=1.0, residual_sd=0.2, effect_sd=3.0)
    r = estimate(cell(question(1.0, reps=100), "s", 12, slots(12), varied))
    # (14 of 100: its interval starts at 0.085)
    assert r.false_positive_rate > 0.1 and r.anticonservative(), r.false_positive_rate


def test_a_pool_too_thin_for_the_orders_a_study_needs_is_said() -> None:
    raw = pool(4, effect=1.0)  # one pool participant per order
    assert cell(question(1.0), "s", 4, slots(4), raw).thin() == []
    thin = cell(question(1.0), "s", 8, slots(8), raw).thin()  # two slots per order, one person who ran it
    assert [(n, have) for _, n, have in thin] == [(2, 1)] * 4


def test_a_metric_is_checked_before_any_trial_is_simulated() -> None:
    from haven_scenarios.conduct.power_pool import check_metric
    from haven_scenarios.study.protocol import load_study

    paper = load_study("haven_paper")
    for fine in (
        "time_to_finish_s",
        "hunav_avg_distance_to_closest_person_m",
        "intimate_centre_intrusion_s",
        "path_length_m",
    ):
        check_metric(fine, paper)
    with pytest.raises(ValueError, match=r"^--metric: no measure 'time_to_finsh_s': did you mean time_to_finish_s\?$"):
        check_metric("time_to_finsh_s", paper)
    with pytest.raises(
        ValueError,
        match=r"^--metric: godspeed_safety is a questionnaire score: simulated participants answer no questionnaire$",
    ):
        check_metric("godspeed_safety", paper)


@pytest.mark.integration  # (a Monte Carlo of model fits)
def test_a_power_of_one_is_drawn(tmp_path: Path) -> None:
    # (60 replicates all detecting: the Wilson interval's top is 1 less a rounding error, below the power)
    sure = estimate(cell(question(5.0, reps=60), "s", 8, slots(8), pool(16, effect=0.0)))
    assert sure.power == 1.0
    assert draw([sure], tmp_path / "p.png", "t").stat().st_size > 5_000
