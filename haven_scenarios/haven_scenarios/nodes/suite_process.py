"""The suite's nodes in one process: the simulator, mux, planner, controller, viz and the
scenario node of a trial (or of `haven sim`) as one rclpy process with one executor on one thread.

    python -m haven_scenarios.nodes.suite_process --node 'sim={}' --node 'mux={"use_sim_time": true}' ...
        --ros-args --params-file params.yaml

Why: what each node process costs (an interpreter, rclpy and a DDS participant, and every message
between the nodes serialised from one process to another) is paid once. Each node keeps its name,
its topics and its parameters: the process's ROS arguments (the parameter file, whose node sections
are each node's own) and its own (`--node KEY=JSON`: the `-p` values the node would have had on
its command line). The lockstep rule holds as across processes: a node's messages are announced by
digest and taken from their readers, never by waiting for another node's callback. The process ends
when the scenario node ends the trial (its exit code is the process's), or on a stop signal, when
every node is destroyed, the scenario node first (its trial_end goes out while the others still run).
`--processes separate` runs one process per node instead (for debugging a node on its own).
"""

from __future__ import annotations

import argparse
import importlib
import json
import sys
from collections.abc import Sequence
from typing import Any

from rclpy.node import Node

from haven_scenarios.run.supervisor import param_args
from haven_sim.common import nodes
from haven_sim.nodes.runner import run_node

HOLDS = tuple(n for n in (*nodes.COMPONENTS, nodes.SCENARIO) if n.node_class)  # the nodes this process can hold


def node_option(text: str) -> tuple[str, dict[str, Any]]:
    """`--node KEY=JSON`: a node's key and its own parameters."""
    key, _, given = text.partition("=")
    if key not in {n.key for n in HOLDS}:
        raise argparse.ArgumentTypeError(f"{key!r} is not one of {', '.join(n.key for n in HOLDS)}")
    try:
        params = json.loads(given or "{}")
    except json.JSONDecodeError:
        raise argparse.ArgumentTypeError(f"{key}: its parameters must be a JSON object") from None
    if not isinstance(params, dict):
        raise argparse.ArgumentTypeError(f"{key}: its parameters must be a JSON object")
    return key, params


def make_nodes(members: Sequence[tuple[str, dict[str, Any]]]) -> list[Node]:
    """The nodes, in the order given, each with its own `-p` arguments; the scenario node first in
    the returned list, so it is destroyed first."""
    made: list[Node] = []
    for key, params in members:
        node = nodes.BY_KEY[key]
        cls = getattr(importlib.import_module(node.module), node.node_class)
        made.append(cls(["--ros-args", *param_args(params)]))
    return sorted(made, key=lambda n: n.get_name() != nodes.SCENARIO.name)


def main(args: list[str] | None = None) -> None:
    argv = list(sys.argv[1:] if args is None else args)
    ours, ros = (
        (argv[: argv.index("--ros-args")], argv[argv.index("--ros-args") :]) if "--ros-args" in argv else (argv, [])
    )
    parser = argparse.ArgumentParser(prog="suite_process", description=__doc__.split("\n\n")[0])
    parser.add_argument("--node", type=node_option, action="append", required=True, help="KEY=JSON (repeat)")
    members = parser.parse_args(ours).node
    sys.exit(run_node(lambda: make_nodes(members), [sys.argv[0], *ros]))


if __name__ == "__main__":
    main()
