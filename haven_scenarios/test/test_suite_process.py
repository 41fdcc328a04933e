"""The suite process's own arguments (`--node KEY=JSON`), refused in one line each before any node starts."""

import subprocess
import sys

import pytest

pytestmark = pytest.mark.integration
SUITE = [sys.executable, "-m", "haven_scenarios.nodes.suite_process"]


@pytest.mark.parametrize(
    ("node", "says"),
    [
        ("recorder={}", "'recorder' is not one of sim, mux, planner, controller, viz, scenario"),
        ("sim=[1]", "sim: its parameters must be a JSON object"),
        ("sim={nope", "sim: its parameters must be a JSON object"),
    ],
)
def test_a_node_it_cannot_hold_or_parameters_that_are_not_an_object_are_one_line(node, says):
    r = subprocess.run([*SUITE, "--node", node], capture_output=True, text=True, timeout=60)
    assert r.returncode == 2 and r.stdout == "", r.stderr
    assert r.stderr.strip().splitlines()[-1].endswith(f"argument --node: {says}"), r.stderr
