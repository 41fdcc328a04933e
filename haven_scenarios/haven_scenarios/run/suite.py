"""The node suite's configuration from one source: each node's config dataclass, read from a ROS
parameter file the same way in ROS mode (the nodes declare from these classes) and in batch mode
(built here), and the shipped haven.yaml rendered from them."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, fields
from importlib import resources
from pathlib import Path
from typing import Any

from haven_scenarios.study.director import ScenarioNodeConfig
from haven_sim.common import nodes
from haven_sim.common.contain import PluginDeadlines
from haven_sim.common.params import (
    WILDCARD,
    ParamsError,
    check_names,
    defaults,
    flatten,
    load_params_file,
    node_values,
    render_params_file,
)
from haven_sim.common.topics import WireParams
from haven_sim.common.yaml_file import file_label, short
from haven_sim.nav.controller import ControllerConfig
from haven_sim.nav.motion_style import MotionStyle
from haven_sim.nav.mux import MuxConfig
from haven_sim.nav.planning import PlannerConfig
from haven_sim.robots.fields import RobotChoice, build_config, robot_figures
from haven_sim.runtime.lockstep import LockstepParams
from haven_sim.sim.simulator import SimulatorConfig
from haven_viz.cues import CUES
from haven_viz.viz import VizConfig

# (node name, its config class): the order of haven.yaml; SuiteConfig's first fields in the same order.
NODES: tuple[tuple[str, type[Any]], ...] = (
    (nodes.SIM.name, SimulatorConfig),
    (nodes.MUX.name, MuxConfig),
    (nodes.PLANNER.name, PlannerConfig),
    (nodes.CONTROLLER.name, ControllerConfig),
    (nodes.VIZ.name, VizConfig),
    (nodes.SCENARIO.name, ScenarioNodeConfig),
)
SHARED = (
    RobotChoice,
    MotionStyle,
    LockstepParams,
    WireParams,
    PluginDeadlines,
)  # one section: the robot, HAVEN's turning rule, the lockstep switch, the velocity topics' type, plugin deadlines
HEADER = """Parameters of every HAVEN node, with their defaults (pass with --params-file to `haven sim`,
`haven run` or `haven batch`, or to any node). Generated from the config dataclasses by
`python -m haven_scenarios.run.suite`: edit those, not this file. The "/**" section applies to
every node that has the parameter (the planner and the controller share the motion style)."""


def packaged_params_file() -> Path:
    return Path(str(resources.files("haven_sim") / "config" / "haven.yaml"))


@dataclass(frozen=True)
class SuiteConfig:
    sim: SimulatorConfig = field(default_factory=SimulatorConfig)
    mux: MuxConfig = field(default_factory=MuxConfig)
    planner: PlannerConfig = field(default_factory=PlannerConfig)
    controller: ControllerConfig = field(default_factory=ControllerConfig)
    viz: VizConfig = field(default_factory=VizConfig)
    scenario: ScenarioNodeConfig = field(default_factory=ScenarioNodeConfig)
    lockstep: LockstepParams = field(default_factory=LockstepParams)  # every node's
    deadlines: PluginDeadlines = field(default_factory=PluginDeadlines)  # every node's (and batch mode's)

    def by_node(self) -> dict[str, Any]:
        """Node name -> its config."""
        return {name: getattr(self, f.name) for (name, _), f in zip(NODES, fields(self)[: len(NODES)], strict=True)}


def render(config: SuiteConfig | None = None, header: str = HEADER) -> str:
    """The parameter file of `config` (default: haven.yaml, every default)."""
    if config is None:
        return render_params_file(NODES, SHARED, header)
    values: dict[str, Any] = {name: flatten(c) for name, c in config.by_node().items()}
    values[WILDCARD] = (
        flatten(config.sim.robot) | flatten(config.planner.style) | flatten(config.lockstep) | flatten(config.deadlines)
    )
    return render_params_file(NODES, SHARED, header, values)


def suite_config(params: Mapping[str, Mapping[str, Any]] | None = None, label: str = "") -> SuiteConfig:
    """Every node's config from a loaded parameter file (None: the defaults); `label` names the
    file in refusals."""
    p = params or {}
    where = f"{label}: " if label else ""
    made = {
        f.name: build_config(cls, node_values(p, name), where=f"{where}{name}: ")
        for (name, cls), f in zip(NODES, fields(SuiteConfig)[: len(NODES)], strict=True)
    }
    shared = node_values(p, nodes.SIM.name)  # (the "/**" section's values, as every node reads them)
    lockstep = build_config(LockstepParams, shared, where=f"{where}sim_node: ")
    return SuiteConfig(
        **made, lockstep=lockstep, deadlines=build_config(PluginDeadlines, shared, where=f"{where}sim_node: ")
    )


# Parameters every node has beside its config: rclpy's own (a node declares them itself) and what
# every component node declares (the velocity topics' type, the lockstep switch).
ROS_BUILTIN = {"use_sim_time": False, "start_type_description_service": True}
EVERY_NODE = (WireParams, LockstepParams, PluginDeadlines)


def known_parameters() -> dict[str, dict[str, Any]]:
    """Node name -> the parameters it declares (with their defaults): what a parameter file may set."""
    common = {**ROS_BUILTIN, **{k: v for cls in EVERY_NODE for k, v in defaults(cls).items()}}
    return {name: {**common, **defaults(cls)} for name, cls in NODES}


# What a trial (`haven run`, `haven batch`, `haven study run`) sets itself, from its options and the
# scenario file: a parameter file's own value for one of these would be overwritten without a word.
_CONDITION = "the condition (--condition, or the scenario's)"
TRIAL_SETS: Mapping[tuple[str, str], str] = {
    **{(node.name, "world"): "the scenario's world (--world)" for node in (nodes.SIM, nodes.PLANNER, nodes.VIZ)},
    **{(nodes.VIZ.name, cue): _CONDITION for cue in CUES},
    (nodes.SIM.name, "seed"): "--seed",
    (nodes.SCENARIO.name, "seed"): "--seed",
    (WILDCARD, "robot"): "--robot (or the scenario's robot: model)",
    (nodes.SIM.name, "battery_pack_m"): "the scenario file (robot: battery: capacity_m)",
    (nodes.SIM.name, "real_time_factor"): "--rtf",
    (nodes.SCENARIO.name, "scenario"): "the scenario haven runs",
    (nodes.SCENARIO.name, "hold_start"): "--web (and --researcher-start)",
    (nodes.SCENARIO.name, "wait_for"): "haven run (--without)",
    (nodes.SIM.name, "reset_allowed"): "haven run",
    **{(nodes.SIM.name, f"lockstep_{k}"): "haven run" for k in ("participants", "observers", "wait_for")},
    (WILDCARD, "lockstep"): "haven run (--free-running for the free-running clock)",
    (WILDCARD, "lockstep_open"): "--allow",
}
SIM_SETS: Mapping[tuple[str, str], str] = {
    **{(node.name, "world"): "--world" for node in (nodes.SIM, nodes.PLANNER, nodes.VIZ)},
    (nodes.SIM.name, "real_time_factor"): "--rtf",
    (WILDCARD, "robot"): "--robot",
}


def load_suite_config(path: str | Path | None, sets: Mapping[tuple[str, str], str] | None = None) -> SuiteConfig:
    """Every node's config from a parameter file (None: the defaults), as strict as a study file:
    the file is first read as any file a user hands us (`read_yaml`: a regular file of at most 1 MiB
    of UTF-8, bounded nesting and aliases), then `checked_suite_config`; `sets`: what the command
    sets itself (a value other than the default there is refused, naming the option to use)."""
    return suite_config(None) if path is None else checked_suite_config(load_params_file(path), file_label(path), sets)


def checked_suite_config(
    params: Mapping[str, Mapping[str, Any]], label: str, sets: Mapping[tuple[str, str], str] | None = None
) -> SuiteConfig:
    """A node or a parameter that no node has, a number that is not finite, a value of the wrong
    type, and one the command sets itself are refused in one line naming file (`label`), node and
    key: the nodes themselves would silently ignore a misspelt name and run on the default."""
    known = known_parameters()
    check_names(params, known, label, elsewhere=robot_figures())
    for (node, name), option in (sets or {}).items():
        for section in dict.fromkeys((node, WILDCARD)):
            value = params.get(section, {}).get(name)
            if value is not None and value != known[nodes.SIM.name if node == WILDCARD else node][name]:
                raise ParamsError(f"{label}: {section}: {name}: set by {option}, not by a parameter file")
    for node, values in params.items():  # (rclpy's own parameters are booleans; the configs check the rest)
        for name in ROS_BUILTIN.keys() & values.keys():
            if not isinstance(values[name], bool):
                raise ParamsError(f"{label}: {node}: {name}: must be true or false, got {short(values[name])}")
    return suite_config(params, label)


if __name__ == "__main__":
    packaged_params_file().write_text(render())
    print(f"wrote {packaged_params_file()}")
