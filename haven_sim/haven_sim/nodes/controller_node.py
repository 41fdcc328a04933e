"""Controller node: follows any nav_msgs/Path on /plan in HAVEN's motion style -> /cmd_vel_nav.

Holds still while /haven/wait (latched Bool) is true or the path is empty; reports arrival once per
path as a `goal_reached` event. The behaviour is `haven_sim.nav.controller.ControllerComponent`.
"""

from __future__ import annotations

import sys
from collections.abc import Sequence

from haven_sim.common import nodes
from haven_sim.nav.controller import ControllerComponent, ControllerConfig
from haven_sim.nodes import wire
from haven_sim.nodes.component_node import ComponentNode
from haven_sim.nodes.runner import run_node


class ControllerNode(ComponentNode):
    def __init__(self, cli_args: Sequence[str] | None = None) -> None:
        super().__init__(nodes.CONTROLLER.name, cli_args)
        self.wire(ControllerComponent(self.declare_config(ControllerConfig)), wire.specs())


def main(args: list[str] | None = None) -> None:
    sys.exit(run_node(ControllerNode, args))


if __name__ == "__main__":
    main()
