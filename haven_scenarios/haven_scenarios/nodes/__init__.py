"""ROS 2 nodes of haven_scenarios: thin translators around the rclpy-free core."""
