"""Simulated participants on the simulator core: each model does what its docstring says."""

import math
from pathlib import Path

import pytest
import yaml

from haven_scenarios.study.participant_kind import make_walker
from haven_scenarios.study.participants import HUMAN_PLANNER, Stop, shuffled_nearest
from haven_scenarios.study.perception import Sight, perceive
from haven_sim.common.geometry import Pose2D
from haven_sim.nav.planner import GridPlanner
from haven_sim.sim.occupancy import rasterise
from haven_sim.sim.simulation import Simulation
from haven_sim.sim.world_file import parse_world
from haven_viz.cues import CueState, Toggles

ROOM = {
    "name": "room",
    "walls": [
        {"segment": s, "thickness": 0.1}
        for s in ([[0, 0], [10, 0]], [[10, 0], [10, 6]], [[10, 6], [0, 6]], [[0, 6], [0, 0]])
    ],
    "robot": {"start": [5.0, 3.0, 0.0]},
    "humans": [{"id": "h1", "start": [1.0, 1.0, 0.0]}],
}


def walk(model, stops, seconds, robot_path=(), robot_at=None):
    """The person in ROOM for `seconds`, perceiving the robot (and `robot_path` as the projected
    path on show, when given) as a participant does."""
    world = parse_world(ROOM)
    sim = Simulation(world)
    grid = rasterise(world)
    planner, sight = GridPlanner(grid, HUMAN_PLANNER), Sight(grid)
    person = make_walker(model, "h1", stops, planner, 1.0, seed=3)
    cues = CueState(Toggles(), {"path_markers": len(robot_path)})
    poses = []
    for k in range(int(seconds * 50)):
        if k % 5 == 0:
            robot, me = robot_at or sim.robot_pose(), sim.human_poses()["h1"]
            seen = perceive(person.params, sight, sim.time, me, robot, cues, [(p.x, p.y) for p in robot_path])
            sim.command_human("h1", person.command(sim.time, me, robot, seen))
        sim.step()
        poses.append(sim.human_poses()["h1"])
    return person, poses


def test_walker_visits_its_stops_in_order_and_dwells():
    stops = [Stop(8.0, 1.0, dwell_s=1.0, reach_m=0.15), Stop(8.0, 5.0)]
    person, poses = walk("walker", stops, 30.0)
    assert person.done
    assert min(math.hypot(p.x - 8.0, p.y - 1.0) for p in poses) <= 0.15
    at_first = [i for i, p in enumerate(poses) if math.hypot(p.x - 8.0, p.y - 1.0) <= 0.15]
    assert (at_first[-1] - at_first[0]) / 50.0 >= 1.0  # stood there for the dwell time
    assert math.hypot(poses[-1].x - 8.0, poses[-1].y - 5.0) <= 0.15


def test_blocker_steps_onto_the_robots_path_ahead_of_it():
    path = [Pose2D(x, 3.0, 0.0) for x in (5.0, 6.0, 7.0, 8.0, 9.0)]
    _, poses = walk("blocker", [Stop(1.0, 5.0)], 12.0, robot_path=path, robot_at=Pose2D(5.0, 3.0, 0.0))
    on_path = [p for p in poses if abs(p.y - 3.0) < 0.2 and p.x > 7.0]
    assert len(on_path) > 100  # stood on the path, about 3 m ahead of the robot, for a while


def test_blocker_seeing_only_a_short_piece_of_path_goes_to_its_farthest_marker():
    """A robot turning on the spot shows a few markers; 2 m of them is enough to block on."""
    path = [Pose2D(x, 3.0, 0.0) for x in (5.0, 5.5, 6.0, 6.5, 7.0)]
    _, poses = walk("blocker", [Stop(1.0, 5.0)], 12.0, robot_path=path, robot_at=Pose2D(5.0, 3.0, 0.0))
    assert len([p for p in poses if math.hypot(p.x - 7.0, p.y - 3.0) < 0.25]) > 100
    # 1 m: too little
    _, short = walk("blocker", [Stop(1.0, 5.0)], 12.0, robot_path=path[:3], robot_at=Pose2D(5.0, 3.0, 0.0))
    assert all(abs(p.y - 3.0) > 0.3 or p.x < 5.5 for p in short)


def test_yielder_stops_and_steps_aside_for_a_robot_in_front():
    robot = Pose2D(3.0, 1.0, math.pi)  # 2 m ahead of the person, facing them
    _, free = walk("walker", [Stop(8.0, 1.0)], 3.5)  # (the person reacts one reaction time late)
    _, yielding = walk("yielder", [Stop(8.0, 1.0)], 3.5, robot_at=robot)
    assert yielding[-1].x < free[-1].x - 0.5  # held back
    assert yielding[-1].y < 1.0 - 0.3  # stepped to its right


def test_gem_routes_are_seeded_and_visit_every_stop():
    stops = [Stop(x, 1.0) for x in (2.0, 4.0, 6.0, 8.0)]
    a, b = shuffled_nearest(stops, (0.0, 0.0), 1), shuffled_nearest(stops, (0.0, 0.0), 1)
    assert a == b and sorted(s.x for s in a) == [2.0, 4.0, 6.0, 8.0]
    assert len({tuple(s.x for s in shuffled_nearest(stops, (5.0, 0.0), seed)) for seed in range(20)}) > 1


def test_a_yielder_facing_a_robot_that_waits_for_them_walks_on_past_it():
    """Defect: the yielder stood aside for a robot that waited for them in turn, for ever."""
    robot = Pose2D(5.0, 1.0, math.pi)  # stands still in the person's way, facing them
    person, poses = walk("yielder", [Stop(9.0, 1.0)], 30.0, robot_at=robot)
    assert person.done
    assert min(math.hypot(p.x - robot.x, p.y - robot.y) for p in poses) > 0.4  # past it, keeping clear


def test_a_stop_the_robot_stands_on_counts_as_reached_from_beside_it_no_deadlock():
    """Defect: the robot waited for a person who waited for the robot to leave a room's centre."""
    stops = [Stop(5.0, 3.0, reach_m=0.3), Stop(8.0, 5.0)]
    person, poses = walk("walker", stops, 30.0)  # the robot starts at (5, 3) and never moves
    assert person.done
    assert min(math.hypot(p.x - 5.0, p.y - 3.0) for p in poses) > 0.4  # never on the robot


def test_our_participant_models_are_plugins_listed_by_haven_plugins(capsys):
    """Registered through entry points as a lab's own are (haven_sim/common/plugins.py)."""
    from haven_scenarios.tools.cli import main
    from haven_sim.common import plugins

    reg = plugins.registry("participants")
    walker = next(p for p in reg if p.name == "walker")
    assert (walker.package, walker.target) == ("haven_scenarios", "haven_scenarios.study.participants:Walker")
    assert main(["plugins"]) == 0
    listed = capsys.readouterr().out.splitlines()
    assert {
        "participants walker haven_scenarios",
        "participants blocker haven_scenarios",
        "participants yielder haven_scenarios",
    } <= set(listed)
    assert all(len(line.split()) == 3 for line in listed)


def test_a_model_whose_plugin_is_broken_is_named_as_such_not_as_unknown(monkeypatch):
    """A lab installed `shy` but it does not import: the scenario's error says so, and why."""
    from fake_plugins import Entry

    from haven_scenarios.run.grid import parse_grid
    from haven_scenarios.study.scenario import ScenarioError
    from haven_sim.common import plugins

    ours = [
        Entry(p.name, p.target, p.package, p.value)
        for p in plugins.registry("participants")
        if p.package == "haven_scenarios"
    ]
    reg = plugins.load(
        "participants", [*ours, Entry("shy", "lab.people:Shy", "lab_people", ImportError("No module named 'lab'"))]
    )
    real = plugins.registry
    monkeypatch.setattr(plugins, "registry", lambda kind: reg if kind == "participants" else real(kind))
    said = "participant model 'shy' is installed but left out: does not load: ImportError: No module named 'lab'"
    with pytest.raises(ValueError, match=f"--grid model: {said}"):
        parse_grid(["model=shy"])
    from importlib import resources

    from haven_scenarios.study.scenario import parse_scenario

    data = yaml.safe_load((Path(str(resources.files("haven_scenarios") / "scenarios" / "hallway.yaml"))).read_text())
    data["humans"][0]["model"] = "shy"
    with pytest.raises(ScenarioError, match=said):
        parse_scenario(data, "lab.yaml")
    data["humans"][0]["model"] = ["shy"]
    with pytest.raises(ScenarioError, match="model: must be one of"):
        parse_scenario(data, "lab.yaml")


def documented_model(name: str):
    """A class defined by a Python block of docs/howto/plugins.md (the block that defines `name`)."""
    import re

    text = (Path(__file__).resolve().parents[2] / "docs" / "howto" / "plugins.md").read_text()
    (block,) = [b for b in re.findall(r"```python\n(.*?)```", text, re.S) if f"class {name}(" in b]
    scope: dict = {}
    exec(compile(block, "plugins.md", "exec"), scope)  # (our own documentation)
    return scope[name]


def test_the_documented_participant_model_runs_and_does_what_its_docstring_says():
    wary = documented_model("Wary")
    world = parse_world(ROOM)
    grid = rasterise(world)
    planner, sight = GridPlanner(grid, HUMAN_PLANNER), Sight(grid)
    person = wary("h1", [Stop(9.0, 1.0)], planner, 1.0, seed=3)
    cues = CueState(Toggles(), {})
    me = Pose2D(1.0, 1.0, 0.0)
    far = perceive(person.params, sight, 0.0, me, Pose2D(8.0, 5.0, 0.0), cues, [])
    near = perceive(person.params, sight, 0.0, me, Pose2D(2.5, 1.0, math.pi), cues, [])
    walking = [person.command(k * 0.1, me, Pose2D(8.0, 5.0, 0.0), far) for k in range(20)]
    assert walking[-1].vx > 0.3  # the robot far off: walks its task
    standing = [person.command(2.0 + k * 0.1, me, Pose2D(2.5, 1.0, math.pi), near) for k in range(20)]
    assert standing[-1] == (0.0, 0.0, 0.0)  # seen within 2 m: stands still
