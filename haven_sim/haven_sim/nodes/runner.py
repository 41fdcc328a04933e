"""How every HAVEN node process runs: init, build, spin until asked to stop, clean up.

A stop signal (SIGINT, SIGTERM, SIGHUP) only sets a flag that the spin loop checks between
callbacks: no KeyboardInterrupt lands in the middle of a callback or of a message being
deserialised, and `destroy_node` runs while the context still works, so a node can still read its
subscriptions then (the recorder writes what its readers hold into the bag).
"""

from __future__ import annotations

import signal
import sys
import threading
from collections.abc import Callable, Sequence
from typing import Any

import rclpy
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions

from haven_sim.sim.world import WorldError

STOP_SIGNALS = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)
POLL_S = 0.1  # how soon a stop request is noticed when nothing else happens
_stop = threading.Event()


def stop_requested() -> bool:
    """For the few loops that wait inside a callback: give up when the process is asked to stop."""
    return _stop.is_set()


def _on_signal(signum: int, frame: Any) -> None:
    _stop.set()


def run_node(factory: Callable[[], Node], args: Sequence[str] | None = None) -> int:
    """Configuration errors become one line on stderr and exit code 2, never a traceback."""
    rclpy.init(args=list(args) if args is not None else None, signal_handler_options=SignalHandlerOptions.NO)
    for sig in STOP_SIGNALS:
        signal.signal(sig, _on_signal)
    node: Node | None = None
    try:
        try:
            node = factory()
        except (WorldError, ValueError) as e:  # bad world or parameters: one line, no traceback
            print(f"error: {e}", file=sys.stderr)
            return 2
        executor = SingleThreadedExecutor()
        executor.add_node(node)
        while not _stop.is_set():
            executor.spin_once(timeout_sec=POLL_S)
    except ExternalShutdownException:
        pass
    finally:
        if node is not None:
            node.destroy_node()
        rclpy.try_shutdown()
    return 0
