"""The Python API (haven_scenarios.api) does what the commands do, with typed results, and refuses
bad input in one line before anything starts."""

from __future__ import annotations

import csv

import pytest
import yaml

from haven_scenarios import api
from haven_scenarios.run.trial import run_trial
from haven_scenarios.study.conditions import parse_condition
from haven_scenarios.study.scenario import load_scenario
from haven_scenarios.tools.cli import main

pytestmark = pytest.mark.integration


def test_a_batch_trial_and_a_sweep_are_the_commands_trials(tmp_path):
    r = api.batch_trial("hallway", seed=2, condition=["turn_signals"])
    assert r.metrics == run_trial(load_scenario("hallway"), 2, parse_condition(["turn_signals"])).metrics
    rows = api.sweep(["hallway"], seeds=[0, 1], grid={"condition": ["all", "none"]}, workers=2)
    assert [(row["trial"], row["condition"], row["seed"]) for row in rows] == [
        (0, "all", 0),
        (1, "all", 1),
        (2, "none", 0),
        (3, "none", 1),
    ]
    out = tmp_path / "batch.csv"
    assert (
        main(
            ["batch", "hallway", "--grid", "condition=all,none", "--seeds", "0-1", "--out", str(out), "--workers", "1"]
        )
        == 0
    )
    with out.open() as f:
        from_cli = list(csv.DictReader(f))
    assert [str(row["min_human_centre_distance_m"]) for row in rows] == [
        row["min_human_centre_distance_m"] for row in from_cli
    ]


def test_a_pilot_study_through_the_api(tmp_path):
    study = tmp_path / "pilot.yaml"
    study.write_text(
        yaml.safe_dump(
            {
                "name": "pilot",
                "scenarios": ["hallway"],
                "conditions": {"none": ["none"], "signals": ["turn_signals"]},
                "participants": ["p01", "p02", "p03"],
                "counterbalancing": "latin",
            }
        )
    )
    assert len(api.study_plan(str(study))) == 6 and len(api.study_plan(str(study), "p02")) == 2
    with pytest.raises(ValueError, match=r"^study_plan: 'p99' is not a participant of study pilot$"):
        api.study_plan(str(study), "p99")
    for p in ("p01", "p02", "p03"):
        assert api.run_participant(str(study), p, batch=True, dir=tmp_path / "study") == 0
    assert api.run_participant(str(study), "p01", batch=True, dir=tmp_path / "study") == 0  # (nothing left to run)
    assert [t.status for t in api.study_status(str(study), dir=tmp_path / "study")] == ["done"] * 6
    report = api.study_report(str(study), dir=tmp_path / "study")
    assert report.trials_done == 6 and (report.folder / "study_long.csv").exists() and not report.study_changed
    with pytest.raises(ValueError, match=r"^no finished trials of study pilot in "):
        api.study_report(str(study), dir=tmp_path / "empty")
    for options, said in (
        ({"participant": "p99"}, "--participant: 'p99' is not a participant of study pilot"),
        (
            {"participant": "p01", "batch": True, "web": True},
            "--batch runs simulated participants in this process: not with --web",
        ),
        ({"participant": "p01", "bach": True}, "run_participant: unknown option 'bach'"),
    ):
        with pytest.raises(api.TrialError, match=said):
            api.run_participant(str(study), dir=tmp_path / "study", **options)


@pytest.mark.parametrize(
    ("options", "said"),
    [
        ({"seed": -1}, "seed: must be an integer 0.."),
        ({"seed": "3"}, "seed: must be an integer 0..2147483647, got '3'"),
        ({"rtf": 0}, "rtf: must be a positive number, got 0"),
        ({"condition": ["sparkles"]}, "unknown cue 'sparkles'"),
        ({"allow": ["/odom"]}, "--allow /odom: the simulator's and the metrics' topics take no outside publisher"),
        (
            {"without": ["sim"]},
            "--without: 'sim' is not one of our nodes that can be left out (mux, planner, controller, viz)",
        ),
        ({"teleop": ["h9"]}, "--teleop: no human 'h9' in scenario hallway"),
        ({"questionnaires": ["nasa_tlx"]}, "--questionnaire: participants answer in their pages: needs --web"),
        ({"participant": "../x"}, "--participant"),
        ({"colour": "red"}, "recorded_trial: unknown option 'colour'"),
    ],
)
def test_bad_input_to_a_recorded_trial_is_one_line_and_starts_nothing(tmp_path, options, said):
    with pytest.raises(api.TrialError) as e:
        api.recorded_trial("hallway", sessions=tmp_path / "s", **options)
    assert said in str(e.value) and "\n" not in str(e.value)
    assert not (tmp_path / "s").exists()


def test_seeds_and_conditions_as_a_script_writes_them():
    """numpy integers are seeds; a single cue may be a string; anything else is one line."""
    import numpy as np

    assert api.batch_trial("hallway", seed=np.int64(1), condition="turn_signals").condition == "turn_signals"
    rows = api.sweep("hallway", seeds=np.arange(2), grid={"condition": "none"})
    assert [(r["seed"], r["condition"]) for r in rows] == [(0, "none"), (1, "none")]
    for bad in (True, 1.5, "x", -1):
        with pytest.raises(ValueError, match=r"^seed: must be an integer 0\.\.2147483647, got "):
            api.batch_trial("hallway", seed=bad)
    with pytest.raises(ValueError, match=r"^seeds: must be an integer"):
        api.sweep(["hallway"], seeds=[0, -2])


def test_a_simulation_stepped_by_hand_is_the_batch_trial(tmp_path):
    sim = api.Simulation("hallway", seed=3)
    start = sim.state()
    assert start.time == 0.0 and start.ended is None and set(start.humans) == {"h1"}
    now = sim.step(500)  # 10 s of the 50 Hz physics
    assert now.time == pytest.approx(500 * sim.step_s) and now.ended is None
    assert now.robot.x > start.robot.x + 1.0 and now.battery < start.battery  # on its way, drawing power
    picture = sim.render(tmp_path / "now.png")
    assert picture.stat().st_size > 10_000 and sim.markers  # the AR cues shown now, drawn
    assert sim.result().end_reason == "interrupted"  # (scored so far: not ended yet)
    stepped = sim.run()
    assert stepped.end_reason == "completed" and sim.step(10).ended == "completed"  # (nothing past the end)
    for bad in (-5, 2.5):
        with pytest.raises(ValueError, match=f"steps must be a whole number of at least 0, got {bad}"):
            sim.step(bad)
    assert stepped.metrics == api.batch_trial("hallway", seed=3).metrics  # the very trial `haven batch` runs


def test_a_trial_of_another_robot_and_of_one_study_participant_is_the_commands_trial():
    """`robot=` and `person=` wherever the API runs a trial, as `haven run --robot` and a study give them."""
    from haven_scenarios.run.grid import for_trial

    r = api.batch_trial("hallway", seed=1, robot="turtlebot4", person=(7, 2))
    scenario = for_trial(load_scenario("hallway"), "turtlebot4", (7, 2))
    assert scenario.robot.name == "turtlebot4" and {h.params.person_seed for h in scenario.humans} == {7}
    assert r.metrics == run_trial(scenario, 1, parse_condition(list(scenario.condition))).metrics
    assert r.metrics != api.batch_trial("hallway", seed=1).metrics
    (row,) = api.sweep("hallway", seeds=[1], robot="turtlebot4")
    assert row["robot"] == "turtlebot4"
    assert row["duration_s"] == api.batch_trial("hallway", seed=1, robot="turtlebot4").metrics["duration_s"]
    sim = api.Simulation("hallway", seed=1, robot="turtlebot4", person=(7, 2))
    assert sim.run().metrics == r.metrics
    with pytest.raises(ValueError, match=r"^--robot: unknown robot 'r2d2'"):
        api.batch_trial("hallway", robot="r2d2")
    with pytest.raises(ValueError, match=r"^sweep: give the robot once"):
        api.sweep("hallway", seeds=[0], robot="turtlebot4", grid={"robot": "turtlebot2"})
