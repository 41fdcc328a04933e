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
the user's own nodes in that shell still reach it, and otherwise the first of 1..101 (the domains
whose ports stay clear of Linux's ephemeral range) where no node runs at all, saying which.
A lab that shares a machine or a network chooses the domains its suites may use: `--domains A-B`
(else HAVEN_DOMAINS=A-B in the environment). Then a suite never runs outside A..B: the inherited
domain only if it lies inside, else the first of A..B where no node runs, saying which; a
`--domain-id` outside the range is refused; all of them taken is one line. The
graph look is the second line of defence (a busy machine can hide a node from it for longer than
it looks): a suite that shares a domain all the same is caught by its recorder, which marks the
session not valid (`record/outsiders.py`).
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

from haven_scenarios.run.locks import FileLock, Locked
from haven_sim.common import nodes

FREE_DOMAINS = range(1, 102)
# The highest ROS domain id on Linux (Fast DDS's port arithmetic: 7400 + 250 x domain + ... stays below
# 65535 and clear of the ephemeral ports only up to here); ROS 2's "The ROS_DOMAIN_ID" concept page,
# https://docs.ros.org/en/jazzy/Concepts/Intermediate/About-Domain-ID.html
MAX_DOMAIN_ID = 232
DOMAINS_ENV = "HAVEN_DOMAINS"  # the lab's range of domains, A-B, where no --domains is given
PROBE_S = 2.0  # wall time a probe watches the graph (a running suite shows up after 0.4-0.9 s, later on a busy machine)
# Nodes that make a suite: a domain where one of them runs is taken.
SUITE_NODES = tuple(n.name for n in nodes.TRIAL)


class DomainBusy(Exception):
    """The domain asked for holds another suite (or names none); the message is one line for the user."""


@dataclass(frozen=True)
class DomainRange:
    """The ROS domains a suite may take, first..last inclusive; `given`: where the range came from
    (`--domains` or the environment variable), for the user's messages."""

    first: int
    last: int
    given: str = "--domains"

    def __contains__(self, domain_id: object) -> bool:
        return isinstance(domain_id, int) and self.first <= domain_id <= self.last

    def __str__(self) -> str:
        return f"{self.given} {self.first}-{self.last}"

    @property
    def ids(self) -> range:
        return range(self.first, self.last + 1)

    @property
    def text(self) -> str:
        """As the option takes it (`haven serve` hands it on to each participant's runner)."""
        return f"{self.first}-{self.last}"


def parse_domains(text: str, given: str = "--domains") -> DomainRange:
    """`A-B` (or one domain `A`) as a DomainRange; ValueError in one line for anything else."""
    parts = text.strip().split("-")
    if len(text) > 20 or not 1 <= len(parts) <= 2 or not all(p.strip().isdigit() for p in parts):
        raise ValueError(f"{given}: expected A-B, ROS domain ids 0..{MAX_DOMAIN_ID} (e.g. 30-39), got {text[:20]!r}")
    first, last = int(parts[0]), int(parts[-1])
    if last > MAX_DOMAIN_ID or first > last:
        why = (
            f"{last} is not a ROS domain id (0..{MAX_DOMAIN_ID})"
            if last > MAX_DOMAIN_ID
            else f"{first} is above {last}"
        )
        raise ValueError(f"{given}: {text.strip()}: {why}")
    return DomainRange(first, last, given)


def domains_of(env: Mapping[str, str]) -> DomainRange | None:
    """The lab's range from the environment (HAVEN_DOMAINS), None where unset; DomainBusy (one line) for a bad one."""
    text = env.get(DOMAINS_ENV, "").strip()
    if not text:
        return None
    try:
        return parse_domains(text, DOMAINS_ENV)
    except ValueError as e:
        raise DomainBusy(f"{e} (in the environment)") from None


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
    """ROS_DOMAIN_ID from the environment (unset or empty: 0); DomainBusy for a value that is no
    domain id (ROS would refuse it, or use another domain than the user meant)."""
    text = env.get("ROS_DOMAIN_ID", "").strip()
    if not text:
        return 0
    if not text.isdigit() or int(text) > MAX_DOMAIN_ID:
        raise DomainBusy(
            f"ROS_DOMAIN_ID={text[:20]!r} in the environment is not a ROS "
            f"domain id (0..{MAX_DOMAIN_ID}): unset it or pass --domain-id"
        )
    return int(text)


def nodes_on(domain_id: int, env: Mapping[str, str], wanted: Sequence[str]) -> list[str]:
    """The nodes the graph of `domain_id` shows (looked at until one of `wanted` shows, or PROBE_S)."""
    probe_env = {**env, "ROS_DOMAIN_ID": str(domain_id)}
    argv = [sys.executable, "-m", "haven_scenarios.nodes.domain_probe", str(PROBE_S), *wanted]
    try:
        r = subprocess.run(argv, env=probe_env, capture_output=True, text=True, timeout=PROBE_S + 30)
    except (OSError, subprocess.TimeoutExpired):
        return []  # (the lock still holds; a probe that cannot run is no reason not to start)
    return r.stdout.split()


def _take(
    domain_id: int, env: Mapping[str, str], ignore: Sequence[str], empty: bool = False
) -> tuple[FileLock | None, str]:
    """The domain's lock if the domain is free (of a HAVEN suite; with `empty`, of any node), else
    (None, what is there); `ignore`: names of nodes the user runs in place of ours."""
    lock = FileLock(lock_path(domain_id))
    try:
        lock.acquire()
    except Locked as e:
        return None, f"another HAVEN suite runs on it ({e.holder.describe()})"
    except OSError as e:
        return None, f"cannot lock {lock_path(domain_id)}: {e.strerror or e}"
    wanted = [n for n in SUITE_NODES if n not in ignore]
    seen = nodes_on(domain_id, env, wanted)
    suite = [n for n in seen if n in wanted]
    if suite or (empty and seen):
        lock.release()
        if suite:
            return (
                None,
                f"HAVEN suite nodes already run on it ({', '.join(suite)}; "
                "started without `haven`, or on another machine)",
            )
        return None, f"other ROS nodes run on it ({', '.join(seen[:3])}{'...' if len(seen) > 3 else ''})"
    return lock, ""


def take_domain(domain_id: int, env: Mapping[str, str], ignore: Sequence[str] = ()) -> Claim:
    """This domain, held until the claim is released; DomainBusy ("ROS domain N: why") if taken."""
    lock, why = _take(domain_id, env, ignore)
    if lock is None:
        raise DomainBusy(f"ROS domain {domain_id}: {why}")
    return Claim(domain_id, lock)


def claim_domain(
    explicit: int | None, env: Mapping[str, str], ignore: Sequence[str] = (), domains: DomainRange | None = None
) -> Claim:
    """The domain this suite runs on: `explicit` or refuse (DomainBusy), else the inherited one
    if free, else the first free one; `ignore`: node names the user's own nodes may have.
    `domains`: the lab's range (None: HAVEN_DOMAINS from `env`, if set), never left."""
    domains = domains if domains is not None else domains_of(env)
    if explicit is not None:
        if domains is not None and explicit not in domains:
            raise DomainBusy(
                f"--domain-id {explicit} is outside {domains}: "
                "choose one inside it, or leave --domain-id out to get a free one"
            )
        try:
            return take_domain(explicit, env, ignore)
        except DomainBusy as e:
            raise DomainBusy(f"{e}; choose another --domain-id, or leave it out to get a free one") from None
    home = inherited_domain(env)
    if domains is None or home in domains:
        lock, why = _take(home, env, ignore)
        if lock is not None:
            return Claim(home, lock)
    else:
        why = f"outside {domains}"
    # (a domain of its own: one where no other node runs either)
    for candidate in domains.ids if domains is not None else FREE_DOMAINS:
        if candidate == home:
            continue
        other, _ = _take(candidate, env, ignore, empty=True)
        if other is not None:
            return Claim(candidate, other, (home, why))
    if domains is not None:
        raise DomainBusy(
            f"no free ROS domain in {domains}: each runs another HAVEN "
            "suite or other ROS nodes (widen the range, or stop one)"
        )
    raise DomainBusy(f"no free ROS domain: {home} and 1..{FREE_DOMAINS[-1]} all hold HAVEN suites")
