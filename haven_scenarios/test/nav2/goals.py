"""Ten navigate_to_pose goals one after the other, as a Nav2 user's script sends them with
BasicNavigator (or with --ours, commander.py's stand-in); prints one JSON line per goal for
test_ros_nav2.py, which holds each "SUCCEEDED" against the recorded /odom.

usage: python goals.py [--ours]
"""

from __future__ import annotations

import math

import rclpy
from drive import finish, navigator, pose, say

# small_test, from the start (1.0, 2.5): turns left and right, straights, arcs, a reversal.
GOALS = [
    (2.2, 4.2, 2.6),
    (3.0, 1.5, 0.0),
    (1.5, 1.5, math.pi),
    (2.5, 3.0, 1.57),
    (1.2, 4.0, -1.57),
    (3.2, 2.2, -0.8),
    (1.0, 2.5, 0.0),
    (2.8, 4.3, 0.4),
    (2.0, 1.4, -2.5),
    (1.4, 3.2, 2.0),
]


def main() -> None:
    rclpy.init()
    nav = navigator()
    nav.waitUntilNav2Active()
    say("active")
    for i, goal in enumerate(GOALS):
        nav.goToPose(pose(nav, *goal))
        finish(nav, f"goal{i}")
    nav.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
