"""HAVEN's AR cues as marker data (rclpy-free), the top-down renderer, and the visualization node
(in `haven_viz.nodes`), with RViz and Foxglove configurations as package data."""

from importlib.metadata import version as _version

__version__ = _version("haven_viz")  # (from package.xml, through setup.py; the rest of the metadata in pyproject.toml)
