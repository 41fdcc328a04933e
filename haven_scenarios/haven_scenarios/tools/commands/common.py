"""What several subcommands share: argument types, the ROS options, running supervised nodes."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Mapping, Sequence
from pathlib import Path

from haven_scenarios.tools.supervisor import ProcessSpec, Supervisor, node_argv, ros_environment

SUITE = ("sim", "mux", "planner", "controller", "viz")
NODE_MODULES = {
    "sim": "haven_sim.nodes.sim_node",
    "mux": "haven_sim.nodes.mux_node",
    "planner": "haven_sim.nodes.planner_node",
    "controller": "haven_sim.nodes.controller_node",
    "viz": "haven_viz.nodes.viz_node",
}


def positive(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number, got {text!r}") from None
    if not value > 0:
        raise argparse.ArgumentTypeError(f"must be positive, got {text}")
    return value


def add_ros_options(p: argparse.ArgumentParser) -> None:
    p.add_argument("--domain-id", type=int, default=None, help="ROS_DOMAIN_ID for the nodes (default: inherited)")
    p.add_argument("--network", action="store_true", help="allow DDS discovery beyond localhost")


def add_suite_options(p: argparse.ArgumentParser) -> None:
    p.add_argument("--params-file", default=None, help="ROS parameter YAML for every node (e.g. an edited copy of haven.yaml)")
    p.add_argument(
        "--without",
        nargs="+",
        default=[],
        choices=SUITE[1:],
        metavar="NODE",
        help="leave out our mux, planner, controller or viz (to run your own in their place)",
    )


def fail(message: str) -> int:
    """A usage or input error: one line, exit code 2."""
    print(f"haven: error: {message}", file=sys.stderr)
    return 2


def environment(args: argparse.Namespace) -> dict[str, str]:
    return ros_environment(network=args.network, domain_id=args.domain_id)


def params_file(args: argparse.Namespace) -> str | None:
    return str(Path(args.params_file).resolve()) if getattr(args, "params_file", None) else None


def suite_specs(params: Mapping[str, Mapping[str, object]], pfile: str | None, without: Sequence[str] = ()) -> list[ProcessSpec]:
    """Our nodes (less `without`), each with the parameter file and its own -p overrides; every node
    but the simulator runs on sim time."""
    specs = []
    for name, module in NODE_MODULES.items():
        if name in without:
            continue
        own = dict(params.get(name, {}))
        if name != "sim":
            own = {"use_sim_time": True, **own}
        specs.append(ProcessSpec(name, node_argv(module, own, params_file=pfile)))
    return specs


def run_client(args: argparse.Namespace, name: str, module: str, params: dict[str, object], extra: Sequence[str] = ()) -> int:
    """Run one client node against a running suite until it exits (or Ctrl-C); its exit code is ours."""
    with Supervisor(environment(args)) as sup:
        sup.install_signal_handlers()
        sup.start(ProcessSpec(name, node_argv(module, params, extra)))
        exited = sup.wait()
        sup.stop()
    return 1 if exited is None else exited.code
