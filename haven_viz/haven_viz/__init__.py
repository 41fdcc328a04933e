"""HAVEN's AR cues as marker data (rclpy-free), the top-down renderer, and the visualization node
(in `haven_viz.nodes`), with RViz and Foxglove configurations as package data."""

__version__ = "0.1.0"
