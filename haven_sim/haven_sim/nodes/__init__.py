"""ROS 2 nodes: thin translators between messages and the rclpy-free core."""
