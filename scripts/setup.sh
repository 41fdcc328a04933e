#!/usr/bin/env bash
# One-time (and idempotent) setup: a Python 3.12 (else 3.11) venv in .venv with the locked
# dependencies and the three HAVEN packages installed in editable mode. Nothing outside the
# project folder is touched.
set -euo pipefail
cd "$(dirname "$0")/.."
VENV=.venv

works() {  # a usable interpreter of a version Jazzy supports, with venv and pip available
  "$1" -c 'import sys, venv, ensurepip; sys.exit(0 if sys.version_info[:2] in ((3, 12), (3, 11)) else 1)' >/dev/null 2>&1
}

find_python() {
  local c root
  local candidates=("${HAVEN_PYTHON:-}")
  root=$(pyenv root 2>/dev/null || echo "$HOME/.pyenv")
  for minor in 12 11; do
    candidates+=("python3.$minor" "/usr/bin/python3.$minor" "/usr/local/bin/python3.$minor")
    for c in "$root"/versions/3."$minor".*/bin/python3."$minor"; do candidates+=("$c"); done
  done
  candidates+=(python3)
  for c in "${candidates[@]}"; do
    [ -n "$c" ] || continue
    if works "$c"; then command -v "$c" || echo "$c"; return 0; fi
  done
  return 1
}

if [ ! -x "$VENV/bin/python" ] || ! works "$VENV/bin/python"; then
  PY=$(find_python) || { echo "setup: no working Python 3.12 or 3.11 found (set HAVEN_PYTHON=/path/to/python3.12)" >&2; exit 1; }
  echo "setup: creating $VENV with $PY ($("$PY" -c 'import platform; print(platform.python_version())'))"
  rm -rf "$VENV"
  "$PY" -m venv "$VENV"
fi

stamp="$VENV/.haven-installed"
want=$(cat requirements.lock haven_*/setup.py haven_*/pyproject.toml | cksum)
if [ ! -f "$stamp" ] || [ "$(cat "$stamp")" != "$want" ]; then
  export PIP_DISABLE_PIP_VERSION_CHECK=1
  # uv installs the lock in ~15 s where pip took ~3 min on a fresh 2-core machine (pip then compiled
  # every module of every package; Python compiles the ones HAVEN imports on first use instead).
  install=("$VENV/bin/python" -m pip install --quiet)
  uv_pin=$(grep '^uv==' requirements.lock)
  if "$VENV/bin/python" -m pip install --quiet "$uv_pin" >/dev/null 2>&1; then
    install=("$VENV/bin/uv" pip install --quiet --python "$VENV/bin/python")
  else
    echo "setup: could not install $uv_pin; installing with pip (a few minutes)" >&2
  fi
  echo "setup: installing the locked packages into $VENV (ROS 2 Jazzy's wheels among them)"
  "${install[@]}" -r requirements.lock
  # compat mode puts each package folder on sys.path, so `python -m haven_sim...` also works from the
  # repository root (where the outer haven_sim/ folder would otherwise shadow the package).
  "${install[@]}" --no-deps --no-build-isolation --config-settings editable_mode=compat \
    -e haven_sim -e haven_viz -e haven_scenarios
  echo "$want" > "$stamp"
  echo "setup: installed the locked dependencies and the HAVEN packages into $VENV"
fi

# tf2_msgs and nav2_msgs are not on PyPI: build them into the venv once (needs cmake and a C
# compiler; tf2_msgs about 20 s, nav2_msgs about 2 minutes). Without them everything works except TF
# (/tf, /tf_static), which the simulator then skips with a warning, and Nav2's action servers
# (navigate_to_pose, ...). `make demo` (HAVEN_SETUP_FOR=demo) needs no Nav2: it builds tf2_msgs only
# and leaves nav2_msgs, and the browser pieces, to `make setup` or `make test`.
if [ "${HAVEN_SETUP_FOR:-}" = demo ]; then
  if ! "$VENV/bin/python" -c "import tf2_msgs.msg" >/dev/null 2>&1; then
    "$VENV/bin/python" scripts/build_interfaces.py tf2_msgs || echo "setup: continuing without it" >&2
  fi
  if ! "$VENV/bin/python" -c "import nav2_msgs.action" >/dev/null 2>&1; then
    echo "setup: nav2_msgs not built yet (the demo does not need it; Nav2's action servers need it): make setup builds it"
  fi
  exit 0
fi
if ! "$VENV/bin/python" -c "import tf2_msgs.msg, nav2_msgs.action" >/dev/null 2>&1; then
  "$VENV/bin/python" scripts/build_interfaces.py || echo "setup: continuing without them" >&2
fi

# The browser pieces: the pages' npm packages (a test rebuilds the committed bundles from them) and
# Debian's Chromium (the browser tests drive it headless). Where they cannot be had, those tests skip
# with one line saying why; HAVEN_NO_BROWSER=1 skips installing Chromium.
if command -v npm >/dev/null 2>&1 && [ ! haven_scenarios/web/node_modules/.package-lock.json -nt haven_scenarios/web/package-lock.json ]; then
  (cd haven_scenarios/web && npm ci --no-audit --no-fund --loglevel=error >/dev/null) \
    && echo "setup: installed the pages' npm packages (haven_scenarios/web/node_modules)" \
    || echo "setup: npm ci failed; the bundle rebuild test will skip" >&2
fi
if ! command -v chromium >/dev/null 2>&1 && [ -z "${HAVEN_NO_BROWSER:-}" ] && [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
  echo "setup: installing Debian's chromium for the browser tests (once, about 2 minutes)"
  { apt-get install -y -q chromium >/dev/null 2>&1 || { apt-get update -q >/dev/null 2>&1 && apt-get install -y -q chromium >/dev/null 2>&1; }; } \
    || echo "setup: could not install chromium; the browser tests will skip" >&2
fi
