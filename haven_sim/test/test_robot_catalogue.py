"""HAVEN's robot catalogue (haven_sim/robots/catalogue): every robot loads through its entry point,
every figure a file states has a source, a lab's own file extends a catalogue robot, and a bad
file or plugin is one line naming what is wrong."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
import yaml
from fake_plugins import Entry

from haven_sim.common import plugins
from haven_sim.robots import catalogue
from haven_sim.robots.description import Kinematics
from haven_sim.robots.robot_file import RobotError
from haven_sim.robots.robot_kind import resolve_robot, robot_names

pytestmark = pytest.mark.unit

CATALOGUE = sorted(Path(catalogue.__file__).parent.glob("*.yaml"))
NOT_FIGURES = {"name", "title", "sources"}


def test_every_catalogue_file_is_registered_and_loads():
    names = robot_names()
    assert len(CATALOGUE) >= 7 and sorted(p.stem for p in CATALOGUE) == sorted(names)
    assert plugins.registry("robots").problems == []
    kinds = {resolve_robot(n).kinematics for n in names}
    assert kinds == {Kinematics.DIFF_DRIVE, Kinematics.OMNI, Kinematics.AERIAL}
    for name in names:
        robot = resolve_robot(name)
        assert robot.name == name and 5 <= len(robot.look.primitives) <= 25, name
        assert robot.motion.cruise_speed_mps <= robot.limits.max_linear_speed_mps


def leaves(data: Any, path: str = "") -> list[str]:
    if isinstance(data, dict):
        return [leaf for k, v in data.items() for leaf in leaves(v, f"{path}.{k}" if path else str(k))]
    return [path]


@pytest.mark.parametrize("path", CATALOGUE, ids=lambda p: p.stem)
def test_every_figure_a_catalogue_file_states_has_a_source(path):
    data = yaml.safe_load(path.read_text())
    sources = data["sources"]
    stated = [leaf for leaf in leaves(data) if leaf.split(".")[0] not in NOT_FIGURES]
    parts = [leaf.split(".") for leaf in stated]
    missing = [".".join(p) for p in parts if not any(".".join(p[:n]) in sources for n in range(1, len(p) + 1))]
    assert missing == [], f"{path.name}: no source for {missing}"
    assert all(len(s) > 10 for s in sources.values())
    unused = [k for k in sources if not any(leaf == k or leaf.startswith(k + ".") for leaf in stated)]
    assert unused == [], f"{path.name}: sources for figures it does not state: {unused}"


def test_the_quadrotor_drains_in_the_air_and_flies_near_eye_level():
    drone = resolve_robot("quadrotor")
    assert drone.aerial and drone.flight is not None and 1.2 <= drone.flight.cruise_height_m <= 1.8
    assert drone.battery.idle_drain_per_s == pytest.approx(1 / (12 * 60), rel=1e-3)  # 12 min flight time
    assert not drone.motion.rotate_in_place and not resolve_robot("youbot").motion.rotate_in_place


def test_a_labs_robot_file_extends_a_catalogue_robot(tmp_path):
    own = tmp_path / "my_bot.yaml"
    own.write_text("extends: turtlebot3_burger\nname: my_bot\ntitle: Burger with a mast\nheight_m: 0.6\n")
    robot = resolve_robot(str(own))
    base = resolve_robot("turtlebot3_burger")
    assert (robot.name, robot.height_m) == ("my_bot", 0.6)
    assert robot.limits == base.limits and robot.footprint == base.footprint
    # The figures it leaves keep their sources; the one it changes loses the burger's.
    assert robot.sources["mass_kg"] == base.sources["mass_kg"] and "height_m" not in robot.sources
    own.write_text(own.read_text() + "limits: {max_linear_speed_mps: 0.21}\nsources: {height_m: our lab}\n")
    robot = resolve_robot(str(own))
    assert robot.sources["height_m"] == "our lab" and "limits.max_linear_speed_mps" not in robot.sources
    assert robot.sources["limits.max_angular_speed_rps"] == base.sources["limits.max_angular_speed_rps"]


BURGER = yaml.safe_load((Path(catalogue.__file__).parent / "turtlebot3_burger.yaml").read_text())


@pytest.mark.parametrize(
    "change, key",
    [
        ({"wheels": 2}, "wheels"),
        ({"motion": {"cruise_speed_mps": 0.5, "max_turn_rate_rps": 1.0}}, "motion.cruise_speed_mps"),
        ({"kinematics": "aerial"}, "flight"),
        ({"footprint": {"polygon": [[0, 0], [0.1, 0]]}}, "footprint"),
        ({"look": {"model": "missing.glb"}}, "look.model"),
        # edges crossing
        ({"footprint": {"polygon": [[0, 0], [0.5, 0], [0, 0.3], [0.3, 0.4]]}}, "footprint.polygon: is not simple"),
        ({"footprint": {"polygon": [[0, 0], [0.1, 0], [0.2, 0]]}}, "footprint.polygon: has zero area"),
        ({"frames": {"base": "a b/../c"}}, "frames.base: must be a ROS frame name"),
        ({"frames": {"base": "/base_footprint"}}, "frames.base: must be a ROS frame name"),
        ({"frames": {"base_link": "base//link"}}, "frames.base_link: must be a ROS frame name"),
        ({"frames": {"base_link": "robot/2nd_link"}}, "frames.base_link: must be a ROS frame name"),
        ({"lidar": {**BURGER["lidar"], "frame": "base__scan"}}, "lidar.frame: must be a ROS frame name"),
        ({"lidar": {**BURGER["lidar"], "frame": "base_link"}}, "frames.base_link: 'base_link' is also lidar.frame"),
        ({"frames": {"base_link": "odom"}}, "frames.base_link: 'odom' is a frame of the world"),
        ({"frames": {"base": "map"}}, "frames.base: 'map' is a frame of the world"),
    ],
)
def test_a_bad_robot_file_is_one_line_naming_the_key(change, key, tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text(yaml.safe_dump({**BURGER, **change}))
    with pytest.raises(RobotError) as e:
        resolve_robot(str(bad))
    said = str(e.value)
    assert "\n" not in said and key in said and str(bad) in said, said


def test_frame_names_with_a_namespace_are_kept(tmp_path):
    own = tmp_path / "ns_bot.yaml"
    frames = {"base": "robot1/base_footprint", "base_link": "robot1/base_link"}
    own.write_text(
        yaml.safe_dump(
            {**BURGER, "name": "ns_bot", "frames": frames, "lidar": {**BURGER["lidar"], "frame": "robot1/laser_2d"}}
        )
    )
    robot = resolve_robot(str(own))
    assert (robot.frames.base, robot.frames.base_link, robot.lidar.frame) == (
        "robot1/base_footprint",
        "robot1/base_link",
        "robot1/laser_2d",
    )


def test_a_plugin_whose_file_names_another_robot_is_left_out_with_one_line():
    burger = str(Path(catalogue.__file__).parent / "turtlebot3_burger.yaml")
    reg = plugins.load("robots", [Entry("my_bot", "lab.robots:MY_BOT", "lab_robots", burger)])
    assert reg.names() == [] and len(reg.problems) == 1 and "\n" not in reg.problems[0]
    assert "my_bot" in reg.problems[0] and "'turtlebot3_burger'" in reg.problems[0]
