"""`haven topics`, `haven echo` and `haven hz` for pip users, who have no `ros2` command: the rclpy
graph API and a generic subscription do what `ros2 topic list -t -v`, `echo` and `hz` would."""

from __future__ import annotations

import argparse
import sys
import time
from collections.abc import Sequence
from typing import Any

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node

from haven_scenarios.nodes.raw_topics import matching_qos, message_class
from haven_scenarios.record.rates import rate_stats


def to_plain(msg: Any) -> Any:
    """A message as nested dicts and lists (what `ros2 topic echo` prints as YAML)."""
    if hasattr(msg, "get_fields_and_field_types"):
        return {name: to_plain(getattr(msg, name)) for name in msg.get_fields_and_field_types()}
    if isinstance(msg, (list, tuple)) or type(msg).__name__ in ("ndarray", "array"):
        return [to_plain(v) for v in msg]
    return msg


def _yaml(value: Any, indent: int = 0) -> str:
    pad = "  " * indent
    if isinstance(value, dict):
        lines = []
        for k, v in value.items():
            if isinstance(v, (dict, list)) and v:
                lines.append(f"{pad}{k}:\n{_yaml(v, indent + 1)}")
            else:
                lines.append(f"{pad}{k}: {v!r}" if isinstance(v, str) else f"{pad}{k}: {v}")
        return "\n".join(lines)
    if isinstance(value, list):
        if len(value) > 16 and not any(isinstance(v, (dict, list)) for v in value):
            return f"{pad}- '<sequence of {len(value)} values, first {value[:4]}>'"
        return "\n".join(
            f"{pad}-\n{_yaml(v, indent + 1)}" if isinstance(v, (dict, list)) else f"{pad}- {v}" for v in value
        )
    return f"{pad}{value}"


def _wait_for_graph(node: Node, seconds: float) -> None:
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        rclpy.spin_once(node, timeout_sec=0.05)


def _type_of(node: Node, topic: str, wait_s: float) -> str | None:
    deadline = time.monotonic() + wait_s
    while time.monotonic() < deadline:
        for name, types in node.get_topic_names_and_types():
            if name == topic:
                return types[0]
        rclpy.spin_once(node, timeout_sec=0.05)
    return None


def main(argv: Sequence[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="haven graph")
    ap.add_argument("command", choices=["topics", "echo", "hz"])
    ap.add_argument("topic", nargs="?")
    ap.add_argument("--count", type=int, default=0, help="echo: stop after this many messages (0 = until Ctrl-C)")
    ap.add_argument("--window", type=int, default=100, help="hz: messages per statistics window")
    ap.add_argument("--wait", type=float, default=2.0, help="seconds to let discovery find the graph")
    args = ap.parse_args(argv)
    if args.command != "topics" and not args.topic:
        print(f"haven {args.command}: a topic is required", file=sys.stderr)
        return 2
    rclpy.init()
    node = rclpy.create_node("haven_graph_tools")
    try:
        if args.command == "topics":
            _wait_for_graph(node, args.wait)
            for name, types in sorted(node.get_topic_names_and_types()):
                print(
                    f"{name} [{', '.join(types)}] publishers: {node.count_publishers(name)}, "
                    f"subscribers: {node.count_subscribers(name)}"
                )
            return 0
        topic = args.topic if args.topic.startswith("/") else "/" + args.topic
        type_name = _type_of(node, topic, max(args.wait, 5.0))
        if type_name is None:
            print(f"haven {args.command}: no topic {topic} in the graph", file=sys.stderr)
            return 1
        arrivals: list[float] = []
        seen = [0]

        def on_message(msg: Any) -> None:
            seen[0] += 1
            if args.command == "echo":
                print(_yaml(to_plain(msg)) + "\n---", flush=True)
            else:
                arrivals.append(time.monotonic())
                if len(arrivals) > args.window:
                    del arrivals[0]

        node.create_subscription(message_class(type_name), topic, on_message, matching_qos(node, topic, depth=10))
        last_report = time.monotonic()
        while rclpy.ok() and not (args.count and seen[0] >= args.count):
            rclpy.spin_once(node, timeout_sec=0.1)
            if args.command == "hz" and time.monotonic() - last_report >= 1.0:
                last_report = time.monotonic()
                stats = rate_stats(arrivals)
                print(stats.line() if stats else "no new messages", flush=True)
        return 0
    except (KeyboardInterrupt, ExternalShutdownException):
        return 0
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == "__main__":
    sys.exit(main())
