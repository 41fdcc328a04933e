"""HAVEN simulator core (rclpy-free) and its ROS 2 nodes (in `haven_sim.nodes`)."""

from importlib.metadata import version as _version

__version__ = _version("haven_sim")  # (from package.xml, through setup.py; the rest of the metadata in pyproject.toml)
