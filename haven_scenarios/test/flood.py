"""A node that sends goals on /goal_pose at RATE_HZ for SECONDS of wall time, from the moment the
suite's planner and recorder read /goal_pose: a hostile neighbour, or RViz's "2D Goal Pose" held
down (the isolation tests and bench/flood.py). Prints how many it sent. (Waiting for the recorder
makes what a test sees not depend on how fast the suite starts: a flood over before the recorder
is up leaves only the planner's early plans as a trace.)

usage: python flood.py RATE_HZ SECONDS   (ROS_DOMAIN_ID from the environment)
"""

import sys
import time

import rclpy
from geometry_msgs.msg import PoseStamped
from rclpy.node import Node

rate_hz, seconds = float(sys.argv[1]), float(sys.argv[2])
rclpy.init()
node = Node("goal_flood")
pub = node.create_publisher(PoseStamped, "/goal_pose", 10)
while not {"planner", "recorder"} <= {i.node_name for i in node.get_subscriptions_info_by_topic("/goal_pose")}:
    rclpy.spin_once(node, timeout_sec=0.05)
msg = PoseStamped()
msg.header.frame_id = "map"
msg.pose.orientation.w = 1.0
start, k = time.monotonic(), 0
while time.monotonic() - start < seconds:
    msg.pose.position.x, msg.pose.position.y = 1.0 + (k % 7) * 0.3, 1.0 + (k % 5) * 0.3
    pub.publish(msg)
    k += 1
    time.sleep(max(0.0, start + k / rate_hz - time.monotonic()))
print(f"flood: {k} goals in {time.monotonic() - start:.1f} s", flush=True)
