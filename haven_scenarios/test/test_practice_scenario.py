"""The practice room: every shipped participant model finishes it, with and without cues, never
touching the robot, and the robot's part is short (so practice is about the controls, not the robot)."""

from __future__ import annotations

import dataclasses

import pytest

from haven_scenarios.run.trial import run_trial
from haven_scenarios.study.conditions import parse_condition
from haven_scenarios.study.scenario import load_scenario

pytestmark = pytest.mark.integration


@pytest.mark.parametrize("model", ["walker", "yielder", "blocker"])
@pytest.mark.parametrize("condition", ["none", "all"])
def test_every_participant_model_completes_the_practice(model: str, condition: str) -> None:
    base = load_scenario("practice")
    assert base.kind == "retrieval" and base.world.name == "practice"
    scenario = dataclasses.replace(base, humans=tuple(dataclasses.replace(h, model=model) for h in base.humans))
    for seed in (0, 1):
        m = run_trial(scenario, seed, parse_condition([condition])).metrics
        assert m["end_reason"] == "completed" and m["valid"], m
        assert m["human_contacts"] == 0 and m["robot_time_to_finish_s"] < 15.0
        assert m["duration_s"] < base.timeout_s / 2  # well within the practice's time limit
