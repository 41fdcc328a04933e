import xml.etree.ElementTree as ET
from glob import glob
from pathlib import Path

from setuptools import find_packages, setup

package_name = "haven_viz"
VERSION = ET.parse(Path(__file__).with_name("package.xml")).getroot().findtext("version")  # (the one source: package.xml, as ROS tools bump it)

setup(
    name=package_name,
    version=VERSION,
    packages=find_packages(exclude=["test"]),
    package_data={package_name: ["py.typed", "rviz/*.rviz", "foxglove/*.json"]},
    data_files=[
        ("share/ament_index/resource_index/packages", [f"resource/{package_name}"]),
        (f"share/{package_name}", ["package.xml"]),
        (f"share/{package_name}/rviz", glob("haven_viz/rviz/*.rviz")),
        (f"share/{package_name}/foxglove", glob("haven_viz/foxglove/*.json")),
    ],
    install_requires=["setuptools", "haven_sim", "numpy", "matplotlib"],
    zip_safe=True,
    maintainer="HAVEN maintainers",
    maintainer_email="haven@example.org",
    description="HAVEN AR cue markers and viewer configs",
    license="Apache-2.0",
    entry_points={
        "console_scripts": [
            "viz_node = haven_viz.nodes.viz_node:main",
            "haven-viz = haven_viz.nodes.viz_node:main",
            "snapshot = haven_viz.nodes.snapshot:main",
        ],
        # The plugin kinds this package owns: what an item of each must be (haven_sim/common/plugins.py).
        "haven.kinds": ["cues = haven_viz.cue_kind:accept_plugin"],
        # HAVEN's cues register as a lab's do (haven_viz/cue_kind.py).
        "haven.cues": [
            "path_projection = haven_viz.builtin_cues:PathProjection",
            "turn_signals = haven_viz.builtin_cues:TurnSignals",
            "thought_bubble = haven_viz.builtin_cues:ThoughtBubble",
            "battery_indicator = haven_viz.builtin_cues:BatteryIndicator",
            "nav_points = haven_viz.drone_cues:NavPoints",
            "arrow = haven_viz.drone_cues:Arrow",
            "gaze = haven_viz.drone_cues:Gaze",
            # the cue library (library_cues.py): off in condition `all`, shown where a condition names them
            "path_line = haven_viz.library_cues:PathLine",
            "projected_arrows = haven_viz.library_cues:ProjectedArrows",
            "light_ring = haven_viz.library_cues:LightRing",
        ],
    },
)
