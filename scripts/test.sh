#!/usr/bin/env bash
# The whole test suite: setup (idempotent), strict type checks of the rclpy-free core, then pytest
# (core unit tests, cross-process ROS tests, the colcon workspace build).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
echo "== mypy (core packages, strict)"
.venv/bin/mypy haven_sim/haven_sim haven_viz/haven_viz haven_scenarios/haven_scenarios
echo "== pytest"
exec .venv/bin/pytest -q --timeout 300 "$@"
