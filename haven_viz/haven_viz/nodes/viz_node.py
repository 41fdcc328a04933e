"""Visualization node: HAVEN's AR cues on /haven/ar_markers, what they show on /haven/cue_state,
the world on /haven/world_markers.

The behaviour is `haven_viz.viz.VizComponent`; this node wires it to topics and turns the four cue
toggles (`path_projection`, `turn_signals`, `thought_bubble`, `battery_indicator`) into run-time
parameters: the study condition, settable while a trial runs (`ros2 param set /viz thought_bubble
false`, Foxglove's Parameters panel, or any SetParameters client); every change is an event.
"""

from __future__ import annotations

import sys
from collections.abc import Sequence

from rcl_interfaces.msg import SetParametersResult
from rclpy.parameter import Parameter

from haven_sim.common import nodes, topics
from haven_sim.nodes import wire
from haven_sim.nodes.component_node import ComponentNode
from haven_sim.nodes.runner import run_node
from haven_sim.sim.world import resolve_world_path
from haven_sim.sim.world_file import load_world
from haven_viz.cues import CUES
from haven_viz.nodes.conversions import viz_specs
from haven_viz.viz import VizComponent, VizConfig


class VizNode(ComponentNode):
    def __init__(self, cli_args: Sequence[str] | None = None) -> None:
        super().__init__(nodes.VIZ.name, cli_args)
        config = self.declare_config(VizConfig)
        world = load_world(resolve_world_path(config.world)) if config.world else None
        self.viz = VizComponent(config, world)
        frames = wire.Frames(map=config.map_frame)
        self.wire(
            self.viz,
            {**wire.specs(frames, [h.id for h in world.humans] if world else []), **viz_specs(config.map_frame)},
        )
        self._viewers = 0
        self.add_post_set_parameters_callback(self._toggles_set)
        self.create_timer(self.viz.period_s, self._count_viewers)

    def _check_parameters(self, params: list[Parameter]) -> SetParametersResult:
        for p in params:
            if p.name in CUES and p.type_ != Parameter.Type.BOOL:
                return SetParametersResult(successful=False, reason=f"{p.name} must be true or false")
        return super()._check_parameters(params)

    def _toggles_set(self, params: list[Parameter]) -> None:
        changes = {p.name: bool(p.value) for p in params if p.name in CUES}
        if changes:
            for name, on in changes.items():
                self.get_logger().info(f"{name} {'on' if on else 'off'}")
            self.emit(self.viz.set_toggles(changes, self.now()))

    def _count_viewers(self) -> None:
        """A viewer (or recorder) that joins late must get the markers that have not changed since."""
        viewers = self._pubs[topics.AR_MARKERS].get_subscription_count()
        if viewers > self._viewers:
            self.viz.viewer_joined()
        self._viewers = viewers


def main(args: list[str] | None = None) -> None:
    sys.exit(run_node(VizNode, args))


if __name__ == "__main__":
    main()
