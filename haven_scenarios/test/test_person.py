"""Simulated people differ between people and within a person from trial to trial, learn over their
session and sometimes misread a cue (study/person.py, study/participants.py)."""

import statistics
from dataclasses import replace

import pytest

from haven_scenarios.record.hesitation import SLOW_FRACTION
from haven_scenarios.study.participant_kind import make_walker
from haven_scenarios.study.participants import HUMAN_PLANNER, Stop, in_session
from haven_scenarios.study.perception import Percept
from haven_scenarios.study.person import HESITATE_LIMITS, NEW_PERSON, PersonParams, individual
from haven_scenarios.study.scenario import load_scenario
from haven_sim.common.geometry import Pose2D
from haven_sim.nav.planner import GridPlanner
from haven_sim.sim.occupancy import rasterise
from haven_sim.sim.world_file import parse_world

DRAWN = ("reaction_s", "pass_gap_m", "anticipate_m", "hesitate_factor", "cue_error")


def traits(params, human="h1", seed=0):
    person = individual(params, human, seed)
    return (person.speed_factor, *(getattr(person.params, k) for k in DRAWN))


def test_a_participant_is_the_same_person_on_every_trial_yet_no_two_trials_are_alike():
    """Under one seed for all their trials (the `per_participant` policy) a person still varies
    from trial to trial, around their own draw, which stays theirs."""
    p = PersonParams(person_seed=7, learning=0.0)
    trials = [traits(replace(p, session_trial=k), seed=3) for k in range(1, 9)]
    assert len(set(trials)) == len(trials)  # the trial noise differs between their trials
    assert traits(replace(p, session_trial=4), seed=3) == trials[3]  # ... and is reproducible
    others = [traits(replace(p, person_seed=s, session_trial=1), seed=3) for s in range(40)]
    # Within a person the spread is smaller than between people (speed factor, reaction time).
    for i in (0, 1):
        within = statistics.stdev(t[i] for t in trials)
        between = statistics.stdev(t[i] for t in others)
        assert within < between / 1.5, (i, within, between)


def test_the_person_draw_comes_from_the_person_not_the_trial_seed():
    p = PersonParams(person_seed=2, speed_trial_sd=0.0, reaction_trial_sd=0.0, learning=0.0)
    assert traits(p, seed=0)[:2] == traits(p, seed=99)[:2]  # no trial spread: the same person under any seed
    fresh = PersonParams(person_seed=NEW_PERSON)
    assert traits(fresh, seed=0) != traits(fresh, seed=1)  # a plain sweep: a new person per seed
    assert traits(p, "h1") != traits(p, "h2")  # two simulated humans of one participant's trial are two people


def test_spreads_of_zero_give_the_typical_person_and_spreads_are_zeroed_once_drawn():
    sd = {f: 0.0 for f in PersonParams.__dataclass_fields__ if f.endswith("_sd")}
    p = PersonParams(**sd, learning=0.0)
    person = individual(p, "h1", 5)
    assert person.speed_factor == 1.0 and person.params == p
    drawn = individual(PersonParams(), "h1", 5).params
    assert all(getattr(drawn, f) == 0.0 for f in sd)


def test_the_slowdown_is_a_random_effect_around_its_centre_never_the_metrics_threshold():
    draws = [individual(PersonParams(person_seed=s), "h1", 0).params.hesitate_factor for s in range(400)]
    assert abs(statistics.mean(draws) - PersonParams().hesitate_factor) < 0.03
    assert statistics.stdev(draws) > 0.08 and min(draws) >= HESITATE_LIMITS[0] and max(draws) <= HESITATE_LIMITS[1]
    assert PersonParams().hesitate_factor != SLOW_FRACTION  # the metric does not measure the parameter
    # A centre of 1 (no slowing) stays 1 with the spreads off.
    assert (
        individual(
            PersonParams(hesitate_factor=1.0, hesitate_person_sd=0.0, hesitate_trial_sd=0.0), "h1", 0
        ).params.hesitate_factor
        == 1.0
    )


def test_people_learn_reaction_time_and_misreading_shrink_over_the_session():
    first = [individual(PersonParams(person_seed=s, session_trial=1), "h1", 0).params for s in range(50)]
    ninth = [individual(PersonParams(person_seed=s, session_trial=9), "h1", 0).params for s in range(50)]
    ratio = statistics.mean(b.reaction_s for b in ninth) / statistics.mean(a.reaction_s for a in first)
    assert 0.6 < ratio < 0.85  # 9^-0.15 = 0.72, with the trial noise around it
    assert statistics.mean(b.cue_error for b in ninth) < 0.8 * statistics.mean(a.cue_error for a in first)


def test_a_misread_encounter_hides_the_cues_for_the_whole_encounter_at_the_documented_rate():
    walls = [
        {"segment": s, "thickness": 0.1}
        for s in ([[-1, -2], [11, -2]], [[11, -2], [11, 2]], [[11, 2], [-1, 2]], [[-1, 2], [-1, -2]])
    ]
    world = parse_world(
        {
            "name": "r",
            "walls": walls,
            "robot": {"start": [5.0, 0.0, 0.0]},
            "humans": [{"id": "h1", "start": [0.0, 0.0, 0.0]}],
        }
    )
    planner = GridPlanner(rasterise(world), HUMAN_PLANNER)
    robot = Pose2D(4.0, 0.0, 3.14)
    shown = Percept(0.0, robot, path=((3.0, 0.0), (2.0, 0.0)))
    misread, encounters = 0, 0
    for seed in range(300):
        w = make_walker(
            "walker", "h1", [Stop(9.0, 0.0)], planner, 1.0, seed, PersonParams(cue_error=0.3, cue_error_person_sd=0.0)
        )
        read = [w._read_cues(t, replace(shown, stamp=t)) for t in (0.0, 0.5, 1.0)]  # one encounter
        assert len({r.path for r in read}) == 1  # read or ignored for all of it
        misread += not read[0].path
        encounters += 1
        later = w._read_cues(10.0, replace(shown, stamp=10.0))  # a new encounter: drawn again
        assert w.encounters == 2 and w.misreads == (not read[0].path) + (not later.path)
        assert w._read_cues(11.0, Percept(11.0, robot)) == Percept(11.0, robot)  # no cue: nothing to misread
    assert 0.22 < misread / encounters < 0.38


def test_a_study_makes_its_simulated_people_the_participant_at_their_place_in_the_session():
    s = in_session(load_scenario("hallway_pair"), person_seed=4, session_trial=6)
    assert {(h.params.person_seed, h.params.session_trial) for h in s.humans} == {(4, 6)}
    assert s.humans[0].route == load_scenario("hallway_pair").humans[0].route


@pytest.mark.parametrize(
    ("change", "message"),
    [
        ({"person_seed": -2}, "person_seed must be -1"),
        ({"person_seed": 1.5}, "person_seed must be a whole number"),
        ({"session_trial": 0}, "session_trial must be 1 or more"),
        ({"cue_error": 1.0}, "cue_error must be within [0, 1)"),
        ({"speed_person_sd": 1.0}, "speed_person_sd must be within [0, 1)"),
        ({"hesitate_person_sd": -0.1}, "hesitate_person_sd must not be negative"),
        ({"learning": -1.0}, "learning must not be negative"),
    ],
)
def test_bad_person_parameters_are_refused_in_one_line(change, message):
    with pytest.raises(ValueError, match=message.replace("[", r"\[").replace("(", r"\(").replace(")", r"\)")):
        PersonParams(**change)


def test_a_sessions_copy_of_the_scenario_keeps_the_peoples_parameters(tmp_path):
    """The scenario node reads the session's scenario.yaml: a recorded trial has the same people as
    a batch one (the copy once dropped every person's `params`)."""
    from haven_scenarios.record.session import SCENARIO_FILE, write_inputs

    s = in_session(load_scenario("hallway"), person_seed=3, session_trial=5)
    s = replace(s, humans=(replace(s.humans[0], params=replace(s.humans[0].params, cue_error=0.2)),))
    write_inputs(tmp_path, s, "{}\n")
    assert load_scenario(tmp_path / SCENARIO_FILE).humans[0].params == s.humans[0].params
