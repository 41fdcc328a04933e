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
from haven_sim.common.params import WILDCARD, ParamsError, build, flatten, load_params_file, node_values, render_params_file
from haven_sim.common.topics import WireParams
from haven_sim.common.yaml_file import file_label, finite, read_yaml, short, shown_key
from haven_sim.nav.controller import ControllerConfig
from haven_sim.nav.motion_style import MotionStyle
from haven_sim.nav.mux import MuxConfig
from haven_sim.nav.planning import PlannerConfig
from haven_sim.runtime.lockstep import LockstepParams
from haven_sim.sim.simulator import SimulatorConfig
from haven_viz.viz import VizConfig

# (node name, its config class): the order of haven.yaml; SuiteConfig's fields in the same order.
NODES: tuple[tuple[str, type[Any]], ...] = (
    ("sim_node", SimulatorConfig),
    ("velocity_mux", MuxConfig),
    ("planner", PlannerConfig),
    ("controller", ControllerConfig),
    ("viz", VizConfig),
    ("scenario", ScenarioNodeConfig),
)
SHARED = (MotionStyle, LockstepParams, WireParams)  # one section: HAVEN's turning rule, the lockstep switch, the velocity topics' type
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

    def by_node(self) -> dict[str, Any]:
        """Node name -> its config."""
        return {name: getattr(self, f.name) for (name, _), f in zip(NODES, fields(self))}


def render(config: SuiteConfig | None = None, header: str = HEADER) -> str:
    """The parameter file of `config` (default: haven.yaml, every default)."""
    if config is None:
        return render_params_file(NODES, SHARED, header)
    values: dict[str, Any] = {name: flatten(c) for name, c in config.by_node().items()}
    values[WILDCARD] = flatten(config.planner.style) | flatten(config.lockstep)
    return render_params_file(NODES, SHARED, header, values)


def suite_config(params: Mapping[str, Mapping[str, Any]] | None = None) -> SuiteConfig:
    """Every node's config from a loaded parameter file (None: the defaults)."""
    p = params or {}
    made = {f.name: build(cls, node_values(p, name), where=f"{name}: ") for (name, cls), f in zip(NODES, fields(SuiteConfig))}
    return SuiteConfig(**made, lockstep=build(LockstepParams, node_values(p, "sim_node")))


def load_suite_config(path: str | Path | None) -> SuiteConfig:
    """Every node's config from a parameter file (None: the defaults). The file is first read as any
    file a user hands us (`read_yaml`: a regular file of at most 1 MiB of UTF-8, bounded nesting and
    aliases), so a hostile one is refused in one line before its ROS structure is read."""
    if path is None:
        return suite_config(None)
    read_yaml(path, "parameter file", ParamsError)
    params = load_params_file(path)
    for node, values in params.items():  # an integer beyond a float's range would overflow where a float is expected
        for name, v in values.items():
            if isinstance(v, int) and not isinstance(v, bool) and finite(v) is None:
                raise ParamsError(f"{file_label(path)}: {shown_key(node)}: {shown_key(name)}: must be a finite number, got {short(v)}")
    return suite_config(params)


if __name__ == "__main__":
    packaged_params_file().write_text(render())
    print(f"wrote {packaged_params_file()}")
