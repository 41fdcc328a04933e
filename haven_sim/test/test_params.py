"""One source of parameters: pydantic config dataclasses flattened to ROS parameters and built back."""

import math

import pytest

from haven_sim.common.params import (
    FRACTION,
    POSITIVE,
    Bounds,
    ParamsError,
    build,
    config,
    defaults,
    docs,
    flatten,
    group,
    leaves,
    load_params_file,
    node_values,
    param,
    render_params_file,
    ros_range,
)
from haven_sim.nav.controller import ControllerConfig
from haven_sim.nav.planning import PlannerConfig
from haven_sim.robots.fields import build_config
from haven_sim.sim.simulator import SimulatorConfig


@config
class Inner:
    capacity_m: float = param(10.0, "size")
    on: bool = param(True, "switch")


@config
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
    with pytest.raises(ParamsError, match=f"node: {name}: {expected}, got ") as info:
        build(Outer, {name: value}, where="node: ")
    assert "\n" not in str(info.value)


def test_validation_of_the_core_configs_names_the_parameter():
    with pytest.raises(ParamsError, match="rate_hz: must be positive"):
        build_config(ControllerConfig, {"rate_hz": 0.0})
    with pytest.raises(ParamsError, match="battery_pack_m: must not be negative"):
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


@config
class Bounded:
    rate: float = param(1.0, "r", POSITIVE)
    share: float = param(0.5, "s", FRACTION)
    angle: float = param(90.0, "a", Bounds(0.0, 360.0, low_open=True))
    cap: int = param(1, "c", Bounds(high=5))
    toggle: bool = param(True, "t", runtime=True)

    def __post_init__(self) -> None:
        if self.share == 0.25:
            raise ValueError("share must not be a quarter")


@pytest.mark.parametrize(
    "given,said",
    [
        ({"rate": 0.0}, "rate: must be positive, got 0.0"),
        ({"rate": math.nan}, "rate: must be a finite number, got nan"),
        ({"share": 1.5}, r"share: must be within 0\.\.1, got 1\.5"),
        ({"angle": 0.0}, r"angle: must be within \(0, 360\], got 0\.0"),
        ({"cap": 6}, "cap: must be at most 5, got 6"),
        ({"cap": 1.0}, "cap: must be an integer, got 1.0"),
        ({"share": 0.25}, "share must not be a quarter"),  # (the config's own check, as it said it)
    ],
)
def test_pydantic_checks_a_config_made_in_code_in_one_line(given, said):
    with pytest.raises(ParamsError, match=f"^{said}$"):
        Bounded(**given)


def test_bounds_are_declared_with_the_parameter_and_say_what_is_allowed():
    by_name = {leaf.name: leaf for leaf in leaves(Bounded)}
    assert by_name["share"].bounds == FRACTION and ros_range(by_name["share"].bounds) == (0.0, 1.0)
    assert ros_range(by_name["rate"].bounds) is None  # (ROS ranges have two closed ends)
    assert by_name["rate"].doc == "r" and by_name["toggle"].runtime and not by_name["rate"].runtime
    with pytest.raises(ParamsError, match=r"^sim: battery_initial_level: must be within 0\.\.1, got 2\.0$"):
        build_config(SimulatorConfig, {"battery_initial_level": 2.0}, where="sim: ")


def test_ros_spellings_of_values_become_the_declared_type():
    made = build(Outer, {"ids": ["", "b"], "battery_capacity_m": "1e-3"})  # (an empty string array is [''] in ROS)
    assert made.ids == ("b",) and made.inner.capacity_m == 0.001
