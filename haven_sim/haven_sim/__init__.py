"""HAVEN simulator core (rclpy-free) and its ROS 2 nodes (in `haven_sim.nodes`)."""

__version__ = "0.1.0"
