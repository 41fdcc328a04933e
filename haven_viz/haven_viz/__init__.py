"""HAVEN AR cue geometry (rclpy-free) and the visualization node (in `haven_viz.nodes`).

The cues themselves arrive with the AR-cue issue; this package exists now so the workspace layout,
dependencies and versions are fixed from the start.
"""

__version__ = "0.1.0"
