"""Mission behaviours are plugins (study/mission_orders.py): ours register as a lab's does, a
scenario file names one, and the mission executive follows it with its battery rules unchanged."""

from __future__ import annotations

import pytest
from fake_plugins import Entry

from haven_scenarios.study.mission import Mission, Target
from haven_scenarios.study.scenario import ScenarioError, load_scenario
from haven_sim.common import plugins
from haven_sim.common.geometry import Pose2D


class Farthest:
    """A lab's behaviour: the farthest target first."""

    def arrange(self, targets, seed):
        return list(targets)

    def pick(self, candidates, robot, path_length):
        return max(candidates, key=lambda t: path_length((robot.x, robot.y), t.xy))


@pytest.fixture
def with_farthest(monkeypatch):
    ours = plugins.registry("missions")
    reg = plugins.load(
        "missions",
        [
            *(Entry(p.name, p.target, p.package, p.value) for p in ours),
            Entry("farthest", "lab.missions:Farthest", "lab_missions", Farthest),
        ],
    )
    real = plugins.registry
    monkeypatch.setattr(plugins, "registry", lambda kind: reg if kind == "missions" else real(kind))


def test_ours_are_registered_plugins():
    assert {p.name: p.package for p in plugins.registry("missions")} == dict.fromkeys(
        ("fixed", "nearest", "random"), "haven_scenarios"
    )


def test_a_labs_behaviour_picks_the_targets_and_a_scenario_names_it(with_farthest, tmp_path):
    targets = [Target(f"g{i}", float(i), 0.0, f"gem g{i}") for i in (1, 2, 3)]
    mission = Mission(targets, lambda a, b: abs(a[0] - b[0]) + abs(a[1] - b[1]), "farthest")
    robot, order = Pose2D(0.0, 0.0, 0.0), []
    out = mission.start(0.0, robot)
    while out.goal is not None:
        order.append(mission.current.id)
        robot = Pose2D(out.goal.x, out.goal.y, 0.0)
        out = mission.target_done(1.0, mission.current.id, robot, 1.0)
    assert order == ["g3", "g1", "g2"]  # from the origin g3 is farthest; from g3, g1
    scenario = tmp_path / "far.yaml"
    scenario.write_text("name: far\nworld: shared_room\nkind: retrieval\nrobot: {order: farthest}\nhumans: []\n")
    assert load_scenario(str(scenario)).robot_order == "farthest"


def test_an_unknown_behaviour_is_one_line_naming_the_known_ones(tmp_path):
    scenario = tmp_path / "far.yaml"
    scenario.write_text("name: far\nworld: shared_room\nkind: retrieval\nrobot: {order: farthest}\nhumans: []\n")
    with pytest.raises(
        ScenarioError, match=r"robot\.order: unknown mission behaviour 'farthest' \(known: fixed, nearest, random\)$"
    ):
        load_scenario(str(scenario))
