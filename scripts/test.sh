#!/usr/bin/env bash
# The whole test suite: setup (idempotent), lint and format (ruff), the import layers, strict type checks of the core
# and the nodes (mypy), the docs site, then every test tier (conftest.py says which).
set -euo pipefail
cd "$(dirname "$0")/.."
# Bytecode caches on: where PYTHONDONTWRITEBYTECODE is set, every process the tests start compiles
# HAVEN's modules again (about 0.5 s of CPU each, nine per live trial) and pytest rewrites every
# test module's asserts on every run (collecting the unit tier took 12 s of CPU instead of 4.5 s).
unset PYTHONDONTWRITEBYTECODE
./scripts/setup.sh
echo "== ruff"
.venv/bin/ruff check .
.venv/bin/ruff format --check .
echo "== import layers (import-linter: .importlinter)"
.venv/bin/lint-imports
# mypy and the docs site (one core each) run beside each other and beside the unit tier.
mkdir -p .test-logs
.venv/bin/mypy haven_sim/haven_sim haven_viz/haven_viz haven_scenarios/haven_scenarios >.test-logs/mypy.log 2>&1 &
mypy_pid=$!
.venv/bin/sphinx-build -W --keep-going -q -b html docs docs/_build/html >.test-logs/docs.log 2>&1 &
docs_pid=$!
# Each test runs once: the unit tier only in the venv without ROS 2. Every tier runs on every core
# (pytest-xdist; each test has its own tmp_path, ports and ROS domain, and the ROS tests of each
# worker keep to a slice of the domains of their own: haven_sim/test/ros_harness.py).
# Every tier runs even when one before it failed; the suite fails if any did. (With arguments, say a
# test file, a tier with none of those tests in it is no failure: pytest's exit code 5.)
failed=()
tier() {
  local rc=0
  "$@" || rc=$?
  [ "$rc" -eq 0 ] || { [ "$rc" -eq 5 ] && [ "$ARGS" -gt 0 ]; }
}
ARGS=$#
echo "== unit tier in a venv without ROS 2 (parallel)"
tier ./scripts/test_unit_without_ros.sh --timeout 60 -n auto --durations=10 "$@" || failed+=(unit)
echo "== mypy (core and nodes, strict)"
wait "$mypy_pid" && tail -1 .test-logs/mypy.log || { cat .test-logs/mypy.log; failed+=(mypy); }
echo "== docs (Sphinx, warnings as errors)"
wait "$docs_pid" && echo "docs built: docs/_build/html" || { cat .test-logs/docs.log; failed+=(docs); }
# The integration tier is spread by file (--dist loadfile): a docs page's examples share one
# namespace, a folder and their `% skip: next` marks, so they run in order on one worker. (Run as one
# session with the ros and browser tiers, the suite took longer on 2 cores: 18 min against 15.)
echo "== integration tier (parallel)"
tier .venv/bin/pytest -q --timeout 300 -n auto --dist loadfile --durations=25 -m "integration and not ros and not browser" "$@" ||
  failed+=(integration)
echo "== ros and browser tiers (parallel)"
tier .venv/bin/pytest -q --timeout 300 -n auto --dist worksteal --durations=25 -m "ros or browser" "$@" ||
  failed+=("ros and browser")
if [ ${#failed[@]} -gt 0 ]; then
  echo "test: failed in the tier(s): ${failed[*]}" >&2
  exit 1
fi
