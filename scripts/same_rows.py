"""Whether a change leaves the batch rows as they were: the same sweep run with the code of a git
revision (default: HEAD) and with the working tree, on this machine, compared row by row.

A refactor must not change a row. The two runs must be on one machine: the rows are reproducible
there to the last bit, but another machine's floating point (its CPU, its libraries' code paths)
may give other last digits, which a long trial's contacts then amplify; so the reference is not a
file kept in the repository.

usage: .venv/bin/python scripts/same_rows.py [REV] [--seeds N]
Prints the first differences (trial, column, before, after) and exits 1 if there are any.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("haven_scenarios", "haven_sim", "haven_viz")
# four scenarios of three kinds (a corridor, a room, a junction, a home), with and without the cues
SWEEP = """
import json, sys
from haven_scenarios import api
rows = api.sweep(["hallway", "shared_room", "office_crossing", "home_fetch"], seeds=range({seeds}),
                 grid={{"condition": ["all", "none"]}}, workers=2)
json.dump(rows, sys.stdout)
"""


def rows_of(tree: Path, seeds: int) -> list[dict[str, object]]:
    """The sweep's rows with the packages of `tree` first on the path (run in a process of its own)."""
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(str(tree / p) for p in PACKAGES)}
    done = subprocess.run(
        [sys.executable, "-c", SWEEP.format(seeds=seeds)],
        env=env,
        cwd=tempfile.gettempdir(),
        capture_output=True,
        text=True,
    )
    if done.returncode != 0:
        sys.exit(f"same_rows: the sweep failed with the code of {tree}:\n{done.stderr[-2000:]}")
    return list(json.loads(done.stdout))


def differences(before: list[dict[str, object]], after: list[dict[str, object]]) -> list[str]:
    if len(before) != len(after):
        return [f"{len(before)} rows before, {len(after)} after"]
    return [
        f"trial {old.get('trial')}: {key}: {old.get(key, '(none)')} -> {new.get(key, '(none)')}"
        for old, new in zip(before, after, strict=True)
        for key in sorted(old.keys() | new.keys())
        if old.get(key, "(none)") != new.get(key, "(none)")
    ]


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("rev", nargs="?", default="HEAD", help="the git revision to compare with (default HEAD)")
    ap.add_argument("--seeds", type=int, default=3, help="seeds 0..N-1 of each scenario and condition (default 3)")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory(prefix="haven_rows_") as scratch:
        ref = Path(scratch) / "ref"
        subprocess.run(["git", "-C", str(ROOT), "worktree", "add", "-q", "--detach", str(ref), args.rev], check=True)
        try:
            before = rows_of(ref, args.seeds)
        finally:
            subprocess.run(["git", "-C", str(ROOT), "worktree", "remove", "--force", str(ref)], check=True)
    after = rows_of(ROOT, args.seeds)
    digest = hashlib.sha1(json.dumps(after).encode()).hexdigest()
    found = differences(before, after)
    if found:
        print(f"same_rows: {len(found)} values differ from {args.rev}:", *found[:20], sep="\n  ")
        return 1
    print(f"same_rows: the {len(after)} rows equal {args.rev}'s (sha1 of the rows as JSON {digest})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
