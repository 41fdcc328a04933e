"""The Docker files cannot be run here (no Docker engine), so they are checked by reading them:
every command they run must exist in the project."""

import re
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[2]


def entry_points():
    """(package, executable) pairs that `ros2 run` finds after colcon build."""
    pairs = set()
    for pkg in ("haven_sim", "haven_viz", "haven_scenarios"):
        text = (ROOT / pkg / "setup.py").read_text()
        for name in re.findall(r'"([a-z_]+) = [a-z_.]+:main"', text):
            pairs.add((pkg, name))
    return pairs


def test_compose_runs_only_executables_the_packages_install():
    compose = yaml.safe_load((ROOT / "docker" / "compose.yaml").read_text())
    known = entry_points()
    services = compose["services"]
    assert {"sim", "mux", "planner", "controller", "viz", "bridge"} <= set(services)
    for name, service in services.items():
        cmd = service["command"]
        assert cmd[:2] == ["ros2", "run"], name
        assert (cmd[2], cmd[3]) in known, f"{name}: {cmd[2]} {cmd[3]} is not an installed executable"
        assert service["image"] == "haven" and service["environment"]["ROS_DOMAIN_ID"]


def test_dockerfile_builds_the_workspace_and_runs_an_existing_command():
    text = (ROOT / "docker" / "Dockerfile").read_text()
    assert next(line for line in text.splitlines() if line.startswith("FROM")) == "FROM ros:jazzy"
    for path in re.findall(r"^COPY (\S+) ", text, flags=re.M):
        assert (ROOT / path).exists(), f"Dockerfile copies {path}, which does not exist"
    assert "colcon build" in text and "rosdep install" in text
    cmd = re.search(r'^CMD \["ros2", "run", "([a-z_]+)", "([a-z_]+)"', text, flags=re.M)
    assert cmd and (cmd.group(1), cmd.group(2)) in entry_points()
    entry = (ROOT / "docker" / "entrypoint.sh").read_text()
    assert "source /haven/ros2_ws/install/setup.bash" in entry
