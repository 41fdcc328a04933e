"""Seeded pilot sweeps show the cue effects the participant model assumes (batch mode).

These are the model's assumptions played out, not findings about people (study/person.py says
which figures are measured and which are ours). In the hallway the person meets the robot head-on.
With the cues (`all`) they see its projected path (and turn signal) from the room's door on, so
they move to the far side early and walk on; without them (`none`) they read only its motion, one
reaction time late, and slow down while it closes in, in their way, until it turns aside. In the
shared room with crossing ways (Walker et al. 2018) the shown path makes them step aside or give
way early where it crosses theirs: they walk farther and finish later, a human-side effect that
no threshold decides. People differ and sometimes misread a cue, so the claims are means over
seeds, with margins well inside what the model gives.
"""

from dataclasses import replace
from statistics import mean

import pytest

from haven_scenarios.run.trial import run_trial
from haven_scenarios.study.conditions import parse_condition
from haven_scenarios.study.scenario import load_scenario

pytestmark = pytest.mark.integration

SEEDS = range(8)
BEHAVIOUR = (
    "h1_path_length_m",
    "h1_detour_m",
    "h1_time_to_finish_s",
    "h1_min_centre_distance_m",
    "h1_time_not_moving_s",
    "avg_closest_human_centre_distance_m",
)


def sweep(name, condition, seeds=SEEDS, model=None):
    s = load_scenario(name)
    if model is not None:
        s = replace(s, humans=tuple(replace(h, model=model) for h in s.humans))
    return [run_trial(s, seed, parse_condition(condition)).metrics for seed in seeds]


def avg(rows, key):
    return mean(r[key] for r in rows)


def test_in_the_hallway_cues_spare_hesitation_and_the_person_passes_sooner():
    cued, blind = sweep("hallway", ["all"]), sweep("hallway", ["none"])
    for r in cued + blind:
        assert r["end_reason"] == "completed" and r["human_contacts"] == 0, (r["seed"], r["condition"])
    assert avg(blind, "h1_hesitations") - avg(cued, "h1_hesitations") >= 0.4
    assert avg(blind, "h1_hesitation_s") - avg(cued, "h1_hesitation_s") >= 0.8
    assert avg(blind, "h1_time_to_finish_s") - avg(cued, "h1_time_to_finish_s") >= 0.3
    assert avg(cued, "h1_path_length_m") - avg(blind, "h1_path_length_m") >= 0.03  # the early side step


def test_in_the_crossing_room_the_cues_change_the_persons_own_walk():
    cued, blind = sweep("shared_room_crossing", ["all"], range(10)), sweep("shared_room_crossing", ["none"], range(10))
    for r in cued + blind:
        assert r["end_reason"] == "completed" and r["human_contacts"] == 0, (r["seed"], r["condition"])
    longer = [c["h1_path_length_m"] - b["h1_path_length_m"] for c, b in zip(cued, blind, strict=True)]
    assert mean(longer) >= 0.8 and sum(d > 0 for d in longer) >= 8  # they step aside early, seed after seed
    assert avg(cued, "h1_time_to_finish_s") - avg(blind, "h1_time_to_finish_s") >= 1.0


@pytest.mark.parametrize("model", ["walker", "blocker", "yielder"])
def test_every_participant_model_crosses_the_room_without_contact(model):
    for r in sweep("shared_room_crossing", ["all"], range(4), model) + sweep(
        "shared_room_crossing", ["none"], range(4), model
    ):
        assert r["end_reason"] == "completed" and r["human_contacts"] == 0, (model, r["seed"], r["condition"])


def test_the_batch_columns_differ_between_the_conditions():
    """Defect: every behavioural column of `haven batch` was the same for all, none and path_projection."""
    rows = {c: sweep("shared_room_crossing", [c], range(5)) for c in ("all", "none", "path_projection")}
    for a, b in (("all", "none"), ("all", "path_projection"), ("none", "path_projection")):
        assert [[r[k] for k in BEHAVIOUR] for r in rows[a]] != [[r[k] for k in BEHAVIOUR] for r in rows[b]], (a, b)
