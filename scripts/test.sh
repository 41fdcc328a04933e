#!/usr/bin/env bash
# The whole test suite: setup (idempotent), lint (ruff), strict type checks of the core and the nodes
# (mypy), then pytest (core unit tests, cross-process ROS tests, the colcon workspace build).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
echo "== ruff"
.venv/bin/ruff check .
echo "== mypy (core and nodes, strict)"
.venv/bin/mypy haven_sim/haven_sim haven_viz/haven_viz haven_scenarios/haven_scenarios
echo "== pytest"
exec .venv/bin/pytest -q --timeout 300 "$@"
