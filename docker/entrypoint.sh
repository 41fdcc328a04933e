#!/bin/bash
# Source ROS 2 and the HAVEN workspace, then run the given command.
set -e
source /opt/ros/jazzy/setup.bash
source /haven/ros2_ws/install/setup.bash
exec "$@"
