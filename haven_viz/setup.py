"""What ROS's layout needs beside pyproject.toml (which holds the package's metadata): the version,
from package.xml (the one source, as ROS's release tools bump it), and the files colcon installs
into share/ and the ament index."""

import xml.etree.ElementTree as ET
from glob import glob
from pathlib import Path

from setuptools import setup

package_name = "haven_viz"
VERSION = ET.parse(Path(__file__).with_name("package.xml")).getroot().findtext("version")

setup(
    version=VERSION,
    data_files=[
        ("share/ament_index/resource_index/packages", [f"resource/{package_name}"]),
        (f"share/{package_name}", ["package.xml"]),
        (f"share/{package_name}/rviz", glob("haven_viz/rviz/*.rviz")),
        (f"share/{package_name}/foxglove", glob("haven_viz/foxglove/*.json")),
    ],
)
