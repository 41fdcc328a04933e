"""ros2_ws builds with colcon (as on a real Jazzy install) and its installed nodes run."""

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

pytestmark = pytest.mark.integration

ROOT = Path(__file__).resolve().parents[2]


def test_colcon_build_of_ros2_ws_installs_runnable_nodes(tmp_path):
    colcon = Path(sys.executable).parent / "colcon"
    if not colcon.exists():
        colcon = Path(shutil.which("colcon") or "colcon")
    r = subprocess.run(
        [
            str(colcon),
            "--log-base",
            str(tmp_path / "log"),
            "build",
            "--build-base",
            str(tmp_path / "build"),
            "--install-base",
            str(tmp_path / "install"),
            "--event-handlers",
            "console_direct-",
        ],
        cwd=ROOT / "ros2_ws",
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert r.returncode == 0, r.stdout + r.stderr
    assert "3 packages finished" in r.stdout
    install = tmp_path / "install"
    for pkg, exe in [("haven_sim", "sim_node"), ("haven_sim", "mux_node"), ("haven_scenarios", "haven")]:
        assert (install / pkg / "lib" / pkg / exe).is_file(), f"{pkg}/{exe} missing"
        assert (install / pkg / "share" / "ament_index" / "resource_index" / "packages" / pkg).is_file()
    assert (install / "haven_sim" / "share" / "haven_sim" / "worlds" / "small_test.yaml").is_file()
    # The installed node runs from the install space (as `ros2 run haven_sim sim_node` would start it).
    site = sorted(install.glob("*/lib/python3*/site-packages"))
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(map(str, site))}
    bad = tmp_path / "bad.yaml"
    bad.write_text("name: x\n")
    run = subprocess.run(
        [
            sys.executable,
            str(install / "haven_sim" / "lib" / "haven_sim" / "sim_node"),
            "--ros-args",
            "-p",
            f"world:={bad}",
        ],
        capture_output=True,
        text=True,
        timeout=60,
        env=env,
        cwd=tmp_path,
    )
    assert run.returncode == 2
    assert run.stderr.strip() == f"error: {bad}: robot: is required"  # (walls are not: a world may come from a map)
