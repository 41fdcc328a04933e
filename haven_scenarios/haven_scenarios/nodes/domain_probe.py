"""Which HAVEN suite nodes are on a ROS domain: `haven run` and `haven sim` ask before they start
theirs (`run/domains.py`), so that two suites never share a graph unknowingly.

Run as `python -m haven_scenarios.nodes.domain_probe SECONDS NAME...` with ROS_DOMAIN_ID set; it
watches the graph for up to SECONDS of wall time (discovery of a running suite takes 0.4-0.9 s
on these machines, more on a busy one), stops as soon as it sees one of the NAMEs, and prints the
names of every node it saw, one per line. Its node has no parameter services and no /rosout, so a suite it finds hears
nothing but a participant that comes and goes.
"""

from __future__ import annotations

import sys
import time

import rclpy
from rclpy.node import Node


def probe(seconds: float, wanted: set[str]) -> set[str]:
    rclpy.init(args=[])
    try:
        node = Node("haven_domain_probe", start_parameter_services=False, enable_rosout=False)
        deadline = time.monotonic() + seconds
        seen: set[str] = set()
        while time.monotonic() < deadline and not seen & wanted:
            rclpy.spin_once(node, timeout_sec=0.05)
            seen = {name for name, _ in node.get_node_names_and_namespaces()} - {node.get_name()}
        node.destroy_node()
        return seen
    finally:
        rclpy.try_shutdown()


def main(argv: list[str] | None = None) -> int:
    args = sys.argv[1:] if argv is None else argv
    for name in sorted(probe(float(args[0]), set(args[1:]))):
        print(name)
    return 0


if __name__ == "__main__":
    sys.exit(main())
