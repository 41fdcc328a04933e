"""Every third-party module a package's code imports is declared where each way of installing it
looks: pyproject.toml (pip) and, as a rosdep key, package.xml (colcon and rosdep, as the Docker image
installs). Derived from the code itself, so a new import without a declaration fails here."""

from __future__ import annotations

import ast
import importlib.metadata
import re
import sys
import tomllib
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
import yaml

pytestmark = pytest.mark.integration  # (reads the installed distributions: ROS's too)

ROOT = Path(__file__).resolve().parents[2]
PACKAGES = ("haven_sim", "haven_viz", "haven_scenarios")

# rosdep keys from ros/rosdistro (rosdep/python.yaml, read 2026-11-26) -> the PyPI distribution each
# installs; ros2_ws/rosdep.yaml adds ours for those upstream has no key for.
UPSTREAM_KEYS = {
    "python3-numpy": "numpy",
    "python3-yaml": "PyYAML",
    "python3-matplotlib": "matplotlib",
    "python3-tqdm": "tqdm",
    "python3-pydantic": "pydantic",
    "python3-rosbags-pip": "rosbags",
    "python3-scipy": "scipy",
    "python3-pil": "pillow",
    "python3-cryptography": "cryptography",
}


def normal(name: str) -> str:
    """A distribution name as PEP 503 compares them."""
    return re.sub(r"[-_.]+", "-", name).lower()


def imported_modules(package: str) -> dict[str, str]:
    """Top-level module -> a file importing it, for every absolute import in the package's code
    (functions' lazy imports included) that is neither the standard library's nor HAVEN's."""
    found: dict[str, str] = {}
    for path in sorted((ROOT / package / package).rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(), str(path))):
            if isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
                names = [node.module]
            else:
                continue
            for name in names:
                top = name.partition(".")[0]
                if top not in sys.stdlib_module_names and not top.startswith("haven_"):
                    found.setdefault(top, str(path.relative_to(ROOT)))
    return found


def setup_requirements(package: str) -> tuple[set[str], set[str]]:
    """(dependencies, every extra's requirements) of the package's pyproject.toml, normalised."""
    project = tomllib.loads((ROOT / package / "pyproject.toml").read_text())["project"]
    names = lambda reqs: {normal(re.split(r"[<>=!~\[;\s]", r, maxsplit=1)[0]) for r in reqs}  # noqa: E731
    extras = set().union(*(names(v) for v in project.get("optional-dependencies", {}).values()))
    return names(project.get("dependencies", [])), extras


def exec_depends(package: str) -> set[str]:
    root = ET.parse(ROOT / package / "package.xml").getroot()
    return {e.text.strip() for tag in ("exec_depend", "depend") for e in root.iter(tag) if e.text}


def rosdep_keys() -> dict[str, str]:
    """rosdep key -> PyPI distribution it installs (upstream's and ours)."""
    ours = yaml.safe_load((ROOT / "ros2_ws" / "rosdep.yaml").read_text())
    keys = {k: v["ubuntu"]["pip"]["packages"][0] for k, v in ours.items()}
    return {k: normal(v) for k, v in {**UPSTREAM_KEYS, **keys}.items()}


def is_ros_package(module: str, dists: list[str]) -> bool:
    """rclpy and the message packages: ROS packages, declared by their own name in package.xml
    (pip gets them from the ros-jazzy-* wheels, colcon from the ROS install)."""
    return any(d.startswith("ros-") for d in dists) or module.endswith(("_msgs", "_srvs", "_interfaces"))


@pytest.mark.parametrize("package", PACKAGES)
def test_every_runtime_import_is_declared_in_pyproject_and_package_xml(package):
    distributions = importlib.metadata.packages_distributions()
    required, extras = setup_requirements(package)
    depends = exec_depends(package)
    keys = rosdep_keys()
    by_key = {dist for key, dist in keys.items() if key in depends}
    problems = []
    for module, where in sorted(imported_modules(package).items()):
        dists = distributions.get(module, [])
        if is_ros_package(module, dists):
            if module not in depends:
                problems.append(f"{where}: imports {module}, not an exec_depend in {package}/package.xml")
            continue
        if not dists:
            problems.append(f"{where}: imports {module}, which no installed distribution provides")
            continue
        dist = normal(dists[0])
        if dist in extras:
            continue  # optional: the code says which extra to install when it is missing
        if dist not in required:
            problems.append(f"{where}: imports {module} ({dist}), not in {package}/pyproject.toml dependencies")
        if dist not in by_key:
            problems.append(f"{where}: imports {module} ({dist}), no rosdep key for it in {package}/package.xml")
    assert problems == [], "\n".join(problems)


def test_every_rosdep_key_in_package_xml_is_known():
    """A key rosdep cannot resolve stops `rosdep install` for the whole workspace."""
    keys = rosdep_keys()
    unknown = [
        f"{p}: {d}" for p in PACKAGES for d in sorted(exec_depends(p)) if d.startswith("python3-") and d not in keys
    ]
    assert unknown == []
