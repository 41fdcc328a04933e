"""One trial, one world: the ROS domain a suite (`haven run`, `haven sim`, `haven demo`) runs on is
its own, so two suites never hear each other unknowingly.

Two checks, before any node starts:
- a lock per domain on this machine (`FileLock` on /tmp/haven-ros-domain-<N>.lock, held while
  the suite runs, released by the kernel however it ends): two suites started at the same moment
  cannot both take a domain;
- a look at the domain's graph (`nodes/domain_probe.py`) for a HAVEN suite's nodes that hold no
  lock here: one started by hand (`ros2 run haven_sim sim_node`) or, with --network, on another
  machine.

With `--domain-id N` the suite runs on N or refuses to start, in one line naming what is there.
Without it, the suite takes the inherited domain (ROS_DOMAIN_ID, else 0) when that is free, so
the user's own nodes in that shell still reach it, and otherwise the first free one of 1..101
(the domains whose ports stay clear of Linux's ephemeral range), saying which.
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

from haven_scenarios.tools.locks import FileLock, Locked

FREE_DOMAINS = range(1, 102)
PROBE_S = 1.5  # wall time a probe watches the graph (a running suite shows up after 0.4-0.9 s)
# Nodes that make a suite: a domain where one of them runs is taken.
SUITE_NODES = ("sim_node", "planner", "recorder", "velocity_mux", "controller", "viz", "scenario")


class DomainBusy(Exception):
    """The domain asked for holds another suite; the message is one line for the user."""


@dataclass
class Claim:
    """A domain this suite holds until `release` (or until the process ends)."""

    domain_id: int
    lock: FileLock
    moved_from: tuple[int, str] | None = None  # the inherited domain and why it was not taken

    def release(self) -> None:
        self.lock.release()


def lock_path(domain_id: int) -> Path:
    return Path(os.environ.get("HAVEN_LOCK_DIR") or tempfile.gettempdir()) / f"haven-ros-domain-{domain_id}.lock"


def inherited_domain(env: Mapping[str, str]) -> int:
    """ROS_DOMAIN_ID as ROS reads it (unset, empty or not a number: 0)."""
    text = env.get("ROS_DOMAIN_ID", "").strip()
    return int(text) if text.isdigit() and int(text) <= 232 else 0


def suite_nodes_on(domain_id: int, env: Mapping[str, str], ignore: Sequence[str] = ()) -> list[str]:
    """A HAVEN suite's nodes that the graph of `domain_id` shows (but those in `ignore`: nodes the
    user runs in place of ours)."""
    wanted = [n for n in SUITE_NODES if n not in ignore]
    probe_env = {**env, "ROS_DOMAIN_ID": str(domain_id)}
    argv = [sys.executable, "-m", "haven_scenarios.nodes.domain_probe", str(PROBE_S), *wanted]
    try:
        r = subprocess.run(argv, env=probe_env, capture_output=True, text=True, timeout=PROBE_S + 30)
    except (OSError, subprocess.TimeoutExpired):
        return []  # (the lock still holds; a probe that cannot run is no reason not to start)
    return [line for line in r.stdout.split() if line in wanted]


def _take(domain_id: int, env: Mapping[str, str], ignore: Sequence[str]) -> tuple[FileLock | None, str]:
    """The domain's lock if the domain is free, else (None, what is there)."""
    lock = FileLock(lock_path(domain_id))
    try:
        lock.acquire()
    except Locked as e:
        return None, f"another HAVEN suite runs on it ({e.holder.describe()})"
    except OSError as e:
        return None, f"cannot lock {lock_path(domain_id)}: {e.strerror or e}"
    found = suite_nodes_on(domain_id, env, ignore)
    if found:
        lock.release()
        return None, f"HAVEN suite nodes already run on it ({', '.join(found)}; started without `haven`, or on another machine)"
    return lock, ""


def claim_domain(explicit: int | None, env: Mapping[str, str], ignore: Sequence[str] = ()) -> Claim:
    """The domain this suite runs on: `explicit` or refuse (DomainBusy), else the inherited one
    if free, else the first free one; `ignore`: node names the user's own nodes may have."""
    if explicit is not None:
        lock, why = _take(explicit, env, ignore)
        if lock is None:
            raise DomainBusy(f"ROS domain {explicit}: {why}; choose another --domain-id, or leave it out to get a free one")
        return Claim(explicit, lock)
    home = inherited_domain(env)
    lock, why = _take(home, env, ignore)
    if lock is not None:
        return Claim(home, lock)
    for candidate in FREE_DOMAINS:
        if candidate == home:
            continue
        other, _ = _take(candidate, env, ignore)
        if other is not None:
            return Claim(candidate, other, (home, why))
    raise DomainBusy(f"no free ROS domain: {home} and 1..{FREE_DOMAINS[-1]} all hold HAVEN suites")
