#!/usr/bin/env bash
# The whole test suite: setup (idempotent), lint (ruff), strict type checks of the core and the nodes
# (mypy), the docs site, the unit tier in a venv without ROS 2, then pytest: every tier (conftest.py says which).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
echo "== ruff"
.venv/bin/ruff check .
echo "== mypy (core and nodes, strict)"
.venv/bin/mypy haven_sim/haven_sim haven_viz/haven_viz haven_scenarios/haven_scenarios
echo "== docs (Sphinx, warnings as errors)"
.venv/bin/sphinx-build -W --keep-going -q -b html docs docs/_build/html
echo "== unit tier in a venv without ROS 2"
./scripts/test_unit_without_ros.sh --timeout 60
echo "== pytest (every tier: unit, integration, ros, browser)"
exec .venv/bin/pytest -q --timeout 300 --durations=25 "$@"
