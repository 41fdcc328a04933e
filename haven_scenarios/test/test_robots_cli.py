"""`haven robots`: the catalogue one line each (its name first), one robot's figures with their
sources, and a name it does not know as one line."""

from __future__ import annotations

import pytest

from haven_scenarios.tools.cli import main
from haven_sim.robots.robot_kind import robot_names

pytestmark = pytest.mark.unit


def test_haven_robots_lists_one_line_per_robot_starting_with_its_name(capsys):
    assert main(["robots"]) == 0
    lines = capsys.readouterr().out.splitlines()
    names = robot_names()
    assert len(lines) >= 7 and len(lines) == len(names)
    assert [line.split()[0] for line in lines] == names
    drone = next(line for line in lines if line.startswith("quadrotor "))
    assert "aerial" in drone and "flies at 1.5 m" in drone


def test_haven_robots_name_gives_each_figure_with_its_source(capsys):
    assert main(["robots", "turtlebot4"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("turtlebot4: TurtleBot4")
    assert "limits.max_linear_speed_mps = 0.46  (max speed 0.46 m/s" in out
    assert "battery.capacity_m = 2700  (operating time" in out
    assert "cues.signal_height_m = " in out and "no source given" in out  # (derived from the body)


def test_haven_robots_with_a_file_and_with_an_unknown_name(capsys, tmp_path):
    own = tmp_path / "my_bot.yaml"
    own.write_text("extends: youbot\nname: my_bot\ntitle: youBot with a mast\nheight_m: 0.9\n")
    assert main(["robots", str(own)]) == 0
    assert "height_m = 0.9" in capsys.readouterr().out
    assert main(["robots", "r2d2"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "unknown robot 'r2d2'" in err


def test_haven_validate_checks_robot_files(capsys, tmp_path):
    good, bad = tmp_path / "my_bot.yaml", tmp_path / "fast.yaml"
    good.write_text("extends: youbot\nname: my_bot\ntitle: youBot with a mast\nheight_m: 0.9\n")
    bad.write_text("extends: turtlebot3_burger\nname: fast\ntitle: F\nmotion: {cruise_speed_mps: 0.5}\n")
    assert main(["validate", str(good), str(bad)]) == 2
    captured = capsys.readouterr()
    assert captured.out.splitlines() == [f"ok: {good} (robot my_bot)"]
    assert captured.err.splitlines() == [
        f"haven: error: {bad}: motion.cruise_speed_mps: 0.5 is above limits.max_linear_speed_mps 0.22"
    ]
