"""The study's mixed model on synthetic data whose participant variance and effects are known."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from haven_scenarios.record.mixed_model import Observation, fit, fit_counts, model_rows
from haven_scenarios.record.study_table import Measure, TrialResults

CONDITIONS = ("none", "path_projection", "turn_signals", "all")
EFFECTS = {"none": 0.0, "path_projection": 0.8, "turn_signals": 0.0, "all": 1.5}


def synthetic(people: int, participant_sd: float, residual_sd: float, seed: int = 1) -> list[Observation]:
    """Each participant sees every condition once, in a rotating order (positions 1..4)."""
    rng = np.random.default_rng(seed)
    out = []
    for k in range(people):
        level = rng.normal(0.0, participant_sd)
        for i in range(len(CONDITIONS)):
            c = CONDITIONS[(i + k) % len(CONDITIONS)]
            out.append(Observation(f"p{k:02d}", c, i + 1, 10.0 + level + EFFECTS[c] + rng.normal(0.0, residual_sd)))
    return out


@pytest.mark.integration  # (a 240-trial fit: seconds of optimisation)
def test_recovers_the_participant_variance_and_the_effects() -> None:
    f = fit(synthetic(200, participant_sd=1.0, residual_sd=0.5), CONDITIONS, "none")
    assert f.converged and not f.singular
    assert f.participant_var is not None and f.residual_var is not None
    assert abs(f.participant_var - 1.0) < 0.25 and abs(f.residual_var - 0.25) < 0.05
    assert f.formula == "value ~ condition + position + (1 | participant)"
    for name, effect in EFFECTS.items():
        if name != "none":
            t = f.term(name)
            assert t is not None and t.ci_low is not None and t.ci_high is not None and t.ci_low < effect < t.ci_high
    all_, zero = f.term("all"), f.term("turn_signals")
    assert all_ is not None and all_.p is not None and all_.p < 1e-6
    assert zero is not None and zero.p is not None and zero.p > 0.001


@pytest.mark.integration  # (a singular or 240-trial fit: seconds of optimisation)
def test_a_robot_that_varies_between_participants_is_a_fixed_effect() -> None:
    # Half the participants with each robot (robot_design: between); the TIAGo adds 2.0 to every value.
    obs = [
        replace(o, robot=r, value=o.value + (2.0 if r == "tiago" else 0.0))
        for o in synthetic(120, 1.0, 0.5)
        for r in [("tiago", "turtlebot2")[int(o.participant[1:]) % 2]]
    ]
    f = fit(obs, CONDITIONS, "none")
    assert (
        f.formula == "value ~ condition + robot + position + (1 | participant)"
        and "robot coded against tiago" in f.note
    )
    robot = f.term("robot:turtlebot2")
    assert (
        robot is not None
        and robot.ci_low is not None
        and robot.ci_high is not None
        and robot.ci_low < -2.0 < robot.ci_high
    )
    same = fit([replace(o, robot="turtlebot2") for o in obs], CONDITIONS, "none")  # one robot: no robot term
    assert "robot" not in same.formula and same.term("robot:turtlebot2") is None


@pytest.mark.integration  # (a singular or 240-trial fit: seconds of optimisation)
def test_identical_participants_give_a_singular_fit_said_plainly() -> None:
    f = fit(synthetic(12, participant_sd=0.0, residual_sd=0.5), CONDITIONS, "none")
    assert f.singular and f.terms
    assert f.participant_var is not None and f.participant_var < 1e-4
    assert "singular fit: participant variance 0" in f.note


def test_nothing_to_fit_is_a_note_not_an_error() -> None:
    flat = [Observation(f"p{k}", c, i + 1, 0.0) for k in range(4) for i, c in enumerate(CONDITIONS)]
    assert fit(flat, CONDITIONS, "none").note == "all values equal (0): nothing to fit"
    no_reference = [o for o in synthetic(6, 1.0, 0.5) if o.condition != "none"]
    assert "reference condition none" in fit(no_reference, CONDITIONS, "none").note
    assert not fit(no_reference, CONDITIONS, "none").terms


def test_position_confounded_with_condition_is_left_out() -> None:
    rng = np.random.default_rng(0)
    same_order = [Observation(f"p{k}", c, i + 1, rng.normal()) for k in range(8) for i, c in enumerate(CONDITIONS)]
    f = fit(same_order, CONDITIONS, "none")
    assert "position" not in f.formula and "position left out: confounded with condition" in f.note


def test_report_rows_one_per_term_and_the_singular_count() -> None:
    results = []
    for o in synthetic(10, participant_sd=1.0, residual_sd=0.5):
        design = {
            "participant": o.participant,
            "practice": False,
            "valid": True,
            "scenario": "hallway",
            "condition": o.condition,
        }
        design["order_position"] = o.position
        results.append(TrialResults(design, (Measure("h1", "detour_m", o.value), Measure("", "flat_m", 1.0))))
    rows = model_rows(results, [("detour_m", True), ("flat_m", False), ("absent", False)], CONDITIONS)
    detour = [r for r in rows if r["measure"] == "detour_m"]
    assert [r["term"] for r in detour] == ["intercept", "path_projection", "turn_signals", "all", "position"]
    assert all(r["human"] == "person" and r["participants"] == 10 and r["trials"] == 40 for r in detour)
    flat = [r for r in rows if r["measure"] == "flat_m"]
    assert len(flat) == 1 and flat[0]["term"] == "" and "nothing to fit" in flat[0]["note"]
    assert fit_counts(rows) == (0, 0, 1)
