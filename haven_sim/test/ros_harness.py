"""ROS test harness shared by the three packages' cross-process tests.

Each harness owns a ROS_DOMAIN_ID of its own, starts nodes as separate processes (each in its own
session, stopped by pid at the end), and waits on conditions with deadlines: publisher/subscriber
matching, a message, an exit code. Never a bare sleep.
"""

from __future__ import annotations

import importlib
import itertools
import os
import signal
import subprocess
import sys
import time
from collections.abc import Callable, Iterator, Mapping, Sequence
from importlib import resources
from typing import Any

import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.publisher import Publisher
from rclpy.qos import QoSProfile
from rclpy.subscription import Subscription

from haven_sim.runtime.process import die_with_parent

_counter = itertools.count()


class Collected(list[Any]):
    """Messages received on one subscription, oldest first."""

    subscription: Subscription


def worker_domains() -> range:
    """This test worker's domains: under pytest-xdist each worker has a slice of 1..100 of its own,
    and the suites its tests start are held to that slice (HAVEN_DOMAINS, `RosHarness.env`), so a
    suite that moves to a free domain (run/domains.py) never lands on another worker's test."""
    count = int(os.environ.get("PYTEST_XDIST_WORKER_COUNT", "1"))
    worker = int(os.environ.get("PYTEST_XDIST_WORKER", "gw0").removeprefix("gw") or 0)
    size = 100 // max(count, 1)
    return range(1 + worker * size, 1 + (worker + 1) * size)


def next_domain_id() -> int:
    """A domain id of this worker's (`worker_domains`), and not one a HAVEN suite holds now (its
    lock, run/domains.py: a `haven run` the user started on this machine)."""
    ids = worker_domains()
    for _ in range(len(ids)):
        candidate = ids[(os.getpid() * 13 + next(_counter)) % len(ids)]
        if not _held(candidate):
            return candidate
    return candidate


def _held(domain_id: int) -> bool:
    try:
        from haven_scenarios.run.domains import lock_path
        from haven_scenarios.run.locks import FileLock, Locked
    except ImportError:  # (haven_sim's tests alone)
        return False
    lock = FileLock(lock_path(domain_id))
    try:
        lock.acquire()
    except Locked:
        return True
    except OSError:
        return False
    lock.release()
    return False


class RosHarness:
    def __init__(self, domain_id: int | None = None) -> None:
        self.domain_id = domain_id if domain_id is not None else next_domain_id()
        self.env = dict(os.environ)
        self.env.update(
            ROS_DOMAIN_ID=str(self.domain_id),
            ROS_AUTOMATIC_DISCOVERY_RANGE="LOCALHOST",
            FASTRTPS_DEFAULT_PROFILES_FILE=str(resources.files("haven_sim") / "config" / "fastdds.xml"),
            PYTHONUNBUFFERED="1",
        )
        ids = worker_domains()
        if int(os.environ.get("PYTEST_XDIST_WORKER_COUNT", "1")) > 1 and self.domain_id in ids:
            self.env.setdefault("HAVEN_DOMAINS", f"{ids[0]}-{ids[-1]}")  # (run/domains.py's DOMAINS_ENV)
        self._saved = {
            k: os.environ.get(k)
            for k in ("ROS_DOMAIN_ID", "ROS_AUTOMATIC_DISCOVERY_RANGE", "FASTRTPS_DEFAULT_PROFILES_FILE")
        }
        os.environ.update({k: self.env[k] for k in self._saved})
        self.context = rclpy.Context()
        rclpy.init(context=self.context)
        self.node = Node("haven_test_probe", context=self.context)
        self.executor = SingleThreadedExecutor(context=self.context)
        self.executor.add_node(self.node)
        self.procs: list[subprocess.Popen[str]] = []

    # -- processes -------------------------------------------------------------------------------
    def start(
        self, module: str, params: Mapping[str, Any] | None = None, args: Sequence[str] = (), capture: bool = False
    ) -> subprocess.Popen[str]:
        argv = [sys.executable, "-m", module, "--ros-args"]
        for k, v in (params or {}).items():
            v = ("true" if v else "false") if isinstance(v, bool) else v
            argv += ["-p", f"{k}:={v}"]
        argv += list(args)
        out = subprocess.PIPE if capture else None
        proc = subprocess.Popen(
            argv, env=self.env, start_new_session=True, stdout=out, stderr=out, text=True, preexec_fn=die_with_parent()
        )
        self.procs.append(proc)
        return proc

    def run(self, argv: Sequence[str], timeout_s: float = 60.0) -> subprocess.CompletedProcess[str]:
        """Run a command to completion in this harness's environment."""
        return subprocess.run(list(argv), env=self.env, capture_output=True, text=True, timeout=timeout_s)

    @staticmethod
    def stop(proc: subprocess.Popen[str], sig: int = signal.SIGINT, timeout_s: float = 10.0) -> int:
        if proc.poll() is None:
            try:
                os.killpg(proc.pid, sig)
                return proc.wait(timeout=timeout_s)
            except subprocess.TimeoutExpired:
                os.killpg(proc.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        return proc.wait()

    def close(self) -> None:
        for proc in self.procs:
            self.stop(proc)
        self.executor.shutdown()
        self.node.destroy_node()
        rclpy.try_shutdown(context=self.context)
        for k, v in self._saved.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v

    # -- waiting ---------------------------------------------------------------------------------
    def spin_until(self, condition: Callable[[], bool], timeout_s: float = 15.0) -> bool:
        deadline = time.monotonic() + timeout_s
        while time.monotonic() < deadline:
            if condition():
                return True
            self.executor.spin_once(timeout_sec=0.02)
        return condition()

    def spin_for(self, duration_s: float) -> None:
        """Process callbacks for a while (for collecting a stream, not for waiting on a condition)."""
        deadline = time.monotonic() + duration_s
        while time.monotonic() < deadline:
            self.executor.spin_once(timeout_sec=0.01)

    def collect(self, msg_type: Any, topic: str, qos: QoSProfile) -> Collected:
        """Subscribe; received messages are appended to the returned list."""
        received = Collected()
        received.subscription = self.node.create_subscription(msg_type, topic, received.append, qos)
        return received

    def stamps(self, topic: str, msgtype: str, qos: QoSProfile | None = None) -> list[tuple[float, float]]:
        """Subscribe to a topic of a stamped type (named like 'nav_msgs/msg/Odometry'); the returned
        list receives (monotonic arrival time, header stamp in seconds) per message."""
        package, kind, cls = msgtype.split("/")
        msg_class = getattr(importlib.import_module(f"{package}.{kind}"), cls)
        rows: list[tuple[float, float]] = []

        def on_message(msg: Any) -> None:
            rows.append((time.monotonic(), msg.header.stamp.sec + msg.header.stamp.nanosec * 1e-9))

        self.node.create_subscription(msg_class, topic, on_message, qos or QoSProfile(depth=100))
        return rows

    def wait_matched(self, entity: Collected | Publisher, timeout_s: float = 15.0) -> None:
        """Wait until a subscription (a `collect` result) or a publisher has a matched peer."""
        if isinstance(entity, Collected):
            sub = entity.subscription
            ok = self.spin_until(lambda: sub.get_publisher_count() > 0, timeout_s)
            name = sub.topic_name
        else:
            pub = entity
            ok = self.spin_until(lambda: pub.get_subscription_count() > 0, timeout_s)
            name = pub.topic_name
        if not ok:
            raise TimeoutError(f"nothing matched on {name} within {timeout_s} s")

    def wait_for_messages(self, received: list[Any], count: int = 1, timeout_s: float = 15.0) -> None:
        if not self.spin_until(lambda: len(received) >= count, timeout_s):
            raise TimeoutError(f"got {len(received)} of {count} messages within {timeout_s} s")


def harness() -> Iterator[RosHarness]:
    """Body of the `ros` pytest fixture: a harness on a domain of its own, closed afterwards."""
    h = RosHarness()
    try:
        yield h
    finally:
        h.close()


def tracebacks(stderr: str) -> list[str]:
    """Tracebacks in a process's stderr, leaving out rclpy's "Exception ignored in" destructor
    noise at interpreter exit (an rclpy shutdown artefact, not an error of the node); and rclpy's
    one-line "exception was never retrieved" of a callback that failed (at shutdown, say)."""
    lines = stderr.splitlines()
    found = []
    for i, line in enumerate(lines):
        if line.startswith("Traceback") and not (i > 0 and lines[i - 1].startswith("Exception ignored in")):
            found.append("\n".join(lines[i : i + 12]))
        elif line.startswith("The following exception was never retrieved"):
            found.append(line)
    return found
