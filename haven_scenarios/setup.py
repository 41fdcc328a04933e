import xml.etree.ElementTree as ET
from glob import glob
from pathlib import Path

from setuptools import find_packages, setup

package_name = "haven_scenarios"
VERSION = ET.parse(Path(__file__).with_name("package.xml")).getroot().findtext("version")  # (the one source: package.xml, as ROS tools bump it)

setup(
    name=package_name,
    version=VERSION,
    packages=find_packages(exclude=["test"]),
    package_data={package_name: ["py.typed", "worlds/*.yaml", "scenarios/*.yaml", "studies/*.yaml", "web/static/*"]},
    data_files=[
        ("share/ament_index/resource_index/packages", [f"resource/{package_name}"]),
        (f"share/{package_name}", ["package.xml"]),
        (f"share/{package_name}/worlds", glob("haven_scenarios/worlds/*.yaml")),
        (f"share/{package_name}/scenarios", glob("haven_scenarios/scenarios/*.yaml")),
        (f"share/{package_name}/studies", glob("haven_scenarios/studies/*.yaml")),
    ],
    install_requires=[
        "setuptools",
        "haven_sim",
        "haven_viz",
        "PyYAML",
        "numpy",
        "matplotlib",
        "rosbags",
        "mcap",
        "foxglove-sdk",
        "tqdm",
        "pydantic>=2",
        "scipy",
        "statsmodels",
        "pillow",  # haven edit: a map image as a PNG for the page
        "cryptography",  # `haven cert`: the lab's certificate authority for HTTPS (web/tls.py)
        "filelock>=4",  # OS file locks (run/locks.py): one runner per participant, one suite per ROS domain
    ],
    # `haven batch --cluster`: sweeps on a Dask cluster (a LocalCluster or a lab's scheduler)
    extras_require={"cluster": ["dask", "distributed"]},
    zip_safe=True,
    maintainer="HAVEN maintainers",
    maintainer_email="haven@example.org",
    description="HAVEN study scenarios, sessions and the haven command",
    license="Apache-2.0",
    entry_points={
        "console_scripts": [
            "haven = haven_scenarios.tools.cli:main",
            "demo_driver = haven_scenarios.nodes.demo_driver:main",
            "goal_client = haven_scenarios.nodes.goal_client:main",
            "scenario_node = haven_scenarios.nodes.scenario_node:main",
            "recorder = haven_scenarios.nodes.recorder:main",
            "keyboard_teleop = haven_scenarios.nodes.keyboard_teleop:main",
            "haven_bridge = haven_scenarios.nodes.bridge:main",
            "web_node = haven_scenarios.nodes.web_node:main",
            "player = haven_scenarios.nodes.player:main",
        ],
        # The plugin kinds this package owns: what an item of each must be (haven_sim/common/plugins.py).
        "haven.kinds": [
            "participants = haven_scenarios.study.participant_kind:accept_plugin",
            "questionnaires = haven_scenarios.study.questionnaires:accept_plugin",
            "metrics = haven_scenarios.record.metric_kind:accept_plugin",
            "missions = haven_scenarios.study.mission_orders:accept_plugin",
        ],
        # HAVEN's own plugins, registered as a lab's package registers its own (haven_sim/common/plugins.py)
        "haven.participants": [
            "walker = haven_scenarios.study.participants:Walker",
            "blocker = haven_scenarios.study.participants:Blocker",
            "yielder = haven_scenarios.study.participants:Yielder",
        ],
        "haven.missions": [
            "fixed = haven_scenarios.study.mission_orders:Fixed",
            "nearest = haven_scenarios.study.mission_orders:Nearest",
            "random = haven_scenarios.study.mission_orders:Random",
        ],
        "haven.metrics": [
            f"{name} = haven_scenarios.record.metrics:{name}"
            for name in ("robot", "navigation", "proximity", "contacts", "mission", "cues", "passes", "people")
        ]
        + ["hunav = haven_scenarios.record.hunav:hunav"],
        "haven.questionnaires": [
            "nasa_tlx = haven_scenarios.study.questionnaires:NASA_TLX",
            "godspeed = haven_scenarios.study.questionnaires:GODSPEED",
            "nars = haven_scenarios.study.instruments:NARS",
            "demographics = haven_scenarios.study.instruments:DEMOGRAPHICS",
        ],
    },
)
