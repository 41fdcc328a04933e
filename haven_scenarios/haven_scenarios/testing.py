"""pytest fixtures for a lab's own plugins: load the package's item as HAVEN would, and run one batch
trial with it. In the plugin package's `conftest.py` (`haven plugins new` writes it)::

    pytest_plugins = ["haven_scenarios.testing"]

and in a test::

    def test_my_cue_is_shown_in_a_trial(haven_plugin, haven_trial):
        haven_plugin("cues", "my_cue")                     # registered, and what its kind needs
        row = haven_trial("hallway", condition="my_cue")   # the row `haven batch` writes
        assert row["valid"] and row["my_cue_shown_s"] > 0

Both go through the registries a scenario or a sweep uses (the installed packages' entry points),
so the package must be installed into HAVEN's environment (`pip install -e .`); a plugin that is
not, or that HAVEN leaves out, fails the test with the one line `haven plugins` would print.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import replace
from pathlib import Path
from typing import Any

import pytest
import yaml

from haven_scenarios.run.grid import parse_grid, plan_sweep
from haven_scenarios.run.suite import TRIAL_SETS, load_suite_config
from haven_scenarios.run.sweep import run_rows
from haven_scenarios.study.conditions import check_seed
from haven_scenarios.study.scenario import load_scenario
from haven_sim.common import plugins

Row = dict[str, Any]


def plugin_item(kind: str, name: str) -> Any:
    """The item registered as `name` of `kind` (`cues`, `participants`, ...), as HAVEN uses it;
    fails the test in one line when it is not installed, or installed but left out."""
    reg = plugins.registry(kind)
    if name not in reg:
        hint = "" if name in reg.left_out else " (install the package into HAVEN's environment: pip install -e .)"
        pytest.fail(f"{reg.unknown(name)}{hint}", pytrace=False)
    return reg.get(name)


def batch_trial_row(
    scenario: str = "hallway",
    seed: int = 0,
    *,
    condition: str | None = None,
    model: str | None = None,
    robot: str | None = None,
    mission: str | None = None,
    params: Mapping[str, Mapping[str, Any]] | None = None,
    params_dir: Path | None = None,
) -> Row:
    """One batch trial, as `haven batch SCENARIO --seeds SEED --grid ...` runs it, and its row:
    `condition` a cue condition, `model` the participants' model, `robot` a robot, `mission` the
    robot's mission behaviour (`robot.order` of the scenario), `params` node -> {parameter: value}
    as a parameter file's `ros__parameters` (written into `params_dir`)."""
    axes = parse_grid(
        [f"{k}={v}" for k, v in (("condition", condition), ("model", model), ("robot", robot)) if v is not None]
    )
    s = load_scenario(scenario)
    if mission is not None:
        plugin_item("missions", mission)
        s = replace(s, robot_order=mission)
    params_file = None
    if params:
        if params_dir is None:
            raise ValueError("batch_trial_row: params need a params_dir to write the parameter file into")
        params_file = params_dir / "params.yaml"
        params_file.write_text(
            yaml.safe_dump({node: {"ros__parameters": dict(values)} for node, values in params.items()})
        )
    specs = plan_sweep([s], axes, (check_seed(seed),))
    (row,) = run_rows(specs, load_suite_config(params_file, TRIAL_SETS))
    return row


@pytest.fixture
def haven_plugin() -> Callable[[str, str], Any]:
    """`haven_plugin(kind, name)`: the registered item (kind plural or singular: `cue` or `cues`)."""

    def get(kind: str, name: str) -> Any:
        try:
            return plugin_item(plugins.kind_named(kind), name)
        except plugins.PluginError as e:
            pytest.fail(str(e), pytrace=False)

    return get


@pytest.fixture
def haven_trial(tmp_path: Path) -> Callable[..., Row]:
    """`haven_trial(scenario="hallway", seed=0, condition=, model=, robot=, mission=, params=)`: one
    batch trial's row (see `batch_trial_row`)."""

    def run(scenario: str = "hallway", seed: int = 0, **options: Any) -> Row:
        return batch_trial_row(scenario, seed, params_dir=tmp_path, **options)

    return run
