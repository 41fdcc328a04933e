"""Commands that talk to a running suite: goto, snapshot, teleop, topics / echo / hz, bridge; and
play, which puts a recorded session back on the graph."""

from __future__ import annotations

import argparse
import subprocess
import sys
from pathlib import Path

from haven_scenarios.conduct.suite_processes import port_free
from haven_scenarios.run.domains import DomainBusy, inherited_domain, take_domain
from haven_scenarios.run.supervisor import node_argv
from haven_scenarios.tools.commands.common import (
    PORT,
    add_ros_options,
    bounded_int,
    environment,
    fail,
    finite,
    positive,
    run_client,
)
from haven_sim.runtime.process import die_with_parent
from haven_sim.sim.world import WorldError, resolve_world_path
from haven_sim.sim.world_file import load_world


def add(sub: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    goto = sub.add_parser("goto", help="send a goal to a running suite (like RViz's 2D Goal Pose) and wait for it")
    goto.add_argument("x", type=finite)
    goto.add_argument("y", type=finite)
    goto.add_argument("yaw", type=finite, nargs="?", default=0.0, help="radians (default 0)")
    goto.add_argument("--timeout", type=positive, default=120.0, help="sim seconds to wait for arrival")
    goto.set_defaults(func=goto_cmd)
    snap = sub.add_parser("snapshot", help="save what a running suite's viewers show as a top-down PNG")
    snap.add_argument("output", nargs="?", default="haven_snapshot.png")
    snap.add_argument("--world", default="small_test", help="the world the suite runs (for the walls)")
    snap.add_argument(
        "--timeout",
        type=positive,
        default=10.0,
        help="give up when no suite shows anything within this many seconds (default 10)",
    )
    snap.set_defaults(func=snapshot_cmd)
    teleop = sub.add_parser("teleop", help="drive a human avatar of a running trial from this terminal")
    teleop.add_argument("human", nargs="?", default="h1")
    teleop.add_argument("--speed", type=positive, default=1.0, help="walking speed, m/s (default 1)")
    teleop.set_defaults(func=teleop_cmd)
    for name, text in (
        ("topics", "list the graph's topics with types and publisher/subscriber counts"),
        ("echo", "print the messages on a topic"),
        ("hz", "measure a topic's message rate"),
    ):
        g = sub.add_parser(name, help=text + " (for installs without the ros2 command)")
        if name != "topics":
            g.add_argument("topic")
        g.add_argument(
            "--count",
            type=bounded_int(0),
            default=0,
            help=argparse.SUPPRESS if name != "echo" else "stop after N messages",
        )
        g.set_defaults(func=graph_cmd)
    bridge = sub.add_parser("bridge", help="relay the running suite's topics to a Foxglove WebSocket server")
    bridge.add_argument("--host", default="127.0.0.1", help="address to bind (default 127.0.0.1: this machine only)")
    bridge.add_argument("--port", type=PORT, default=8765)
    bridge.add_argument("--topics", nargs="+", default=None, help="only these topics (default: every topic)")
    bridge.set_defaults(func=bridge_cmd)
    play = sub.add_parser(
        "play",
        help="play a recorded session back onto the graph, latched topics latched (for installs without ros2 bag)",
    )
    play.add_argument("session", type=Path, help="a session folder (or its bag/)")
    play.add_argument("--rate", type=positive, default=1.0, help="playback speed (default 1)")
    play.add_argument(
        "--hold", action="store_true", help="stay up after the end, so the latched topics remain for late viewers"
    )
    play.set_defaults(func=play_cmd)
    for p in (goto, snap, teleop, bridge, play, *(sub.choices[n] for n in ("topics", "echo", "hz"))):
        add_ros_options(p)


def goto_cmd(args: argparse.Namespace) -> int:
    goal = {"x": args.x, "y": args.y, "yaw": args.yaw, "timeout_s": args.timeout, "use_sim_time": True}
    return run_client(args, "goal_client", "haven_scenarios.nodes.goal_client", goal)


def snapshot_cmd(args: argparse.Namespace) -> int:
    try:
        world = str(resolve_world_path(args.world))
        load_world(world)
    except WorldError as e:
        return fail(str(e))
    return run_client(
        args,
        "snapshot",
        "haven_viz.nodes.snapshot",
        {"world": world, "output": str(Path(args.output).resolve()), "timeout_s": args.timeout},
    )


def _call(argv: list[str], args: argparse.Namespace) -> int:
    """In this terminal's process group, so that it reads the keyboard; Ctrl-C ends it (and it ends
    with `haven` however that ends)."""
    try:
        return subprocess.call(argv, env=environment(args), preexec_fn=die_with_parent())
    except KeyboardInterrupt:
        return 0


def teleop_cmd(args: argparse.Namespace) -> int:
    return _call(
        node_argv("haven_scenarios.nodes.keyboard_teleop", {"human": args.human, "speed_mps": args.speed}), args
    )


def play_cmd(args: argparse.Namespace) -> int:
    bag = args.session / "bag" if (args.session / "bag").is_dir() else args.session
    if not (bag / "metadata.yaml").is_file():
        return fail(
            f"{args.session}: no bag here (a session folder or its bag/ "
            "with metadata.yaml; an unclosed bag: haven repair first)"
        )
    env = environment(args)
    try:  # (a recording played into a running trial would mix into it: the domain is taken as a suite takes it)
        domain = take_domain(args.domain_id if args.domain_id is not None else inherited_domain(env), env)
    except DomainBusy as e:
        return fail(f"{e}; a recording played there would mix into it (play it on another --domain-id)")
    with domain.lock:
        args.domain_id = domain.domain_id
        return run_client(
            args,
            "player",
            "haven_scenarios.nodes.player",
            {"bag": str(bag.resolve()), "rate": args.rate, "hold": args.hold},
        )


def graph_cmd(args: argparse.Namespace) -> int:
    argv = [sys.executable, "-m", "haven_scenarios.nodes.graph_tools", args.command]
    argv += [args.topic] if args.command != "topics" else []
    argv += ["--count", str(args.count)] if args.count else []
    return _call(argv, args)


def bridge_cmd(args: argparse.Namespace) -> int:
    busy = port_free(args.host, args.port)
    if busy:
        return fail(busy)
    extra = ["-p", f"topics:=[{','.join(args.topics)}]"] if args.topics else []
    return run_client(args, "bridge", "haven_scenarios.nodes.bridge", {"host": args.host, "port": args.port}, extra)
