"""The processes of a trial's suite and the ROS domain it runs on."""

from __future__ import annotations

import importlib.util
import json
import socket
import sys
from collections.abc import Callable, Mapping, Sequence

from haven_scenarios.run.domains import Claim, DomainRange, claim_domain
from haven_scenarios.run.supervisor import ProcessSpec, node_argv, ros_environment
from haven_sim.common import nodes
from haven_sim.common.params import load_params_file


def port_free(host: str, port: int) -> str | None:
    """None if the port can be bound on `host` (0: any free one), else why not: checked before
    anything starts, so a busy port is one line, not a server's traceback."""
    try:
        with socket.socket() as s:
            s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
            s.bind((host, port))
    except (OSError, OverflowError) as e:
        return f"--host {host} --port {port}: {getattr(e, 'strerror', None) or e}"
    return None


def claim_ros_domain(
    domain_id: int | None,
    network: bool,
    ignore: Sequence[str] = (),
    say: Callable[[str], None] = print,
    domains: DomainRange | None = None,
) -> Claim:
    """The ROS domain a suite runs on (`run/domains.py`); DomainBusy (one line) when `domain_id`
    names a domain another suite holds or one outside `domains` (None: $HAVEN_DOMAINS, if set), or
    when no domain is free. Said when the inherited domain was taken (or lies outside the range)
    and the suite moved. `ignore`: our nodes left out (`--without`), whose names the user's own nodes may have."""
    got = claim_domain(domain_id, ros_environment(network=network), [nodes.BY_KEY[n].name for n in ignore], domains)
    if got.moved_from is not None:
        home, why = got.moved_from
        here = got.domain_id
        say(f"haven: ROS domain {home}: {why}; this suite runs on ROS domain {here} (ROS_DOMAIN_ID={here} to join it)")
    return got


def suite_specs(
    params: Mapping[str, Mapping[str, object]],
    pfile: str | None,
    without: Sequence[str] = (),
    processes: str = "one",
    members: Sequence[nodes.SuiteNode] = nodes.COMPONENTS,
) -> list[ProcessSpec]:
    """Our nodes (`members` less `without`), each with the parameter file and its own -p overrides;
    every node but the simulator runs on sim time unless its overrides say otherwise. `processes`:
    "one" holds them in one process (nodes.SUITE_PROCESS), "separate" runs a process each."""
    own = {
        n.key: ({} if n is nodes.SIM else {"use_sim_time": True}) | dict(params.get(n.key, {}))
        for n in members
        if n.key not in without
    }
    if processes not in nodes.PROCESS_LAYOUTS:
        raise ValueError(f"--processes: {processes!r} is not one of {', '.join(nodes.PROCESS_LAYOUTS)}")
    if processes == "separate":
        return [ProcessSpec(k, node_argv(nodes.BY_KEY[k].module, p, params_file=pfile)) for k, p in own.items()]
    argv = [sys.executable, "-m", nodes.SUITE_PROCESS.module]
    for key, p in own.items():
        argv += ["--node", f"{key}={json.dumps(p)}"]
    return [ProcessSpec(nodes.SUITE_PROCESS.key, argv + ["--ros-args"] + (["--params-file", pfile] if pfile else []))]


def nav2_specs(params: Mapping[str, Mapping[str, object]], pfile: str | None) -> list[ProcessSpec]:
    """Nav2's action servers (nodes.NAV2) with the planner's parameters, from the parameter file's
    planner section and the command's (its planner_server plans as our planner does), or nothing,
    said in one line, where nav2_msgs is not installed."""
    if importlib.util.find_spec("nav2_msgs") is None:
        print("haven: nav2_msgs is not installed: no Nav2 action servers (`make setup` builds it)", flush=True)
        return []
    from_file = load_params_file(pfile).get(nodes.PLANNER.name, {}) if pfile else {}
    own = {"use_sim_time": True, **from_file, **params.get(nodes.PLANNER.key, {})}
    return [ProcessSpec(nodes.NAV2.key, node_argv(nodes.NAV2.module, own, params_file=pfile))]
