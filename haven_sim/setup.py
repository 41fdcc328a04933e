import xml.etree.ElementTree as ET
from glob import glob
from pathlib import Path

from setuptools import find_packages, setup

package_name = "haven_sim"
VERSION = ET.parse(Path(__file__).with_name("package.xml")).getroot().findtext("version")  # (the one source: package.xml, as ROS tools bump it)

setup(
    name=package_name,
    version=VERSION,
    packages=find_packages(exclude=["test"]),
    package_data={package_name: ["worlds/*.yaml", "config/*.yaml", "config/*.xml", "robots/catalogue/*.yaml", "robots/catalogue/*.glb", "py.typed"]},
    data_files=[
        ("share/ament_index/resource_index/packages", [f"resource/{package_name}"]),
        (f"share/{package_name}", ["package.xml"]),
        (f"share/{package_name}/config", glob("haven_sim/config/*")),
        (f"share/{package_name}/worlds", glob("haven_sim/worlds/*.yaml")),
    ],
    install_requires=["setuptools", "numpy", "pymunk", "PyYAML", "pydantic>=2", "pillow"],
    zip_safe=True,
    maintainer="HAVEN maintainers",
    maintainer_email="haven@example.org",
    description="HAVEN simulator: world model, physics, sensors, battery, velocity mux",
    license="Apache-2.0",
    entry_points={
        "console_scripts": [
            # `ros2 run haven_sim <name>` on a ROS install
            "sim_node = haven_sim.nodes.sim_node:main",
            "mux_node = haven_sim.nodes.mux_node:main",
            "planner_node = haven_sim.nodes.planner_node:main",
            "controller_node = haven_sim.nodes.controller_node:main",
            # the same nodes as plain commands for the pip setup
            "haven-sim = haven_sim.nodes.sim_node:main",
            "haven-mux = haven_sim.nodes.mux_node:main",
            "haven-planner = haven_sim.nodes.planner_node:main",
            "haven-controller = haven_sim.nodes.controller_node:main",
        ],
        # The plugin kinds this package owns: what an item of each must be (haven_sim/common/plugins.py).
        "haven.kinds": ["planners = haven_sim.nav.planner_kind:accept_plugin", "robots = haven_sim.robots.robot_kind:accept_plugin"],
        # HAVEN's path planner registers as a lab's does (haven_sim/nav/planner_kind.py).
        "haven.planners": ["visibility = haven_sim.nav.planner:GridPlanner"],
        # HAVEN's robot catalogue registers as a lab's robot does (haven_sim/robots/robot_kind.py): each a robot file.
        "haven.robots": [
            f"{name} = haven_sim.robots.catalogue:{name}"
            for name in ("turtlebot2", "turtlebot3_burger", "turtlebot3_waffle_pi", "turtlebot4", "tiago", "youbot", "quadrotor")
        ],
    },
)
