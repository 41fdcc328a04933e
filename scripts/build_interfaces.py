"""Builds the interface packages PyPI has no wheel for into the venv with colcon, for the pip-only
setup: tf2_msgs (TF), and the nav2_msgs subset that HAVEN's Nav2 action servers and
nav2_simple_commander need (with geographic_msgs' two messages it uses). Their interface files are
in scripts/interfaces/. Per ROS_PIP_NOTES: the ROS build wheels must be installed (they are in the
lock file), and the include paths of the wheels' build machine baked into their *Export.cmake
files rewritten to this machine's. Installs with --merge-install into the venv prefix, where rclpy
already finds messages; only packages that do not import yet are built. Exits non-zero with one
line if anything is missing; setup.sh then carries on without them.

The build is not load-limited: colcon's default MAKEFLAGS (`-jN -lN`) makes make wait while the
machine's load is above N, which on a shared machine serialised nav2_msgs to 26-52 minutes; here
make runs N jobs whatever the load, and independent packages build side by side. A line is printed
as each package starts and ends. Only the C type supports rclpy loads are generated (each package's
CMakeLists.txt drops the C++ generators): nav2_msgs took 3 min 19 s with them and 2 min 6 s without,
on an idle 2-core machine.

usage: .venv/bin/python scripts/build_interfaces.py [PACKAGE ...]   (default: all of them)
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import sysconfig
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PREFIX = Path(sys.prefix)
# package -> (an import that proves it is built, what is missing without it)
PACKAGES = {
    "tf2_msgs": ("from tf2_msgs.msg import TFMessage; TFMessage()", "TF (/tf, /tf_static)"),
    "geographic_msgs": ("from geographic_msgs.msg import GeoPose; GeoPose()", "Nav2's actions"),
    "nav2_msgs": (
        "from nav2_msgs.action import NavigateToPose; NavigateToPose.Goal()",
        "Nav2's actions (navigate_to_pose, ...)",
    ),
}


def fix_export_paths() -> int:
    include = sysconfig.get_paths()["include"]
    site = sysconfig.get_paths()["purelib"]
    pattern_inc = re.compile(r"/opt/python/cp3\d+-cp3\d+/include/python3\.\d+")
    pattern_site = re.compile(r"/opt/python/cp3\d+-cp3\d+/lib/python3\.\d+/site-packages")
    fixed = 0
    for f in (PREFIX / "share").glob("*/cmake/*.cmake"):
        text = f.read_text()
        if "/opt/python/" not in text:
            continue
        f.write_text(pattern_site.sub(site, pattern_inc.sub(include, text)))
        fixed += 1
    return fixed


def imports(package: str) -> bool:
    return subprocess.run([sys.executable, "-c", PACKAGES[package][0]], capture_output=True).returncode == 0


def main(asked: list[str]) -> int:
    unknown = [p for p in asked if p not in PACKAGES]
    if unknown:
        print(f"build_interfaces: unknown package {unknown[0]} (known: {', '.join(PACKAGES)})", file=sys.stderr)
        return 2
    asked = asked or list(PACKAGES)
    if "nav2_msgs" in asked and "geographic_msgs" not in asked:
        asked.insert(0, "geographic_msgs")  # (nav2_msgs needs it)
    wanted = [p for p in asked if not imports(p)]
    if not wanted:
        print("build_interfaces: " + ", ".join(asked) + " already built")
        return 0
    missing = "; ".join(f"{p}: {PACKAGES[p][1]}" for p in wanted)
    for tool in ("cmake", "make", "cc"):
        if shutil.which(tool) is None:
            print(f"build_interfaces: {tool} not found; not available: {missing}", file=sys.stderr)
            return 1
    fix_export_paths()
    jobs = os.cpu_count() or 2
    started = time.monotonic()
    with tempfile.TemporaryDirectory() as tmp:
        cmd = [
            str(PREFIX / "bin" / "colcon"),
            "--log-base",
            f"{tmp}/log",
            "build",
            "--merge-install",
            "--base-paths",
            str(ROOT / "scripts" / "interfaces"),
            "--packages-select",
            *wanted,
            "--build-base",
            f"{tmp}/build",
            "--install-base",
            str(PREFIX),
            "--cmake-args",
            f"-DPython3_EXECUTABLE={sys.executable}",
            "-DBUILD_TESTING=OFF",
            "--parallel-workers",
            str(jobs),
            "--event-handlers",
            "console_direct-",
            "console_start_end+",
        ]
        env = {**os.environ, "AMENT_PREFIX_PATH": str(PREFIX), "CMAKE_PREFIX_PATH": str(PREFIX)}
        env.setdefault("MAKEFLAGS", f"-j{jobs}")  # (no -l: see the module docstring)
        slow = " (nav2_msgs takes about 2 minutes)" if "nav2_msgs" in wanted else ""
        print(f"build_interfaces: building {', '.join(wanted)} with {jobs} jobs{slow}", flush=True)
        said: list[str] = []
        with subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env) as colcon:
            assert colcon.stdout is not None
            for line in colcon.stdout:
                said.append(line.rstrip())
                if line.startswith(("Starting >>>", "Finished <<<", "Failed")):
                    print(f"build_interfaces: {line.strip()}", flush=True)
        if colcon.returncode != 0:
            print(
                f"build_interfaces: colcon build of {', '.join(wanted)} failed:\n" + "\n".join(said[-15:]),
                file=sys.stderr,
            )
            return 1
    broken = [p for p in wanted if not imports(p)]
    if broken:
        print(f"build_interfaces: built but does not import: {', '.join(broken)}", file=sys.stderr)
        return 1
    took = time.monotonic() - started
    print(f"build_interfaces: {', '.join(wanted)} built into {PREFIX} in {took:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
