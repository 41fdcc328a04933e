"""A scenario's own starts for the robot and the people (a world serves several scenarios): used by
batch trials, checked as a world file's starts are, and kept in a session's copy of the world, which
the ROS nodes read."""

import pytest
import yaml

from haven_scenarios.record.session import write_inputs
from haven_scenarios.study.scenario import ScenarioError, load_scenario, parse_scenario
from haven_sim.common.geometry import Pose2D
from haven_sim.sim.world_file import load_world

pytestmark = pytest.mark.unit

BASE = {
    "name": "s",
    "world": "office",
    "kind": "hallway",
    "robot": {"route": ["W"]},
    "humans": [{"id": "h1", "route": ["west_end"]}],
}


def test_the_scenario_starts_replace_the_worlds():
    s = load_scenario("office_crossing")
    assert s.world.robot_start == Pose2D(12.0, 1.0, 1.5708)
    assert s.world.humans[0].start == Pose2D(21.0, 10.5, -1.5708)
    plain = parse_scenario(BASE, "s.yaml")
    assert plain.world.robot_start == load_world(plain.world_path).robot_start


@pytest.mark.parametrize(
    "where, value, words",
    [
        ("robot", [10.8, 3.0, 0.0], "robot.start: (10.8, 3) lies inside a wall"),
        ("human", [13.1, 3.0], "humans[0].start: (13.1, 3) puts the person's body (radius 0.25 m) into a wall"),
        ("robot", [1, 2, 3, 4], "robot.start: must be a pose [x, y, yaw]"),
        ("human", "here", "humans[0].start: must be a pose [x, y, yaw]"),
    ],
)
def test_bad_starts_are_refused_in_one_line(where, value, words):
    data = yaml.safe_load(yaml.safe_dump(BASE))
    (data["robot"] if where == "robot" else data["humans"][0])["start"] = value
    with pytest.raises(ScenarioError) as e:
        parse_scenario(data, "s.yaml")
    assert words in str(e.value) and "\n" not in str(e.value), str(e.value)


def test_a_sessions_world_copy_has_the_starts_it_ran_with(tmp_path):
    s = load_scenario("office_crossing")
    write_inputs(tmp_path, s, "{}\n")
    copy = load_world(tmp_path / "world.yaml")
    assert copy.robot_start == s.world.robot_start and copy.humans[0].start == s.world.humans[0].start
    again = load_scenario(str(tmp_path / "scenario.yaml"))
    assert again.world.robot_start == s.world.robot_start
