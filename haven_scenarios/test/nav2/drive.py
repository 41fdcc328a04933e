"""A Nav2 user's script, as the nav2_simple_commander examples write them: wait for Nav2, get a
path, follow it, go to a pose, follow waypoints, go through poses, cancel a goal, and goals off the map. Uses
nav2_simple_commander's BasicNavigator where it is installed (or with --ours, commander.py's
stand-in); prints one JSON line per step for test_ros_nav2.py.

usage: python drive.py [--ours]
"""

from __future__ import annotations

import json
import math
import sys
import time
from pathlib import Path
from typing import Any

import rclpy
from geometry_msgs.msg import PoseStamped

GOAL = (2.2, 4.2, 2.6)  # small_test: from the start (1.0, 2.5) a left turn, a straight, a turn to the yaw
WAYPOINTS = [(3.0, 1.5, 0.0), (1.5, 1.5, math.pi)]
THROUGH = [(1.0, 3.8, 3.5), (1.0, 2.0, -1.57)]  # from GOAL: passed on the way (a curve), then the end
FAR = (7.0, 2.5, 0.0)  # through the door into the east room: cancelled on the way
OFF_MAP = (50.0, 50.0, 0.0)


def pose(nav: Any, x: float, y: float, yaw: float) -> PoseStamped:
    p = PoseStamped()
    p.header.frame_id = "map"
    p.header.stamp = nav.get_clock().now().to_msg()
    p.pose.position.x, p.pose.position.y = float(x), float(y)
    p.pose.orientation.z, p.pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    return p


def say(step: str, **data: object) -> None:
    print(json.dumps({"step": step, **data}), flush=True)


def finish(nav: Any, step: str, cancel_below_m: float | None = None) -> None:
    """Wait for the task as the examples do, keeping what its feedback said."""
    distances: list[float] = []
    while not nav.isTaskComplete():
        fb = nav.getFeedback()
        if fb is not None and hasattr(fb, "distance_remaining"):
            distances.append(round(float(fb.distance_remaining), 3))
            if cancel_below_m is not None and 0 < fb.distance_remaining < cancel_below_m:
                nav.cancelTask()
                cancel_below_m = None
        time.sleep(0.05)
    fb = nav.getFeedback()
    extra = {"current_waypoint": int(fb.current_waypoint)} if fb is not None and hasattr(fb, "current_waypoint") else {}
    code = int(nav.result_future.result().result.error_code) if nav.result_future is not None else -1
    say(step, result=nav.getResult().name, error_code=code, distances=distances, **extra)


def navigator() -> Any:
    if "--ours" in sys.argv:
        sys.path.insert(0, str(Path(__file__).parent))
        from commander import Commander

        return Commander()
    from nav2_simple_commander.robot_navigator import BasicNavigator

    return BasicNavigator()


def main() -> None:
    rclpy.init()
    nav = navigator()
    nav.waitUntilNav2Active()
    say("active")
    path = nav.getPath(pose(nav, 0, 0, 0), pose(nav, *GOAL))
    say("getPath", poses=len(path.poses) if path is not None else 0)
    elsewhere = pose(nav, *GOAL)
    elsewhere.header.frame_id = "base_link"
    say("getPathInAnotherFrame", refused=nav.getPath(pose(nav, 0, 0, 0), elsewhere) is None)
    nav.followPath(path)
    finish(nav, "followPath")
    nav.goToPose(pose(nav, *WAYPOINTS[0]))
    finish(nav, "goToPose")
    nav.followWaypoints([pose(nav, *w) for w in [*WAYPOINTS[1:], GOAL]])
    finish(nav, "followWaypoints")
    nav.goThroughPoses([pose(nav, *p) for p in THROUGH])
    finish(nav, "goThroughPoses")
    nav.goToPose(pose(nav, *FAR))
    finish(nav, "cancelTask", cancel_below_m=4.0)
    nav.goToPose(pose(nav, *OFF_MAP))
    finish(nav, "offMap")
    nav.goThroughPoses([pose(nav, *GOAL), pose(nav, *OFF_MAP)])
    finish(nav, "throughPosesOffMap")
    nav.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
