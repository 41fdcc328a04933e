"""Velocity mux node: /cmd_vel_teleop beats /cmd_vel_nav; /haven/estop (latched Bool) forces zero.

The behaviour is `haven_sim.nav.mux.MuxComponent`; this node only wires it to topics.
"""

from __future__ import annotations

import sys
from collections.abc import Sequence

from haven_sim.common import nodes
from haven_sim.nav.mux import MuxComponent, MuxConfig
from haven_sim.nodes import wire
from haven_sim.nodes.component_node import ComponentNode
from haven_sim.nodes.runner import run_node


class MuxNode(ComponentNode):
    def __init__(self, cli_args: Sequence[str] | None = None) -> None:
        super().__init__(nodes.MUX.name, cli_args)
        self.wire(MuxComponent(self.declare_config(MuxConfig)), wire.specs())


def main(args: list[str] | None = None) -> None:
    sys.exit(run_node(MuxNode, args))


if __name__ == "__main__":
    main()
