"""ROS 2 node of haven_viz: publishes the AR cues and the world as MarkerArrays."""
