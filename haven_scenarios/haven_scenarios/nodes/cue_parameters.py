"""The viz node's four cue toggles as Foxglove parameters, named as Foxglove's ROS bridge names node
parameters ('/viz.path_projection'), read and set through the viz node's parameter services (so a
change is a `cue_toggled` event, as from any other client). Used by the researcher console and by
`haven bridge` (Foxglove's Parameters panel).

The calls wait for the viz node's answer: make them from a thread other than the node's executor
(Foxglove's server callbacks run on its own threads)."""

from __future__ import annotations

import threading
from typing import Any

from foxglove import Parameter as FoxgloveParameter
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.parameter_client import AsyncParameterClient

from haven_sim.common import nodes
from haven_viz.cues import CUES

VIZ_NODE = nodes.VIZ.name
PARAMETER_TIMEOUT_S = 5.0


def parameter_name(cue: str) -> str:
    """A cue toggle as Foxglove's ROS bridge names node parameters: '/viz.path_projection'."""
    return f"/{VIZ_NODE}.{cue}"


class CueParameters:
    def __init__(self, node: Node) -> None:
        self.node = node
        self.client = AsyncParameterClient(node, VIZ_NODE)

    def _ready(self) -> bool:
        """The viz node's parameter services found (a client that asks right after start-up, or
        on a busy machine, is answered once they are, within the timeout)."""
        if self.client.services_are_ready() or self.client.wait_for_services(timeout_sec=PARAMETER_TIMEOUT_S):
            return True
        self.node.get_logger().warning(
            f"no {VIZ_NODE} node answers parameter requests (within {PARAMETER_TIMEOUT_S:g} s)"
        )
        return False

    def _wait(self, future: Any) -> Any:
        done = threading.Event()
        future.add_done_callback(lambda _: done.set())
        if not done.wait(PARAMETER_TIMEOUT_S):
            self.node.get_logger().warning(f"the {VIZ_NODE} node did not answer within {PARAMETER_TIMEOUT_S:g} s")
            return None
        return future.result()

    def get(self, names: list[str]) -> list[FoxgloveParameter]:
        """The toggles named (all of them for no names)."""
        cues = [c for c in CUES if not names or parameter_name(c) in names]
        result = self._wait(self.client.get_parameters(cues)) if cues and self._ready() else None
        if result is None:
            return []
        return [
            FoxgloveParameter(parameter_name(c), value=bool(v.bool_value))
            for c, v in zip(cues, result.values, strict=False)
        ]

    def set(self, parameters: list[FoxgloveParameter]) -> list[FoxgloveParameter]:
        """Set the toggles among `parameters` (others and non-booleans are ignored); all of them, as they now are."""
        by_name = {parameter_name(c): c for c in CUES}
        values = {p.name: p.get_value() for p in parameters}
        changes = [
            Parameter(by_name[n], value=bool(v)) for n, v in values.items() if n in by_name and isinstance(v, bool)
        ]
        if changes and self._ready():
            self._wait(self.client.set_parameters(changes))
        return self.get([])
