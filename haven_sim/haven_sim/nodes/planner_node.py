"""Planner node: /goal_pose in, /plan out (HAVEN's rotate / arc / straight path), human-aware.

Plans on whatever /map holds (ours or any nav_msgs/OccupancyGrid), from the robot's /odom pose, and
watches /humans: a human on the upcoming path makes the robot wait (latched /haven/wait) or detour.
The behaviour is `haven_sim.nav.planning.PlannerComponent`.
"""

from __future__ import annotations

import sys
from collections.abc import Sequence

from haven_sim.common import nodes
from haven_sim.nav.planning import PlannerComponent, PlannerConfig, world_lanes
from haven_sim.nodes import wire
from haven_sim.nodes.component_node import ComponentNode
from haven_sim.nodes.runner import run_node
from haven_sim.sim.world import resolve_world_path
from haven_sim.sim.world_file import load_world


class PlannerNode(ComponentNode):
    def __init__(self, cli_args: Sequence[str] | None = None) -> None:
        super().__init__(nodes.PLANNER.name, cli_args)
        config = self.declare_config(PlannerConfig)
        lanes = world_lanes(load_world(resolve_world_path(config.world))) if config.world else ()
        component = PlannerComponent(config, lanes)
        self.wire(component, wire.specs(wire.Frames(map=config.map_frame)))


def main(args: list[str] | None = None) -> None:
    sys.exit(run_node(PlannerNode, args))


if __name__ == "__main__":
    main()
