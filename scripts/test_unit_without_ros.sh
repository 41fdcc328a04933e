#!/usr/bin/env bash
# The unit tier in a venv without ROS 2 (.venv-noros: the locked versions of HAVEN's PyPI
# dependencies, no ros-jazzy-* wheel, the three packages installed as in setup.sh): proves the core
# and its unit tests need nothing from ROS. Run by scripts/test.sh; after the first time, seconds.
set -euo pipefail
cd "$(dirname "$0")/.."
VENV=.venv-noros
BASE=$(.venv/bin/python -c 'import sys; print(sys._base_executable)')
want=$(cat requirements.lock haven_*/setup.py haven_*/pyproject.toml "$0" | cksum)
stamp="$VENV/.haven-installed"
if [ ! -f "$stamp" ] || [ "$(cat "$stamp")" != "$want" ]; then
  rm -rf "$VENV"
  "$BASE" -m venv "$VENV"
  grep -v '^ros-' requirements.lock | sed 's/\[[a-z]*\]==/==/' > "$VENV/constraints.txt"
  export PIP_DISABLE_PIP_VERSION_CHECK=1
  install=("$VENV/bin/python" -m pip install --quiet)  # (uv, where setup.sh installed it: seconds)
  [ -x .venv/bin/uv ] && install=(.venv/bin/uv pip install --quiet --python "$VENV/bin/python")
  "${install[@]}" -c "$VENV/constraints.txt" \
    setuptools numpy pymunk PyYAML pydantic pillow matplotlib rosbags mcap foxglove-sdk cryptography filelock aiohttp tqdm statsmodels pytest pytest-timeout pytest-xdist sybil
  "${install[@]}" --no-deps --no-build-isolation --config-settings editable_mode=compat \
    -e haven_sim -e haven_viz -e haven_scenarios
  echo "$want" > "$stamp"
fi
if "$VENV/bin/python" -c "import rclpy" >/dev/null 2>&1; then
  echo "test_unit_without_ros: rclpy is importable in $VENV; this is not a venv without ROS" >&2
  exit 1
fi
exec "$VENV/bin/pytest" -q -p no:cacheprovider -m unit "$@"
