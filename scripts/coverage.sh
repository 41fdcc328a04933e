#!/usr/bin/env bash
# Line coverage of the three packages by the unit and integration tiers (and with HAVEN_COVERAGE_ALL=1
# the ros and browser tiers too), measured in every Python process the tests start; prints the
# total and writes coverage.xml. Arguments go to pytest.
set -euo pipefail
cd "$(dirname "$0")/.."
unset PYTHONDONTWRITEBYTECODE
export COVERAGE_FILE="$PWD/.coverage" COVERAGE_RCFILE="$PWD/.coveragerc"
rm -f .coverage .coverage.*
tiers="unit or (integration and not ros and not browser)"
[ -n "${HAVEN_COVERAGE_ALL:-}" ] && tiers="unit or integration or ros or browser"
.venv/bin/pytest -q -p no:cacheprovider -n auto --dist loadfile --timeout 600 --cov --cov-report= -m "$tiers" "$@" || true
.venv/bin/coverage combine -q --append 2>/dev/null || true  # (the processes the tests started; pytest-cov combined its workers')
.venv/bin/coverage report --format=total | sed 's/^/coverage: line coverage (%): /'
.venv/bin/coverage xml -q -o coverage.xml
