"""haven_viz is installed, importable, and depends on nothing of ours but haven_sim (DESIGN.md)."""

import json
import tomllib
import xml.etree.ElementTree as ET
from pathlib import Path

import haven_viz

ROOT = Path(__file__).resolve().parents[1]


def test_installed_version_matches_package_xml():
    xml = ET.parse(ROOT / "package.xml").getroot()
    assert haven_viz.__version__ == xml.findtext("version")


def test_depends_only_on_haven_sim_among_our_packages():
    xml = ET.parse(ROOT / "package.xml").getroot()
    ours = {e.text for e in xml.iter("exec_depend") if e.text and e.text.startswith("haven_")}
    assert ours == {"haven_sim"}
    requires = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["dependencies"]
    assert "haven_sim" in requires and "haven_scenarios" not in requires


def test_shipped_foxglove_layout_is_what_the_generator_makes():
    import importlib.util

    script = ROOT.parent / "scripts" / "foxglove_layout.py"
    spec = importlib.util.spec_from_file_location("foxglove_layout", script)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    shipped = (ROOT / "haven_viz" / "foxglove" / "haven_layout.json").read_text()
    assert module.build().to_json() + "\n" == shipped
    layout = json.loads(shipped)
    topics = layout["content"]["items"][0]["content"]["config"]["topics"]
    assert {"/map", "/haven/ar_markers", "/haven/world_markers", "/plan", "/scan"} <= set(topics)


def test_rviz_config_shows_the_suite_in_frame_map():
    import yaml

    cfg = yaml.safe_load((ROOT / "haven_viz" / "rviz" / "haven.rviz").read_text())
    manager = cfg["Visualization Manager"]
    assert manager["Global Options"]["Fixed Frame"] == "map"
    topics = {d["Topic"]["Value"] for d in manager["Displays"] if "Topic" in d}
    assert {"/map", "/haven/ar_markers", "/haven/world_markers", "/plan", "/scan", "/odom"} <= topics
