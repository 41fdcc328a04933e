"""`haven study` as a researcher uses it: a batch pilot of three simulated participants, stopped
with Ctrl-C part-way and resumed, its status, and the report's tables and figure."""

from __future__ import annotations

import csv
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
import yaml

from haven_scenarios.study.conditions import parse_condition
from haven_scenarios.study.questionnaires import ANSWERS_FILE, BUILTINS, answers_record, likert
from haven_scenarios.tools.cli import main

pytestmark = pytest.mark.integration

HAVEN = [sys.executable, "-m", "haven_scenarios"]
LEGIBILITY = {
    "name": "legibility",
    "points": 7,
    "items": [{"id": "side", "text": "I knew its side."}, {"id": "odd", "text": "It surprised me.", "reverse": True}],
}
STUDY = {
    "name": "pilot",
    "scenarios": ["shared_room"],
    "conditions": {"none": ["none"], "all": ["all"]},
    "participants": 3,
    "practice": [{"scenario": "shared_room", "condition": "all"}],
    "seeds": {"policy": "per_participant", "base": 0},
    "questionnaires": ["nasa_tlx", LEGIBILITY],
}


# `haven ARGS...` whose second batch trial, once running, touches the file argv[1] and waits; with
# Ctrl-C as in a terminal (a shell's background job would start it with SIGINT ignored).
HOLD_SECOND_TRIAL = """
import pathlib, signal, sys, time
signal.signal(signal.SIGINT, signal.default_int_handler)
from haven_scenarios.run import session_batch
from haven_scenarios.tools.cli import main

real, calls = session_batch.run_trial, []

def held(*args, **kwargs):
    calls.append(1)
    if len(calls) == 2:
        pathlib.Path(sys.argv[1]).touch()
        time.sleep(300)
    return real(*args, **kwargs)

session_batch.run_trial = held
sys.exit(main(sys.argv[2:]))
"""


def study_file(tmp_path: Path, **changes: object) -> Path:
    path = tmp_path / "pilot.yaml"
    path.write_text(yaml.safe_dump({**STUDY, **changes}, sort_keys=False))
    return path


def sessions(root: Path) -> dict[str, list[tuple[str, str]]]:
    """Per trial folder (`p01/02_shared_room-none`), its attempts: (session folder, outcome)."""
    out: dict[str, list[tuple[str, str]]] = {}
    for info in sorted(root.glob("*/*/*/session.json")):
        trial = f"{info.parents[2].name}/{info.parents[1].name}"
        out.setdefault(trial, []).append((info.parent.name, json.loads(info.read_text())["outcome"]))
    return out


def wait_for(condition, timeout_s: float = 60.0) -> None:  # type: ignore[no-untyped-def]
    deadline = time.monotonic() + timeout_s
    while not condition():
        assert time.monotonic() < deadline, "timed out"
        time.sleep(0.01)


def haven(*args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*HAVEN, *args], cwd=cwd, capture_output=True, text=True, timeout=300)


def test_batch_study_resumes_after_ctrl_c_without_running_a_finished_trial_twice(tmp_path: Path) -> None:
    path = study_file(tmp_path)
    root = tmp_path / "studies" / "pilot"
    assert haven("study", "run", str(path), "--participant", "p01", "--batch", cwd=tmp_path).returncode == 0
    # p02: Ctrl-C (SIGINT to the process group, as a terminal sends it) while its second trial runs.
    # A batch trial takes a fraction of a second, so the second one is held until the signal comes:
    # where the study is cut is the test's choice, not the machine's speed.
    held = tmp_path / "second_trial_running"
    proc = subprocess.Popen([sys.executable, "-c", HOLD_SECOND_TRIAL, str(held),
                             "study", "run", str(path), "--participant", "p02", "--batch"],
                            cwd=tmp_path, start_new_session=True, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True)  # fmt: skip
    wait_for(held.exists, 120.0)
    os.killpg(proc.pid, signal.SIGINT)
    _out, err = proc.communicate(timeout=60)
    assert proc.returncode == 130, err
    assert "stopped during 02_" in err and "Traceback" not in err
    before = sessions(root)
    interrupted = [t for t, a in before.items() if t.startswith("p02/") and a[-1][1] != "completed"]
    assert interrupted == [next(t for t in before if t.startswith("p02/02_"))]
    assert before[interrupted[0]][0][1] == "interrupted (stopped by a signal)"  # (written as the signal came)

    status = haven("study", "status", str(path), cwd=tmp_path)
    assert status.returncode == 0
    lines = {line.split()[0]: line for line in status.stdout.splitlines() if line.startswith("p0")}
    assert "3/3" in lines["p01"] and "1/3" in lines["p02"] and "1 attempt(s)" in lines["p02"] and "0/3" in lines["p03"]
    assert "02_shared_room-" in lines["p02"].split("last:")[1]  # what comes next: the interrupted trial

    for p in ("p02", "p03"):
        r = haven("study", "run", str(path), "--participant", p, "--batch", cwd=tmp_path)
        assert r.returncode == 0, r.stderr
    after = sessions(root)
    assert len(after) == 9
    for trial, tried in before.items():  # nothing finished ran again; the interrupted attempt is kept
        assert after[trial][: len(tried)] == tried
        assert len(after[trial]) == len(tried) + (trial in interrupted)
    assert all(a[-1][1] == "completed" for a in after.values())
    again = haven("study", "run", str(path), "--participant", "p01", "--batch", cwd=tmp_path)
    assert again.returncode == 0 and "3/3 trials done" in again.stdout and sessions(root) == after

    changed = haven(
        "study", "run", str(study_file(tmp_path, participants=4)), "--participant", "p04", "--batch", cwd=tmp_path
    )
    assert (
        changed.returncode == 2
        and changed.stderr.count("\n") == 1
        and "the study changed since its first run" in changed.stderr
    )

    report = haven("study", "report", str(study_file(tmp_path)), cwd=tmp_path)
    assert report.returncode == 0, report.stderr
    with (root / "report" / "study_long.csv").open() as f:
        rows = list(csv.DictReader(f))
    assert list(rows[0])[:3] == ["participant", "human", "trial_id"] and list(rows[0])[-3:] == [
        "measure",
        "unit",
        "value",
    ]
    with (root / "report" / "codebook.csv").open() as f:  # every measure of the long table, documented
        book = {(r["per_person"] == "True", r["measure"]): r for r in csv.DictReader(f)}
    assert book.keys() == {(bool(r["human"]), r["measure"]) for r in rows} and all(r["source"] for r in book.values())
    assert {(r["participant"], r["trial_id"]) for r in rows} == {
        (f"p0{k}", t) for k in (1, 2, 3) for t in ("practice1-shared_room-all", "shared_room-none", "shared_room-all")
    }
    closest = [r for r in rows if r["measure"] == "min_human_centre_distance_m"]
    assert len(closest) == 9 and all(r["human"] == "" and r["unit"] == "m" for r in closest)
    standing = [r for r in rows if r["measure"] == "time_not_moving_s" and r["human"] == "h1"]
    assert len(standing) == 9
    with (root / "report" / "study_wide.csv").open() as f:
        wide = list(csv.DictReader(f))
    assert len(wide) == 9 and "h1_time_not_moving_s" in wide[0] and "min_human_centre_distance_m" in wide[0]
    png = root / "report" / "summary.png"
    assert png.stat().st_size > 20_000

    # Re-planned with other seeds: p01's finished sessions ran with the old ones, so they are kept
    # but no longer count, and the trials run again; the table labels each session as it ran.
    reseeded = study_file(tmp_path, seeds={"policy": "per_participant", "base": 100})
    r = haven("study", "run", str(reseeded), "--participant", "p01", "--batch", "--replan", cwd=tmp_path)
    assert r.returncode == 0 and "0/3 trials done" in r.stdout, r.stderr
    replanned = sessions(root)
    assert all(
        replanned[t][: len(after[t])] == after[t] and len(replanned[t]) == len(after[t]) + t.startswith("p01/")
        for t in after
    )
    status = haven("study", "status", str(reseeded), cwd=tmp_path)
    assert "3/3" in next(line for line in status.stdout.splitlines() if line.startswith("p01")), status.stdout
    assert haven("study", "report", str(reseeded), cwd=tmp_path).returncode == 0
    with (root / "report" / "study_long.csv").open() as f:
        seeds = {(r["participant"], r["seed"]) for r in csv.DictReader(f)}
    assert seeds == {("p01", "100")}  # (p02's and p03's sessions ran with the old seeds: theirs are to run again)


def test_a_second_runner_on_the_same_participant_is_refused_and_a_killed_runner_leaves_no_lock(tmp_path: Path) -> None:
    """Two `haven study run --batch` on one participant: the second says who holds the participant
    and exits before running anything; after the first is killed outright (SIGKILL: no clean-up),
    the lock is gone and the study goes on; no trial ever has two finished attempts."""
    path = study_file(tmp_path, participants=1)
    root = tmp_path / "studies" / "pilot"
    held = tmp_path / "second_trial_running"
    first = subprocess.Popen([sys.executable, "-c", HOLD_SECOND_TRIAL, str(held),
                              "study", "run", str(path), "--participant", "p01", "--batch"],
                             cwd=tmp_path, start_new_session=True, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True)  # fmt: skip
    try:
        wait_for(held.exists, 120.0)
        before = sessions(root)
        second = haven("study", "run", str(path), "--participant", "p01", "--batch", cwd=tmp_path)
        assert second.returncode == 2 and second.stderr.count("\n") == 1, second.stderr
        assert (
            f"participant p01 of study pilot is already being run (pid {first.pid}" in second.stderr
            and "study run" in second.stderr
        )
        assert sessions(root) == before  # it ran nothing
        # (still held: still refused)
        other = haven("study", "run", str(path), "--participant", "p01", "--batch", cwd=tmp_path)
        assert other.returncode == 2
    finally:
        os.killpg(first.pid, signal.SIGKILL)
        first.communicate(timeout=60)
    after = haven("study", "run", str(path), "--participant", "p01", "--batch", cwd=tmp_path)
    assert after.returncode == 0, after.stderr
    finished = {t: [a for a in tried if a[1] == "completed"] for t, tried in sessions(root).items()}
    assert len(finished) == 3 and all(len(a) == 1 for a in finished.values()), finished


def test_report_reads_questionnaires_and_flags_invalid_sessions(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    conditions = {"none": ["none"], "path": ["path_projection"]}
    path = study_file(
        tmp_path, participants=2, conditions=conditions, practice=[{"scenario": "shared_room", "condition": "path"}]
    )
    monkeypatch.chdir(tmp_path)
    for p in ("p01", "p02"):
        assert main(["study", "run", str(path), "--participant", p, "--batch"]) == 0
    root = tmp_path / "studies" / "pilot"
    tlx, legibility = BUILTINS["nasa_tlx"], likert(LEGIBILITY, "test")
    folders = sorted(s.parent for s in root.glob("*/*/*/session.json"))
    for k, folder in enumerate(folders):
        answers = {"h1": {
            "nasa_tlx": answers_record(tlx, {i.id: 5 * k for i in tlx.items}, "2026-11-24T10:00:00"),
            "legibility": answers_record(legibility, {"side": 1 + k % 7, "odd": 2}, "2026-11-24T10:01:00"),
        }}  # fmt: skip
        (folder / ANSWERS_FILE).write_text(json.dumps(answers))
    bad = next(f for f in folders if f.parents[1].name == "p01" and f.parent.name.startswith("02_"))
    metrics = json.loads((bad / "metrics.json").read_text())
    (bad / "metrics.json").write_text(json.dumps({**metrics, "valid": False, "invalid_reasons": ["lost messages"]}))

    assert main(["study", "report", str(path), "--out", str(tmp_path / "out")]) == 0
    with (tmp_path / "out" / "study_long.csv").open() as f:
        rows = list(csv.DictReader(f))
    tlx_rows = {(r["participant"], r["trial_id"]): r for r in rows if r["measure"] == "nasa_tlx_raw"}
    assert len(tlx_rows) == 6 and all(r["human"] == "h1" for r in tlx_rows.values())
    expected = {(f.parents[1].name, f.parent.name.split("_", 1)[1]): 5.0 * k for k, f in enumerate(folders)}
    assert {key: float(r["value"]) for key, r in tlx_rows.items()} == expected
    flagged = {r["session"] for r in rows if r["valid"] == "False"}
    assert flagged == {str(bad.relative_to(root))}  # the invalid session is in the table, flagged
    with (tmp_path / "out" / "summary.csv").open() as f:
        summary = list(csv.DictReader(f))
    leg = {r["condition"]: r for r in summary if r["measure"] == "legibility"}
    assert set(leg) == {"none", "path"}
    # 2 participants x 2 conditions: practice left out
    assert sum(int(r["n"]) + int(r["n_invalid"]) for r in leg.values()) == 4
    bad_condition = next(r["condition"] for r in rows if r["session"] == str(bad.relative_to(root)))
    assert (int(leg[bad_condition]["n"]), int(leg[bad_condition]["n_invalid"])) == (1, 1)
    good = [
        float(r["value"])
        for r in rows
        if r["measure"] == "legibility"
        and r["condition"] == bad_condition
        and r["valid"] == "True"
        and r["practice"] == "False"
    ]
    assert float(leg[bad_condition]["mean"]) == pytest.approx(sum(good) / len(good))
    assert (tmp_path / "out" / "summary.png").stat().st_size > 20_000


def test_with_web_each_trial_is_a_browser_trial_with_the_studys_questionnaires(tmp_path: Path) -> None:
    """Each trial is asked for as `haven run` would be (no command line in between): in the browser,
    every human teleoperated, the study's questionnaires (its own Likert one as a file)."""
    from haven_scenarios.conduct.recorded_trial import plan_trial
    from haven_scenarios.conduct.study_run import trial_request
    from haven_scenarios.record.progress import questionnaire_specs
    from haven_scenarios.study.protocol import load_study
    from haven_scenarios.study.schedule import participant_schedule
    from haven_scenarios.tools.cli import build_parser

    path = study_file(tmp_path)
    args = build_parser().parse_args(
        ["study", "run", str(path), "--participant", "p02", "--web", "--port", "0", "--domain-id", "7"]
    )
    study = load_study(path)
    specs = questionnaire_specs(study, tmp_path / "studies" / "pilot")
    trial = participant_schedule(study, "p02")[1]
    request = trial_request(args, trial, specs, study)
    assert request.extra["study"] == {"name": "pilot", "trial_id": trial.trial_id, "position": 2,
                                      "condition": trial.condition, "practice": False, "sequence": 2, "block": 1,
                                      "position_in_block": 1, "previous_condition": ""}  # fmt: skip
    assert (request.scenario, request.participant, request.condition, request.seed) == (
        "shared_room",
        "p02",
        tuple(trial.cues),
        1,
    )
    # the study's second participant (seed base 0), at the second place in their session
    assert request.person == (1, 2)
    assert request.web is not None and (request.web.host, request.web.port) == ("127.0.0.1", 0) and request.teleop == ()
    assert request.questionnaires[0] == "nasa_tlx"
    written = Path(request.questionnaires[-1])
    assert written.parent == (tmp_path / "studies" / "pilot" / "questionnaires").resolve()
    # the study's own, as `haven run` reads it
    assert likert(yaml.safe_load(written.read_text()), "file") == likert(LEGIBILITY, "file")
    plan = plan_trial(request)
    assert plan.web is not None and [h.teleoperated for h in plan.scenario.humans] == [True] * len(plan.scenario.humans)
    assert plan.extra["questionnaires"][0] == "nasa_tlx" and plan.toggles == parse_condition(list(trial.cues))


def test_a_reader_that_stops_early_gets_no_traceback(tmp_path: Path) -> None:
    """`haven study plan haven_paper | head -1`: the pipe closes; haven stops quietly."""
    proc = subprocess.Popen(
        [*HAVEN, "study", "plan", "haven_paper"], cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE
    )
    assert proc.stdout is not None and proc.stderr is not None
    proc.stdout.close()
    err = proc.stderr.read().decode()
    assert proc.wait(timeout=60) == 141 and err == ""


def test_a_counterbalanced_pilot_has_the_order_columns_and_the_order_table(tmp_path: Path) -> None:
    """Two scenarios as counterbalanced blocks, random assignment, the neutral practice: `plan` states
    the design, each participant's blocks come in their own order, and the report's tables carry
    the order columns (long and wide alike) and order_effects.csv."""
    path = study_file(tmp_path, scenarios=["hallway", "shared_room"], participants=2, practice={},
                      assignment={"policy": "random", "seed": 1}, questionnaires=[])  # fmt: skip
    plan = haven("study", "plan", str(path), cwd=tmp_path)
    assert plan.returncode == 0, plan.stderr
    assert (
        "2 sequences" in plan.stdout
        and "2 participant(s) complete it" in plan.stdout
        and "Assignment: random (seed 1)" in plan.stdout
    )
    assert "practice1-practice-none" in plan.stdout and "note:" not in plan.stdout
    assert (
        "sequence 1: blocks hallway, shared_room" in plan.stdout
        and "sequence 2: blocks shared_room, hallway" in plan.stdout
    )
    for p in ("p01", "p02"):
        r = haven("study", "run", str(path), "--participant", p, "--batch", "--dir", str(tmp_path / "d"), cwd=tmp_path)
        assert r.returncode == 0, r.stderr
    report = haven("study", "report", str(path), "--dir", str(tmp_path / "d"), cwd=tmp_path)
    assert report.returncode == 0 and "order_effects.csv" in report.stdout, report.stderr
    out = tmp_path / "d" / "report"
    with (out / "study_wide.csv").open() as f:
        wide = list(csv.DictReader(f))
    with (out / "study_long.csv").open() as f:
        long = list(csv.DictReader(f))
    order = ["sequence", "order_position", "block", "position_in_block", "previous_condition"]
    assert all(c in wide[0] and c in long[0] for c in order)
    trials = {(w["participant"], int(w["order_position"])): w for w in wide}
    assert len(trials) == 10
    first_block = {p: trials[(p, 2)]["scenario"] for p in ("p01", "p02")}
    assert sorted(first_block.values()) == ["hallway", "shared_room"]  # one each: the blocks are counterbalanced
    assert {trials[(p, 1)]["scenario"] for p in ("p01", "p02")} == {"practice"}
    for (p, position), w in trials.items():
        if w["practice"] == "True":
            assert (w["block"], w["condition"], w["previous_condition"]) == ("0", "none", "")
            continue
        assert w["block"] == ("1" if w["scenario"] == first_block[p] else "2")
        assert int(w["position_in_block"]) == (position - 2) % 2 + 1
        before = trials[(p, position - 1)]
        assert w["previous_condition"] == (before["condition"] if w["position_in_block"] == "2" else "")
    for row in long:  # the long table repeats the trial's design on every measure
        w = trials[(row["participant"], int(row["order_position"]))]
        assert all(row[c] == w[c] for c in order)
    recorded = json.loads(next((tmp_path / "d" / "p02").glob("03_*/*/session.json")).read_text())["study"]
    assert (recorded["block"], recorded["position_in_block"], recorded["previous_condition"]) == (
        1,
        2,
        trials[("p02", 2)]["condition"],
    )
    with (out / "order_effects.csv").open() as f:
        effects = list(csv.DictReader(f))
    blocks = {
        (r["scenario"], r["level"])
        for r in effects
        if r["factor"] == "block" and r["measure"] == "min_human_centre_distance_m"
    }
    assert blocks == {("hallway", "1"), ("hallway", "2"), ("shared_room", "1"), ("shared_room", "2")}
    assert {r["level"] for r in effects if r["factor"] == "previous_condition" and r["condition"] == "all"} <= {
        "(first)",
        "none",
    }
