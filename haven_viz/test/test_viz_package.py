"""haven_viz is installed, importable, and depends on nothing of ours but haven_sim (DESIGN.md)."""

import re
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
    requires = re.search(r"install_requires=\[([^\]]*)\]", (ROOT / "setup.py").read_text()).group(1)
    assert "haven_scenarios" not in requires
