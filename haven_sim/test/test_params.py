"""One source of parameters: config dataclasses flattened to ROS parameters and built back."""

import math
from dataclasses import dataclass

import pytest

from haven_sim.common.params import (
    FRACTION,
    POSITIVE,
    Bounds,
    ParamsError,
    build,
    defaults,
    docs,
    flatten,
    group,
    load_params_file,
    node_values,
    param,
    render_params_file,
)
from haven_sim.nav.controller import ControllerConfig
from haven_sim.nav.planning import PlannerConfig
from haven_sim.robots.fields import build_config
from haven_sim.sim.simulator import SimulatorConfig


@dataclass(frozen=True)
class Inner:
    capacity_m: float = param(10.0, "size")
    on: bool = param(True, "switch")


@dataclass(frozen=True)
class Outer:
    inner: Inner = group(Inner, prefix="battery_")
    name: str = param("x", "a name")
    ids: tuple[str, ...] = param(("a",), "some ids")


def test_flatten_prefixes_groups_and_build_reads_them_back():
    assert flatten(Outer()) == {"battery_capacity_m": 10.0, "battery_on": True, "name": "x", "ids": ["a"]}
    made = build(Outer, {"battery_capacity_m": 3, "ids": ["b", "c"], "unrelated": 1})
    assert made == Outer(Inner(3.0, True), "x", ("b", "c"))  # ints become floats; unknown names are ignored
    assert docs(Outer)["battery_on"] == "switch"


@pytest.mark.parametrize(
    "name,value,expected",
    [
        ("battery_on", "no", "must be true or false"),
        ("battery_capacity_m", True, "must be a finite number"),
        ("battery_capacity_m", math.inf, "must be a finite number"),
        ("name", 3, "must be a string"),
        ("ids", "a", "must be a list of strings"),
    ],
)
def test_wrong_types_are_refused_in_one_line(name, value, expected):
    with pytest.raises(ParamsError, match=f"node: {name}: {expected}") as info:
        build(Outer, {name: value}, where="node: ")
    assert "\n" not in str(info.value)


def test_validation_of_the_core_configs_names_the_parameter():
    with pytest.raises(ParamsError, match="rate_hz must be positive"):
        build_config(ControllerConfig, {"rate_hz": 0.0})
    with pytest.raises(ParamsError, match="battery_pack_m must not be negative"):
        build_config(SimulatorConfig, {"battery_pack_m": -1.0})
    with pytest.raises(ParamsError, match="unknown robot 'no_such_bot'"):
        build_config(SimulatorConfig, {"robot": "no_such_bot"})


def test_shared_motion_style_has_the_same_names_in_planner_and_controller():
    shared = {"arc_max_angle_deg", "too_close_distance_m", "facing_tolerance_deg", "rotate_speed_deg_s"}
    assert shared <= set(defaults(PlannerConfig)) and shared <= set(defaults(ControllerConfig))
    built = build_config(PlannerConfig, {"arc_max_angle_deg": 45.0})
    assert built.style.arc_max_angle_deg == 45.0
    assert build_config(ControllerConfig, {"arc_max_angle_deg": 45.0}).style == built.style


def test_params_files_wildcard_then_node(tmp_path):
    f = tmp_path / "p.yaml"
    f.write_text('"/**":\n  ros__parameters: {a: 1, b: 1}\nplanner:\n  ros__parameters: {b: 2}\n')
    values = load_params_file(f)
    assert node_values(values, "planner") == {"a": 1, "b": 2} and node_values(values, "viz") == {"a": 1, "b": 1}
    f.write_text("planner: [1, 2]\n")
    with pytest.raises(ParamsError, match="planner: needs a 'ros__parameters' mapping"):
        load_params_file(f)
    with pytest.raises(ParamsError, match="cannot read parameter file: No such file"):
        load_params_file(tmp_path / "missing.yaml")


def test_rendered_file_has_every_parameter_once_and_reads_back(tmp_path):
    text = render_params_file([("outer", Outer)], header="hello")
    assert text.startswith("# hello\nouter:\n  ros__parameters:\n")
    f = tmp_path / "p.yaml"
    f.write_text(text)
    assert build(Outer, node_values(load_params_file(f), "outer")) == Outer()


def test_bounds_are_declared_with_the_parameter_and_say_what_is_allowed():
    assert POSITIVE.problem(0.0) == "must be positive" and POSITIVE.problem(1e-9) is None
    assert FRACTION.problem(1.5) == "must be within 0..1" and FRACTION.problem(1.0) is None
    assert Bounds(0.0, 360.0, low_open=True).problem(0.0) == "must be within (0, 360]"
    assert (
        Bounds(high=5.0).problem(6) == "must be at most 5" and POSITIVE.problem(math.nan) == "must be a finite number"
    )
    with pytest.raises(ParamsError, match=r"^sim: battery_initial_level must be within 0\.\.1, got 2\.0$"):
        build_config(SimulatorConfig, {"battery_initial_level": 2.0}, where="sim: ")
