"""The Jazzy-safe node `main()` shared by every HAVEN node (ros2/examples `composed.py` shape)."""

from __future__ import annotations

import sys
import time
from collections.abc import Callable, Sequence

import rclpy
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor
from rclpy.node import Node

from haven_sim.sim.world import WorldError


def run_node(factory: Callable[[], Node], args: Sequence[str] | None = None) -> int:
    """Init, build, spin until Ctrl-C or shutdown, clean up. Configuration errors become one line
    on stderr and exit code 2, never a traceback."""
    rclpy.init(args=list(args) if args is not None else None)
    node: Node | None = None
    try:
        try:
            node = factory()
        except (WorldError, ValueError) as e:  # bad world or parameters: one line, no traceback
            print(f"error: {e}", file=sys.stderr)
            return 2
        executor = SingleThreadedExecutor()
        executor.add_node(node)
        executor.spin()
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    except RuntimeError:
        # rclpy can fail to take a message that arrives while Ctrl-C shuts the context down;
        # that is a clean stop (the shutdown completes a moment later), anything else is a bug
        # and keeps its traceback.
        time.sleep(0.1)
        if rclpy.ok():
            raise
    finally:
        if node is not None:
            node.destroy_node()
        rclpy.try_shutdown()
    return 0
