"""Builds tf2_msgs (TFMessage) into the venv with colcon, for the pip-only setup: PyPI has no
tf2_msgs wheel. Per ROS_PIP_NOTES: the ROS build wheels must be installed (they are in the lock file),
and the include paths of the wheels' build machine baked into their *Export.cmake files rewritten
to this machine's. Installs with --merge-install into the venv prefix, where rclpy already finds
messages. Exits non-zero with one line if anything is missing; setup.sh then carries on without TF.

usage: .venv/bin/python scripts/build_interfaces.py
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import sysconfig
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PREFIX = Path(sys.prefix)


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


def main() -> int:
    for tool in ("cmake", "make", "cc"):
        if shutil.which(tool) is None:
            print(f"build_interfaces: {tool} not found; TF (tf2_msgs) will not be available", file=sys.stderr)
            return 1
    fixed = fix_export_paths()
    with tempfile.TemporaryDirectory() as tmp:
        cmd = [
            str(PREFIX / "bin" / "colcon"),
            "--log-base",
            f"{tmp}/log",
            "build",
            "--merge-install",
            "--base-paths",
            str(ROOT / "scripts" / "interfaces"),
            "--build-base",
            f"{tmp}/build",
            "--install-base",
            str(PREFIX),
            "--cmake-args",
            f"-DPython3_EXECUTABLE={sys.executable}",
            "-DBUILD_TESTING=OFF",
            "--event-handlers",
            "console_direct-",
        ]
        env = {**os.environ, "AMENT_PREFIX_PATH": str(PREFIX), "CMAKE_PREFIX_PATH": str(PREFIX)}
        r = subprocess.run(cmd, capture_output=True, text=True, env=env)
        if r.returncode != 0:
            tail = (r.stdout + r.stderr).strip().splitlines()[-15:]
            print("build_interfaces: colcon build of tf2_msgs failed:\n" + "\n".join(tail), file=sys.stderr)
            return 1
    check = subprocess.run([sys.executable, "-c", "from tf2_msgs.msg import TFMessage; TFMessage()"], capture_output=True, text=True)
    if check.returncode != 0:
        print(f"build_interfaces: tf2_msgs built but does not import: {check.stderr.strip().splitlines()[-1]}", file=sys.stderr)
        return 1
    print(f"build_interfaces: tf2_msgs built into {PREFIX} ({fixed} cmake files had their paths fixed)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
