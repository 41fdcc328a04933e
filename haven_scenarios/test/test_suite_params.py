"""One parameter source for both modes: haven.yaml is generated from the config dataclasses, and an
edited copy changes batch mode as it changes the nodes."""

import subprocess
import sys

import pytest
import yaml

from haven_scenarios.run.suite import NODES, load_suite_config, packaged_params_file, render
from haven_scenarios.run.trial import run_trial
from haven_scenarios.study.scenario import load_scenario
from haven_sim.common.params import ParamsError, defaults

pytestmark = pytest.mark.integration


def test_shipped_haven_yaml_is_generated_from_the_configs():
    assert packaged_params_file().read_text() == render(), "regenerate with: python -m haven_scenarios.run.suite"


def test_every_default_appears_once_in_haven_yaml():
    data = yaml.safe_load(packaged_params_file().read_text())
    shared = data["/**"]["ros__parameters"]
    for node, cls in NODES:
        own = data[node]["ros__parameters"]
        assert not set(own) & set(shared), node
        expected = {k: (list(v) if isinstance(v, tuple) else v) for k, v in defaults(cls).items()}
        assert {**{k: v for k, v in shared.items() if k in expected}, **own} == expected, node


def test_an_edited_params_file_changes_batch_mode(tmp_path):
    f = tmp_path / "slow.yaml"
    f.write_text('"/**":\n  ros__parameters:\n    rotate_speed_deg_s: 10.0\n')
    scenario = load_scenario("shared_room")
    fast = run_trial(scenario, 1).metrics
    slow = run_trial(scenario, 1, suite=load_suite_config(f)).metrics
    assert slow["robot_time_to_finish_s"] > 1.2 * fast["robot_time_to_finish_s"]


def test_batch_refuses_a_bad_params_file_in_one_line(tmp_path):
    f = tmp_path / "bad.yaml"
    f.write_text("controller:\n  ros__parameters:\n    rate_hz: fast\n")
    r = subprocess.run(
        [sys.executable, "-m", "haven_scenarios", "batch", "shared_room", "--params-file", str(f)],
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert (
        r.returncode == 2
        and r.stderr.strip() == f"haven: error: {f}: controller: rate_hz: must be a finite number, got 'fast'"
    )


def test_booleans_in_a_parameter_file_are_booleans_not_numbers(tmp_path):
    """(A session's own params.yaml says `lockstep: true`; `haven rerun` reads it back.)"""
    p = tmp_path / "params.yaml"
    p.write_text("/**:\n  ros__parameters:\n    lockstep: true\nviz:\n  ros__parameters:\n    turn_signals: false\n")
    config = load_suite_config(str(p))
    assert config.lockstep.lockstep is True and config.viz.toggles.turn_signals is False
    p.write_text("/**:\n  ros__parameters:\n    lockstep: 1\n")
    with pytest.raises(ParamsError, match=f"^{p}: sim_node: lockstep: must be true or false, got 1$"):
        load_suite_config(str(p))


@pytest.mark.parametrize(
    ("text", "problem"),
    [
        (
            "sim_node:\n  ros__parameters:\n    physics_hz: fast\n",
            "sim_node: physics_hz: no such parameter (did you mean physics_rate_hz?)",
        ),
        ("planer:\n  ros__parameters:\n    check_rate_hz: 5.0\n", "planer: no such node (did you mean planner?)"),
        ('"/**":\n  ros__parameters:\n    use_sim_time: .nan\n', "/**: use_sim_time: must be true or false, got nan"),
        (
            '"/**":\n  ros__parameters:\n    arc_max_angle_deg: .nan\n',
            "/**: arc_max_angle_deg: must be a finite number, got nan",
        ),
        ("scenario:\n  ros__parameters:\n    rate_hz: nan\n", "scenario: rate_hz: must be a finite number, got nan"),
        (
            '"/**":\n  ros__parameters:\n    use_sim_tim: true\n',
            "/**: use_sim_tim: no such parameter (did you mean use_sim_time?)",
        ),
        (
            "controller:\n  ros__parameters:\n    use_sim_time: 1\n",
            "controller: use_sim_time: must be true or false, got 1",
        ),
        (
            "controller:\n  ros__parameters:\n    lookahead_m: -.inf\n",
            "controller: lookahead_m: must be a finite number, got -inf",
        ),
        (
            "controller:\n  ros__parameters:\n    lookahead_m: 1" + "0" * 400 + "\n",
            "controller: lookahead_m: must be a finite number",
        ),
        (
            "viz:\n  ros__parameters:\n    turn_signal: true\n",
            "viz: turn_signal: no such parameter (did you mean turn_signals?)",
        ),
        (  # (a robot's figure: not the nearest parameter's name, min_linear_speed_mps)
            '"/**":\n  ros__parameters:\n    max_linear_speed_mps: 2.0\n',
            "/**: max_linear_speed_mps: no such parameter: it is the robot's, limits.max_linear_speed_mps in a robot",
        ),
    ],
)
def test_a_typo_or_a_non_finite_value_in_a_parameter_file_is_refused_naming_file_node_and_key(tmp_path, text, problem):
    p = tmp_path / "params.yaml"
    p.write_text(text)
    with pytest.raises(ParamsError) as e:
        load_suite_config(str(p))
    assert str(e.value).startswith(f"{p}: {problem}") and "\n" not in str(e.value)


def test_what_a_trial_sets_itself_is_refused_in_its_parameter_file_unless_left_at_the_default(tmp_path):
    from haven_scenarios.run.suite import TRIAL_SETS

    p = tmp_path / "params.yaml"
    p.write_text("scenario:\n  ros__parameters:\n    seed: 7\n")
    with pytest.raises(ParamsError, match=f"^{p}: scenario: seed: set by --seed, not by a parameter file$"):
        load_suite_config(str(p), TRIAL_SETS)
    p.write_text('"/**":\n  ros__parameters:\n    lockstep: true\n')
    with pytest.raises(ParamsError, match="lockstep: set by haven run"):
        load_suite_config(str(p), TRIAL_SETS)
    assert load_suite_config(str(p)).lockstep.lockstep is True  # (a session's own params.yaml, for haven rerun)
    load_suite_config(str(packaged_params_file()), TRIAL_SETS)  # every default: an edited copy of haven.yaml is fine


def test_a_double_written_as_ros_reads_it_is_a_number(tmp_path):
    """rcl reads `1e-3` as a double, YAML 1.1 as a string: a parameter file means the double."""
    p = tmp_path / "params.yaml"
    p.write_text("controller:\n  ros__parameters:\n    rate_hz: 2e1\n")
    assert load_suite_config(str(p)).controller.rate_hz == 20.0


def test_namespaced_and_wildcard_node_keys_name_the_node(tmp_path):
    p = tmp_path / "params.yaml"
    p.write_text(
        "/robot1/controller:\n  ros__parameters:\n    lookahead_m: 0.3\n"
        "/**/planner:\n  ros__parameters:\n    check_rate_hz: 4.0\n"
    )
    config = load_suite_config(str(p))
    assert config.controller.follower.lookahead_m == 0.3 and config.planner.check_rate_hz == 4.0
