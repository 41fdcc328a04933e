"""The Docker files cannot be run here (no Docker engine), so they are checked by reading them:
every command they run must exist in the project."""

import re
import tomllib
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[2]


def entry_points():
    """(package, executable) pairs that `ros2 run` finds after colcon build."""
    pairs = set()
    for pkg in ("haven_sim", "haven_viz", "haven_scenarios"):
        scripts = tomllib.loads((ROOT / pkg / "pyproject.toml").read_text())["project"]["scripts"]
        pairs |= {(pkg, name) for name in scripts if re.fullmatch(r"[a-z_]+", name)}
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


def test_every_pypi_dependency_rosdep_would_install_is_pinned_by_the_image_and_the_bridge_stays_local():
    """rosdep's pip keys install whatever PyPI has that day: the image installs each of them first,
    at the lock file's version (rosdep then finds them installed). The compose bridge, which takes
    goals and the e-stop, listens on this machine unless asked."""
    ours = yaml.safe_load((ROOT / "ros2_ws" / "rosdep.yaml").read_text())
    pip_keys = {k: v["ubuntu"]["pip"]["packages"][0] for k, v in ours.items()}
    used = set()
    for pkg in ("haven_sim", "haven_viz", "haven_scenarios"):
        used |= set(
            re.findall(r"<exec_depend>(python3-[a-z0-9-]+-pip)</exec_depend>", (ROOT / pkg / "package.xml").read_text())
        )
    wanted = {pip_keys[k] for k in used}
    text = (ROOT / "docker" / "Dockerfile").read_text()
    pinned = re.search(r"pip install --no-cache-dir -c /tmp/constraints.txt ([a-z0-9 -]+)", text)
    assert pinned and wanted <= set(pinned.group(1).split()), wanted - set(pinned.group(1).split() if pinned else [])
    lock = (ROOT / "requirements.lock").read_text().lower()
    assert all(re.search(rf"^{re.escape(p)}==", lock, flags=re.M) for p in wanted)  # each has a version to pin to
    bridge = yaml.safe_load((ROOT / "docker" / "compose.yaml").read_text())["services"]["bridge"]["command"]
    assert "host:=${HAVEN_BRIDGE_HOST:-127.0.0.1}" in bridge
