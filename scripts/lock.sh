#!/usr/bin/env bash
# Re-resolve requirements.in into requirements.lock in a throw-away venv (run after editing requirements.in).
set -euo pipefail
cd "$(dirname "$0")/.."
PY=${HAVEN_PYTHON:-.venv/bin/python}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$PY" -m venv "$tmp/venv"
# The current pins constrain the resolution, so adding a package changes no other pin unless it must
# (then pip says which one conflicts: drop that line from the lock and run again); HAVEN_LOCK_UPGRADE=1 re-resolves all.
constraints=()
if [[ -f requirements.lock && -z "${HAVEN_LOCK_UPGRADE:-}" ]]; then
  grep '==' requirements.lock | sed 's/\[[a-z]*\]==/==/' > "$tmp/constraints.txt"
  constraints=(-c "$tmp/constraints.txt")
fi
"$tmp/venv/bin/pip" install --quiet --disable-pip-version-check -r requirements.in "${constraints[@]}"
{
  echo "# Exact versions of everything requirements.in pulls in (Python 3.12; 3.11 resolves the same set)."
  echo "# Regenerate: make lock. The import-name metadata the ros-* wheels also register (rclpy==7.1.5,"
  echo "# std_msgs==..., which are not PyPI packages) is left out; ros-jazzy-rclpy carries its extra."
  "$tmp/venv/bin/pip" freeze --all | grep -v '^pip==' | python3 -c '
import re, sys
lines = [l.strip() for l in sys.stdin if "==" in l]
names = {l.split("==")[0].lower() for l in lines}
for l in lines:
    n = l.split("==")[0]
    if "ros-" + n.replace("_", "-").lower() in names or n in ("rclpy", "rcutils"):
        continue
    print(l.replace("ros-jazzy-rclpy==", "ros-jazzy-rclpy[fastrtps]=="))
'
} > requirements.lock
echo "lock: $(grep -c == requirements.lock) pinned packages"
