"""Choosing the robot everywhere: `--robot NAME|FILE` on haven run/sim/batch, `--grid robot=...`,
sessions that keep the robot they ran (robot.yaml, session.json), and the robot as a study's design
factor (`robots`, `robot_design`). Robots here are user files beside the test (`extends: turtlebot2`)."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import pytest
import yaml

from haven_scenarios.conduct.recorded_trial import TrialError, TrialRequest, plan_trial
from haven_scenarios.record.progress import ran_otherwise
from haven_scenarios.record.session import ROBOT_FILE, session_scenario, write_inputs
from haven_scenarios.run.grid import parse_grid, plan_sweep
from haven_scenarios.run.suite import TRIAL_SETS, load_suite_config, render
from haven_scenarios.study.protocol import StudyError, load_study
from haven_scenarios.study.scenario import load_scenario
from haven_scenarios.study.schedule import schedule
from haven_scenarios.tools.cli import main
from haven_sim.common.params import ParamsError

SLOW_BOT = "name: slow_bot\ntitle: a slower TurtleBot2\nextends: turtlebot2\nmotion: {cruise_speed_mps: 0.25}\n"


@pytest.fixture
def slow_bot(tmp_path: Path) -> Path:
    path = tmp_path / "slow.yaml"
    path.write_text(SLOW_BOT)
    return path


def study_file(tmp_path: Path, **changes: object) -> Path:
    data = {
        "name": "robots_pilot",
        "scenarios": ["shared_room"],
        "conditions": {"none": ["none"], "all": ["all"]},
        "participants": 2,
        "practice": [],
        "counterbalancing": "none",
        "blocks": "none",
        "robots": ["turtlebot2", "slow.yaml"],
        **changes,
    }
    path = tmp_path / "study.yaml"
    path.write_text(yaml.safe_dump(data))
    return path


@pytest.mark.unit
@pytest.mark.parametrize(
    "command", [["batch", "hallway", "--seeds", "0"], ["run", "hallway"], ["sim", "--duration", "1"]]
)
def test_an_unknown_robot_or_a_missing_file_is_one_line_naming_the_option(
    command: list[str], capsys: pytest.CaptureFixture[str]
) -> None:
    for robot, says in (("hal9000", "unknown robot 'hal9000'"), ("nowhere/bot.yaml", "no such robot file")):
        assert main([*command, "--robot", robot]) == 2
        err = capsys.readouterr().err
        assert err.startswith("haven: error: --robot: ") and says in err and err.count("\n") == 1, err


@pytest.mark.unit
def test_a_robot_on_the_grid_is_a_design_column_and_replaces_the_scenarios_robot(slow_bot: Path) -> None:
    axes = parse_grid([f"robot=turtlebot2,{slow_bot}"])
    assert axes["robot"] == ("turtlebot2", str(slow_bot))
    specs = plan_sweep([load_scenario("hallway")], axes, (0,))
    assert [s.columns()["robot"] for s in specs] == ["turtlebot2", "slow_bot"]
    assert list(specs[1].columns())[:6] == ["trial", "scenario", "condition", "model", "robot", "seed"]
    assert specs[1].scenario.robot.motion.cruise_speed_mps == 0.25
    with pytest.raises(ValueError, match=r"^--grid robot: unknown robot 'r2d2'"):
        parse_grid(["robot=r2d2"])
    assert main(["batch", "hallway", "--robot", "turtlebot2", "--grid", "robot=turtlebot2", "--seeds", "0"]) == 2


@pytest.mark.unit
def test_robot_wins_over_the_scenarios_and_the_session_keeps_the_robot_as_run(
    tmp_path: Path, slow_bot: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)  # (a relative robot file: made absolute, as the nodes run in the session folder)
    plan = plan_trial(TrialRequest("hallway", robot="slow.yaml"))
    assert (plan.scenario.robot.name, plan.scenario.robot_model) == ("slow_bot", str(slow_bot))
    folder = tmp_path / "session"
    folder.mkdir()
    write_inputs(folder, plan.scenario, render(plan.config(folder)))
    kept = yaml.safe_load((folder / ROBOT_FILE).read_text())
    assert kept["name"] == "slow_bot" and "extends" not in kept and kept["motion"]["cruise_speed_mps"] == 0.25
    assert yaml.safe_load((folder / "params.yaml").read_text())["/**"]["ros__parameters"]["robot"] == ROBOT_FILE
    scenario, problem = session_scenario(folder)  # (what the scenario node, the web node, report and rerun read)
    assert problem == "" and scenario is not None and scenario.robot.name == "slow_bot"
    with pytest.raises(TrialError, match=r"^--robot: unknown robot 'nope'"):
        plan_trial(TrialRequest("hallway", robot="nope"))


@pytest.mark.unit
def test_a_parameter_file_cannot_choose_the_robot(tmp_path: Path) -> None:
    params = tmp_path / "params.yaml"
    params.write_text("/**:\n  ros__parameters:\n    robot: turtlebot4\n")
    with pytest.raises(
        ParamsError, match=r"/\*\*: robot: set by --robot \(or the scenario's robot: model\), not by a parameter file"
    ):
        load_suite_config(params, TRIAL_SETS)


@pytest.mark.unit
def test_a_study_plans_the_robot_between_or_within_participants(tmp_path: Path, slow_bot: Path) -> None:
    between = schedule(load_study(study_file(tmp_path)))
    assert [(t.participant, t.robot_name) for t in between] == [("p01", "turtlebot2")] * 2 + [("p02", "slow_bot")] * 2
    assert {t.robot for t in between if t.participant == "p02"} == {str(slow_bot)}
    within = schedule(load_study(study_file(tmp_path, robot_design="within", counterbalancing="williams")))
    p01, p02 = ([t for t in within if t.participant == p] for p in ("p01", "p02"))
    assert [t.robot_name for t in p01] == ["turtlebot2"] * 2 + ["slow_bot"] * 2  # a block of trials per robot,
    assert [t.robot_name for t in p02] == ["slow_bot"] * 2 + ["turtlebot2"] * 2  # in counterbalanced order
    assert [t.block for t in p01] == [1, 1, 2, 2] and p01[0].trial_id == "shared_room-all-turtlebot2"
    ran = {
        "scenario": "shared_room",
        "condition": between[2].condition,
        "seed": between[2].seed,
        "robot_name": "turtlebot2",
    }
    # (not done: run again)
    assert ran_otherwise(ran, between[2]) == "ran with robot turtlebot2; the schedule now says robot slow_bot"
    assert ran_otherwise({**ran, "robot_name": "slow_bot"}, between[2]) is None
    plain = schedule(load_study(study_file(tmp_path, robots=[])))
    assert {(t.robot, t.robot_name) for t in plain} == {("", "")} and plain[0].trial_id == "shared_room-all"
    for robots, says in (
        (["r2d2"], "robots[0]: unknown robot 'r2d2'"),
        (["turtlebot2", "turtlebot2"], "robots[1]: robot 'turtlebot2' is listed twice"),
    ):
        with pytest.raises(StudyError, match=r"study\.yaml: " + says.replace("[", r"\[").replace("]", r"\]")):
            load_study(study_file(tmp_path, robots=robots))


@pytest.mark.integration
def test_a_users_slower_robot_file_runs_in_batch_and_takes_longer(tmp_path: Path, slow_bot: Path) -> None:
    out = tmp_path / "rows.csv"
    assert (
        main(
            [
                "batch",
                "shared_room",
                "--grid",
                f"robot=turtlebot2,{slow_bot}",
                "--seeds",
                "0",
                "--workers",
                "1",
                "--out",
                str(out),
            ]
        )
        == 0
    )
    rows = list(csv.DictReader(out.open()))
    assert [r["robot"] for r in rows] == ["turtlebot2", "slow_bot"] and all(
        r["end_reason"] == "completed" for r in rows
    )
    assert float(rows[1]["robot_time_to_finish_s"]) > float(rows[0]["robot_time_to_finish_s"]) + 5.0


@pytest.mark.integration
def test_a_study_with_robots_runs_in_batch_and_reports_the_robot_column(tmp_path: Path, slow_bot: Path) -> None:
    path, root = study_file(tmp_path), tmp_path / "run"
    for participant in ("p01", "p02"):
        assert (
            main(["study", "run", str(path), "--batch", "--participant", participant, "--no-pause", "--dir", str(root)])
            == 0
        )
    assert main(["study", "report", str(path), "--dir", str(root)]) == 0
    wide = list(csv.DictReader((root / "report" / "study_wide.csv").open()))
    assert [(r["participant"], r["robot"]) for r in wide] == [("p01", "turtlebot2")] * 2 + [("p02", "slow_bot")] * 2
    slow = {float(r["robot_time_to_finish_s"]) for r in wide if r["robot"] == "slow_bot"}
    assert min(slow) > max(float(r["robot_time_to_finish_s"]) for r in wide if r["robot"] == "turtlebot2")
    long = next(csv.DictReader((root / "report" / "study_long.csv").open()))
    assert "robot" in long
    summary = list(csv.DictReader((root / "report" / "summary.csv").open()))
    assert {r["robot"] for r in summary} == {"turtlebot2", "slow_bot"}  # per robot when the robot varies
    session = next((root / "p02").glob("*/*/session.json"))
    assert json.loads(session.read_text())["robot_name"] == "slow_bot"


def test_a_robot_too_big_for_the_worlds_start_is_one_line(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    big = tmp_path / "big.yaml"
    big.write_text("extends: tiago\nname: big_bot\nfootprint: {radius_m: 3.0}\n")
    assert main(["batch", "hallway", "--robot", str(big), "--seeds", "0", "--out", str(tmp_path / "x.csv")]) == 2
    (line,) = capsys.readouterr().err.strip().splitlines()
    assert (
        "robot 'big_bot' (radius 3.00 m) does not fit at world 'hallway''s robot start" in line
        and "overlaps a wall" in line
    )


def test_a_drone_counts_its_hovering_in_the_range_its_mission_plans_with() -> None:
    from haven_sim.robots.robot_kind import resolve_robot

    room = load_scenario("shared_room")
    drone = resolve_robot("quadrotor")
    assert room.battery.drain_factor == 1.0 and not room.battery.drains_waiting  # TurtleBot2 drains only as it moves
    flying = room.for_robot(drone).battery
    hover_m_per_m = drone.battery.idle_drain_per_s * 15.0 / drone.motion.cruise_speed_mps  # the scenario's 15 m pack
    assert flying.capacity_m == 15.0 and flying.drain_factor == pytest.approx(1.0 + hover_m_per_m)
    assert flying.drains_waiting  # its mission watches the range while it hovers (study/mission.py)
