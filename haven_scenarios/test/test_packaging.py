"""The layout contract: versions agree, ament metadata exists, the core never imports ROS."""

import ast
import importlib
import tomllib
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from test_code_shape import ROS_IMPORTS  # (the core-imports-no-ROS check lives there)

ROOT = Path(__file__).resolve().parents[2]
PACKAGES = ["haven_sim", "haven_viz", "haven_scenarios"]


@pytest.mark.parametrize("pkg", PACKAGES)
def test_package_is_an_ament_python_package_with_one_version(pkg):
    root = ROOT / pkg
    xml = ET.parse(root / "package.xml").getroot()
    assert xml.findtext("name") == pkg
    assert xml.find("export/build_type").text == "ament_python"
    assert (root / "resource" / pkg).is_file()
    assert (root / "test").is_dir()
    assert "version=VERSION" in (root / "setup.py").read_text()  # (read from package.xml)
    project = tomllib.loads((root / "pyproject.toml").read_text())["project"]
    # (the metadata, PEP 621)
    assert project["name"] == pkg and project["dynamic"] == ["version"] and "version" not in project
    # (the three move together)
    assert xml.findtext("version") == ET.parse(ROOT / "haven_sim" / "package.xml").getroot().findtext("version")
    assert importlib.import_module(pkg).__version__ == xml.findtext("version")
    assert (ROOT / "ros2_ws" / "src" / pkg).resolve() == root


def test_rosdep_keys_cover_what_the_nodes_import():
    """Every message package a node imports is declared in that package's package.xml."""
    for pkg in PACKAGES:
        declared = {e.text for e in ET.parse(ROOT / pkg / "package.xml").getroot().iter("exec_depend")}
        for path in (ROOT / pkg / pkg).rglob("*.py"):
            for node in ast.walk(ast.parse(path.read_text())):
                if isinstance(node, ast.ImportFrom) and node.module and node.module.split(".")[0] in ROS_IMPORTS:
                    assert node.module.split(".")[0] in declared, f"{pkg}/package.xml lacks {node.module.split('.')[0]}"
