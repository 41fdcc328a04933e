"""The schema layer (haven_sim/common/schema.py) as an editor sees it: `haven schema KIND` prints
a JSON Schema that a validator we did not write (jsonschema) accepts every shipped file with, and
that refuses what our reader refuses for its shape (an unknown key, a wrong type, a value out of
range, a missing key)."""

from __future__ import annotations

import json
from importlib import resources
from pathlib import Path

import pytest
import yaml

from haven_scenarios.tools.cli import main

pytestmark = pytest.mark.integration  # (the CLI in-process, every shipped file)


def shipped(package: str, folder: str) -> list[Path]:
    return sorted(Path(str(resources.files(package) / folder)).glob("*.yaml"))


FILES = {
    "world": shipped("haven_scenarios", "worlds") + shipped("haven_sim", "worlds"),
    "scenario": shipped("haven_scenarios", "scenarios"),
    "study": shipped("haven_scenarios", "studies"),
    "robot": shipped("haven_sim", "robots/catalogue"),
}


def validator_of(kind: str, capsys: pytest.CaptureFixture[str]):
    import jsonschema  # (in the test venv; the venv without ROS runs the unit tier only)

    assert main(["schema", kind]) == 0
    schema = json.loads(capsys.readouterr().out)
    jsonschema.Draft202012Validator.check_schema(schema)
    return jsonschema.Draft202012Validator(schema)


@pytest.mark.parametrize("kind", sorted(FILES))
def test_every_shipped_file_meets_its_exported_schema(kind, capsys):
    validator = validator_of(kind, capsys)
    assert FILES[kind]
    for path in FILES[kind]:
        errors = [e.message for e in validator.iter_errors(yaml.safe_load(path.read_text()))]
        assert errors == [], f"{path.name}: {errors}"


@pytest.mark.parametrize(
    "kind, change, key",
    [
        ("scenario", {"colour": "red"}, "colour"),
        ("scenario", {"kind": "corridor"}, "kind"),
        ("scenario", {"timeout_s": -1}, "timeout_s"),
        ("study", {"repetitions": 0}, "repetitions"),
        ("study", {"counterbalancing": "random"}, "counterbalancing"),
        ("world", {"robot": {}}, "robot.start"),
    ],
)
def test_the_schema_and_our_reader_refuse_the_same_shape_errors(kind, change, key, capsys, tmp_path):
    validator = validator_of(kind, capsys)
    data = {**yaml.safe_load(FILES[kind][0].read_text()), **change}
    assert list(validator.iter_errors(data)), f"the schema accepts {change}"
    bad = tmp_path / "bad.yaml"
    bad.write_text(yaml.safe_dump(data))
    assert main(["validate", str(bad)]) == 2
    assert f"{bad}: {key}: " in capsys.readouterr().err


def test_a_robot_file_that_extends_another_need_not_repeat_what_it_inherits(capsys):
    validator = validator_of("robot", capsys)
    assert not list(validator.iter_errors({"extends": "turtlebot2", "name": "my_bot", "height_m": 0.6}))
    assert list(validator.iter_errors({"name": "my_bot", "height_m": 0.6}))  # (no extends: the whole robot)
    assert list(validator.iter_errors({"extends": "turtlebot2", "wheels": 2}))
