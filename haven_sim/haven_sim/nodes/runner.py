"""How every HAVEN node process runs: init, build, spin until asked to stop, clean up.

A stop signal (SIGINT, SIGTERM, SIGHUP, and the other catchable ones that would end the process)
only sets a flag that the spin loop checks between callbacks: no KeyboardInterrupt lands in the middle of a callback or
of a message being deserialised, and `destroy_node` runs while the context still works, so a node can still read its
subscriptions then (the recorder writes what its readers hold into the bag).
"""

from __future__ import annotations

import signal
import sys
import threading
import time
import traceback
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

import rclpy
from rcl_interfaces.msg import ParameterDescriptor, SetParametersResult
from rclpy.exceptions import InvalidParameterTypeException
from rclpy.executors import ExternalShutdownException, MultiThreadedExecutor, SingleThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.signals import SignalHandlerOptions

from haven_sim.common.component import Message
from haven_sim.common.params import ParamsError
from haven_sim.runtime.process import STOP_SIGNALS
from haven_sim.sim.world import WorldError

THROTTLE_S = 5.0  # lines about input a node cannot use: at most one per call site in this many seconds
POLL_S = 0.1  # how soon a stop request is noticed when nothing else happens
_stop = threading.Event()


def stop_requested() -> bool:
    """For the few loops that wait inside a callback: give up when the process is asked to stop."""
    return _stop.is_set()


def _on_signal(signum: int, frame: Any) -> None:
    _stop.set()


def callback_failed(node: Node, e: BaseException) -> None:
    """The last line of defence against input no check foresaw (rclpy's own /clock reader raises
    on a negative time, for one): the callback that raised is abandoned with one throttled error
    line naming the exception and where it was raised, and the node keeps running."""
    frame = traceback.extract_tb(e.__traceback__)[-1] if e.__traceback__ is not None else None
    where = f" ({Path(frame.filename).name}:{frame.lineno})" if frame is not None else ""
    text = str(e).splitlines()[0][:200] if str(e) else ""
    node.get_logger().error(
        f"a callback failed and was skipped: {type(e).__name__}: {text}{where}", throttle_duration_sec=THROTTLE_S
    )


def refused(node: Node, topic: str, reason: object) -> None:
    """One throttled line for a message a node cannot use, naming the topic and why."""
    node.get_logger().warning(
        f"ignored a message on {node.resolve_topic_name(topic)}: {reason}", throttle_duration_sec=THROTTLE_S
    )


def handle(
    node: Node, topic: str, handler: Callable[[Any, float], Sequence[Message]], data: Any, now: float
) -> Sequence[Message]:
    """A component's handler on one input: a ValueError is the component refusing it (a warning
    naming the topic), anything else a failure of that message alone (`callback_failed`); either
    way the node, and a lockstep tick in progress, go on."""
    try:
        return handler(data, now)
    except ValueError as e:
        refused(node, topic, e)
    except Exception as e:
        callback_failed(node, e)
    return []


def start_up_only(
    node: Node, params: Sequence[Parameter], allowed: frozenset[str] = frozenset()
) -> tuple[str, str] | None:
    """(the parameter, why) a change is refused, or None: once a node runs, only the `allowed`
    parameters change; any other it has (its own, and rclpy's use_sim_time: time must not switch
    clocks mid-trial) is read at start-up only. (A parameter being declared does not exist yet.)"""
    for p in params:
        if node.has_parameter(p.name) and p.name not in allowed:
            reason = f"{p.name}: read at start-up only; restart the node to change it"
            node.get_logger().warning(f"refused to set {reason}", throttle_duration_sec=2.0)
            return p.name, reason
    return None


def refuse_changes(node: Node, on_refused: Callable[[str, str], None] | None = None) -> None:
    """Refuse every parameter change once the node runs (`start_up_only`); `on_refused(name, reason)`."""

    def check(params: list[Parameter]) -> SetParametersResult:
        refused = start_up_only(node, params)
        if refused is None:
            return SetParametersResult(successful=True)
        if on_refused is not None:
            on_refused(*refused)
        return SetParametersResult(successful=False, reason=refused[1])

    node.add_on_set_parameters_callback(check)


def declare(node: Node, name: str, default: Any, descriptor: ParameterDescriptor | None = None) -> Any:
    """Declare a parameter and return its value. Read at start-up only, it is read-only unless
    `descriptor` says otherwise (so `ros2 param set`, rqt_reconfigure and Foxglove do not offer to
    change what the node would not act on). A list is a string array, also when empty (rclpy types
    `[]` as a byte array). ParamsError (one line) for a list given as something else."""
    d = descriptor if descriptor is not None else ParameterDescriptor(read_only=True)
    listed = isinstance(default, list)
    d.dynamic_typing = not listed
    try:
        value = node.declare_parameter(
            name, Parameter.Type.STRING_ARRAY if listed and not default else default, d
        ).value
    except InvalidParameterTypeException:
        raise ParamsError(f"{node.get_name()}: parameter {name}: must be a list of strings") from None
    if listed and value is None:  # declared by its type (or `[]` on the command line): the empty string array
        # (rclpy's public calls would infer a byte array from [] or leave it unset; its own store takes the typed value)
        node._parameters[name] = Parameter(name, Parameter.Type.STRING_ARRAY, [])
        return []
    return value


def _drain(executor: Any, timeout_s: float = 2.0) -> None:
    """Let the callbacks still running on a MultiThreadedExecutor's threads finish before it shuts
    down (rclpy 7's Executor.shutdown does not wait for them, it tests the flag it has just set, and
    destroys the guard condition each one triggers as it ends: "exception was never retrieved")."""
    deadline = time.monotonic() + timeout_s
    for task in list(getattr(executor, "_futures", ())):  # (its running callbacks: no public way to them)
        while not task.done() and time.monotonic() < deadline:
            time.sleep(0.01)


def run_node(factory: Callable[[], Node | Sequence[Node]], args: Sequence[str] | None = None, threads: int = 1) -> int:
    """Configuration errors become one line on stderr and exit code 2, never a traceback. The
    factory may make several nodes (one process, one executor); with `threads` above 1 their
    callbacks run on that many threads (for callbacks that wait, as action servers' do)."""
    rclpy.init(args=list(args) if args is not None else None, signal_handler_options=SignalHandlerOptions.NO)
    for sig in STOP_SIGNALS:
        signal.signal(sig, _on_signal)
    made: list[Node] = []
    try:
        try:
            got = factory()
            made = [got] if isinstance(got, Node) else list(got)
        except (WorldError, ValueError) as e:  # bad world or parameters: one line, no traceback
            print(f"error: {e}", file=sys.stderr)
            return 2
        executor = SingleThreadedExecutor() if threads == 1 else MultiThreadedExecutor(num_threads=threads)
        for node in made:
            executor.add_node(node)
        while not _stop.is_set():
            try:
                executor.spin_once(timeout_sec=POLL_S)
            except ExternalShutdownException:
                raise
            except Exception as e:
                callback_failed(made[0], e)
        _drain(executor)
        executor.shutdown(timeout_sec=1.0)
    except ExternalShutdownException:
        pass
    finally:
        for node in made:
            node.destroy_node()
        rclpy.try_shutdown()
    return 0
