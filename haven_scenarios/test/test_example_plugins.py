"""The worked plugin package (examples/haven_lab_example), as a lab would use it: installed beside
HAVEN, its items are listed by `haven plugins`, named in a scenario, a study and a `--grid` axis,
and show in batch rows (the cue in its exposure column and in the simulated participants'
behaviour); its own tests pass. (Installed into a folder of this test's, on PYTHONPATH,
so the shared venv stays as setup made it; `pip install -e` into the venv works the same.)"""

from __future__ import annotations

import csv
import os
import subprocess
import sys
from pathlib import Path

import pytest

pytestmark = pytest.mark.integration

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "haven_lab_example"
HAVEN = [sys.executable, "-m", "haven_scenarios"]

SCENARIO = """\
name: hurried_hallway
world: hallway
kind: hallway
timeout_s: 240
condition: [turn_signals, floor_arrows]
robot:
  route: [B, C, D, A]
humans:
  - {id: h1, model: hurried, route: [B, A, D, C], speed_mps: 1.0}
"""
STUDY = """\
name: lab_pilot
scenarios: [hallway]
conditions: {none: [none], arrows: [floor_arrows]}
participants: [p01, p02]
questionnaires: [nasa_tlx, trust]
"""


def installed(tmp_path: Path) -> dict[str, str]:
    """The example package built and installed into tmp_path/site; the environment that sees it."""
    site = tmp_path / "site"
    pip = [
        sys.executable,
        "-m",
        "pip",
        "install",
        "--quiet",
        "--no-deps",
        "--no-build-isolation",
        "--target",
        str(site),
        str(EXAMPLE),
    ]
    r = subprocess.run(pip, capture_output=True, text=True, env={**os.environ, "PIP_DISABLE_PIP_VERSION_CHECK": "1"})
    assert r.returncode == 0, r.stderr[-2000:]
    return {
        **os.environ,
        "PYTHONPATH": os.pathsep.join([str(site), os.environ.get("PYTHONPATH", "")]).rstrip(os.pathsep),
    }


def haven(env: dict[str, str], *args: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*HAVEN, *args], capture_output=True, text=True, env=env, cwd=cwd, timeout=600)


def test_the_example_plugins_install_list_and_run_in_batch_trials_scenarios_and_studies(tmp_path):
    env = installed(tmp_path)
    listed = haven(env, "plugins").stdout.splitlines()
    for kind, name in (
        ("participants", "hurried"),
        ("metrics", "near"),
        ("questionnaires", "trust"),
        ("cues", "floor_arrows"),
    ):
        assert f"{kind} {name} haven-lab-example" in listed
    tests = [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", str(EXAMPLE / "tests")]
    own = subprocess.run(tests, env=env, capture_output=True, text=True)
    assert own.returncode == 0, own.stdout[-2000:]
    # A --grid axis and the metric's column in the batch rows.
    out = tmp_path / "rows.csv"
    r = haven(
        env, "batch", "hallway", "--grid", "model=walker,hurried", "--seeds", "0-1", "--workers", "1", "--out", str(out)
    )
    assert r.returncode == 0, r.stderr[-2000:]
    with out.open() as f:
        rows = list(csv.DictReader(f))
    assert [row["model"] for row in rows] == ["walker", "walker", "hurried", "hurried"]
    assert all(float(row["seconds_within_2m"]) >= 0 for row in rows) and not any("near_error" in row for row in rows)
    hurried, walker = (float(rows[k]["h1_time_to_finish_s"]) for k in (2, 0))
    assert hurried < walker  # a third faster than asked
    # The cue as a --grid condition: on show, in its exposure column, and read by the simulated
    # participants as the robot's way (as the projected path is: no hesitation where, without
    # a cue, each of them hesitates; cue_error 0: nobody misreads it here).
    grid = ("--grid", "condition=none,floor_arrows", "--grid", "cue_error=0")
    r = haven(env, "batch", "hallway", *grid, "--seeds", "0-1", "--workers", "1", "--out", str(out))
    assert r.returncode == 0, r.stderr[-2000:]
    with out.open() as f:
        rows = {(row["condition"], row["seed"]): row for row in csv.DictReader(f)}
    for seed in "01":
        none, arrows = rows[("none", seed)], rows[("floor_arrows", seed)]
        assert float(none["floor_arrows_shown_s"]) == 0.0 < float(arrows["floor_arrows_shown_s"])
        assert int(arrows["h1_hesitations"]) < int(none["h1_hesitations"])
    # Named in a scenario file and in a study file.
    (tmp_path / "hurried.yaml").write_text(SCENARIO)
    (tmp_path / "study.yaml").write_text(STUDY)
    r = haven(env, "validate", str(tmp_path / "hurried.yaml"), str(tmp_path / "study.yaml"))
    assert r.returncode == 0 and r.stdout.count("ok: ") == 2, r.stderr
    r = haven(env, "batch", str(tmp_path / "hurried.yaml"), "--trials", "1", "--out", str(tmp_path / "one.csv"))
    assert r.returncode == 0, r.stderr[-2000:]
    # Without the package: the names are refused in one line, listing what is registered.
    bare = {k: v for k, v in env.items() if k != "PYTHONPATH"}
    r = haven(bare, "validate", str(tmp_path / "hurried.yaml"))
    assert r.returncode == 2 and r.stderr.count("\n") == 1 and "hurried" in r.stderr and "walker" in r.stderr, r.stderr
    r = haven(bare, "validate", str(tmp_path / "study.yaml"))
    assert r.returncode == 2 and "unknown cue 'floor_arrows'" in r.stderr, r.stderr
