"""One parameter source for both modes: haven.yaml is generated from the config dataclasses, and an
edited copy changes batch mode as it changes the nodes."""

import subprocess
import sys

import yaml

from haven_scenarios.run.suite import NODES, load_suite_config, packaged_params_file, render
from haven_scenarios.run.trial import run_trial
from haven_scenarios.study.scenario import load_scenario
from haven_sim.common.params import defaults


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
    f.write_text("controller:\n  ros__parameters:\n    linear_speed_mps: 0.25\n")
    scenario = load_scenario("shared_room")
    fast = run_trial(scenario, 1).metrics
    slow = run_trial(scenario, 1, suite=load_suite_config(f)).metrics
    assert slow["robot_time_to_finish_s"] > 1.2 * fast["robot_time_to_finish_s"]


def test_batch_refuses_a_bad_params_file_in_one_line(tmp_path):
    f = tmp_path / "bad.yaml"
    f.write_text("controller:\n  ros__parameters:\n    rate_hz: fast\n")
    r = subprocess.run(
        [sys.executable, "-m", "haven_scenarios", "batch", "shared_room", "--params-file", str(f)], capture_output=True, text=True, timeout=60
    )
    assert r.returncode == 2 and r.stderr.strip() == "haven: error: controller: rate_hz: must be a finite number, got 'fast'"


def test_booleans_in_a_parameter_file_are_booleans_not_numbers(tmp_path):
    """(A session's own params.yaml says `lockstep: true`; `haven rerun` reads it back.)"""
    from haven_scenarios.run.suite import load_suite_config

    p = tmp_path / "params.yaml"
    p.write_text("/**:\n  ros__parameters:\n    lockstep: true\n")
    load_suite_config(str(p))
