"""`haven study plan | run | status | report`: a whole study from one study file (study/protocol.py)."""

from __future__ import annotations

import argparse
import os
from dataclasses import fields
from pathlib import Path

from haven_scenarios.record.participants import PARTICIPANTS_CSV
from haven_scenarios.record.progress import TrialProgress, differences, progress, stored
from haven_scenarios.record.study_report import write_report
from haven_scenarios.study.names import study_dir
from haven_scenarios.study.protocol import Study, StudyError, load_study, study_names
from haven_scenarios.study.schedule import (
    PlannedTrial,
    design_note,
    participant_schedule,
    practice_note,
    schedule,
    sequence_orders,
    trials_per_participant,
)
from haven_scenarios.tools.commands import power as power_step
from haven_scenarios.tools.commands.common import (
    PORT,
    add_dropout_options,
    add_ros_options,
    add_tls_options,
    existing_file,
    fail,
    table,
)
from haven_scenarios.web.online_runner import NEXT_URL_ENV
from haven_sim.runtime.process import interrupted, on_stop_signals

SHOWN_SEQUENCES = 24  # `plan` lists the design's sequences up to this many


def add(sub: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    study = sub.add_parser(
        "study", help="a whole study from a study file: plan, run a participant's trials, status, report, power"
    )
    steps = study.add_subparsers(dest="step", required=True)
    spec = f"a study file, or a shipped study ({', '.join(study_names())})"
    plan = steps.add_parser("plan", help="print the schedule: every participant's trials in order")
    plan.add_argument("study", help=spec)
    plan.add_argument("--participant", default=None, help="only this participant's trials")
    plan.set_defaults(func=plan_cmd)
    run = steps.add_parser(
        "run", help="run a participant's trials in order (resumable: a finished trial never runs twice)"
    )
    run.add_argument("study", help=spec)
    run.add_argument("--participant", required=True, help="the participant's id (one of the study's)")
    run.add_argument(
        "--batch",
        action="store_true",
        help="simulated participants in this process without ROS: a quick pilot (no bag)",
    )
    run.add_argument(
        "--web",
        action="store_true",
        help="the participant plays in the browser (haven run --web --teleop), questionnaires after each trial",
    )
    run.add_argument("--host", default="127.0.0.1", help="with --web: address the pages are served on")
    run.add_argument("--port", type=PORT, default=8088, help="with --web: port of the pages")
    add_tls_options(run)
    add_dropout_options(run)
    run.add_argument(
        "--next-url",
        default=os.environ.get(NEXT_URL_ENV),
        metavar="URL",
        help=(
            "with --web: the participant's browser goes here after each "
            f"page (default: ${NEXT_URL_ENV}, where haven serve puts it)"
        ),
    )
    run.add_argument(
        "--teleop",
        nargs="*",
        default=None,
        metavar="HUMAN",
        help="these humans (default: all) are driven by the participant",
    )
    run.add_argument("--no-pause", action="store_true", help="with a person: do not wait for Enter between trials")
    run.add_argument("--params-file", type=existing_file, default=None, help="ROS parameter YAML for every trial")
    run.add_argument(
        "--replan",
        action="store_true",
        help="accept a study file changed since the first run (its new schedule is stored)",
    )
    add_ros_options(run, suite=True)
    status = steps.add_parser("status", help="per participant: trials done, failed, and what comes next")
    status.add_argument("study", help=spec)
    report = steps.add_parser(
        "report",
        help="tidy long CSV, wide CSV, codebook, summary.csv, summary.png, order_effects.csv and mixed_models.csv",
    )
    report.add_argument("study", help=spec)
    report.add_argument("--out", type=Path, default=None, help="folder for the report (default: <study dir>/report)")
    power = power_step.add(steps, spec)
    for p in (plan, run, status, report, power):
        p.add_argument("--dir", type=Path, default=None, help="the study's folder (default: studies/<study name> here)")
    run.set_defaults(func=_run)
    status.set_defaults(func=status_cmd)
    report.set_defaults(func=report_cmd)


def _run(args: argparse.Namespace) -> int:
    """Every stop signal is a Ctrl-C here (`interrupted`), between trials too: the command ends
    within a moment, its files whole, exit code 130 (a recorded trial installs its own handlers
    while it runs, which stop its nodes in order)."""
    from haven_scenarios.conduct.recorded_trial import TrialError  # (the runner loads only for this command)
    from haven_scenarios.conduct.study_run import StudyRun, run_participant

    values = {f.name: getattr(args, f.name) for f in fields(StudyRun)}
    values["teleop"] = tuple(args.teleop) if args.teleop is not None else None
    try:
        with on_stop_signals(interrupted):
            return run_participant(StudyRun(**values))
    except TrialError as e:
        return fail(str(e))


def plan_rows(trials: list[PlannedTrial]) -> list[list[str]]:
    head = [
        "participant",
        "sequence",
        "position",
        "block",
        "in block",
        "trial id",
        "scenario",
        "condition",
        "after",
        "seed",
        "practice",
    ]
    rows = [
        [
            t.participant,
            str(t.sequence),
            str(t.position),
            str(t.block) if t.block else "-",
            str(t.position_in_block),
            t.trial_id,
            t.scenario,
            t.condition,
            t.previous_condition or "-",
            str(t.seed),
            "yes" if t.practice else "",
        ]
        for t in trials
    ]
    if any(t.robot_name for t in trials):  # (the robot as a design factor: after the condition)
        head.insert(8, "robot")
        for row, t in zip(rows, trials, strict=True):
            row.insert(8, t.robot_name or "-")
    return [head, *rows]


def plan_cmd(args: argparse.Namespace) -> int:
    try:
        study = load_study(args.study)
    except StudyError as e:
        return fail(str(e))
    if args.participant is not None and args.participant not in study.participants:
        return fail(
            f"--participant: {args.participant!r} is not a participant of study {study.name} ({_listing(study)})"
        )
    trials = participant_schedule(study, args.participant) if args.participant else schedule(study)
    print(
        f"study {study.name}: {len(study.participants)} participant(s) x {trials_per_participant(study)} trial(s) "
        f"({len(study.practice)} practice); {len(study.scenarios)} scenario(s) x {len(study.conditions)} condition(s) "
        f"x {study.repetitions} repetition(s)"
    )
    print(
        f"order: {design_note(study)} Each scenario is one block; "
        "every block shows the conditions in the participant's order."
    )
    shown = sequence_orders(study)
    for s, (scenarios, conditions) in enumerate(shown[:SHOWN_SEQUENCES], 1):
        print(f"sequence {s}: blocks {', '.join(scenarios)}; conditions {', '.join(conditions)}")
    if len(shown) > SHOWN_SEQUENCES:
        print(f"... and {len(shown) - SHOWN_SEQUENCES} more sequences (the schedule below has each participant's)")
    carry = practice_note(study)
    if carry:
        print(f"warning: {carry}")
    print(
        f"seeds: {study.seed_policy}, base {study.seed_base}; questionnaires after each trial: {_questionnaires(study)}"
    )
    if inst := study.instruments():
        before, after = (", ".join(q.name for q in qs) or "none" for qs in (inst.first, inst.after))
        print(f"before the first trial: {before}; after the last: {after} (once per participant)")
    print(table(plan_rows(trials)))
    return 0


def _listing(study: Study) -> str:
    ids = study.participants
    return ", ".join(ids) if len(ids) <= 6 else f"{ids[0]} .. {ids[-1]}"


def _questionnaires(study: Study) -> str:
    return ", ".join(q if isinstance(q, str) else str(q.get("name")) for q in study.questionnaires) or "none"


def _load(args: argparse.Namespace) -> tuple[Study, Path, list[TrialProgress]]:
    """The study, its folder and every trial's progress (StudyError, one line, if unreadable)."""
    study = load_study(args.study)
    root = study_dir(args.dir, study)
    return study, root, progress(root, schedule(study))


def status_cmd(args: argparse.Namespace) -> int:
    try:
        study, root, done = _load(args)
        old = stored(root)
    except StudyError as e:
        return fail(str(e))
    if old is None:
        print(f"study {study.name}: not started in {root}")
    else:
        changed = differences(old["study"], study.describe())
        note = (
            f" (the study file changed since the first run: {', '.join(changed)}; `study run` needs --replan)"
            if changed
            else ""
        )
        print(f"study {study.name} in {root}{note}")
    rows = [["participant", "done", "failed", "next"]]
    for p in study.participants:
        mine = [t for t in done if t.trial.participant == p]
        failed = [t for t in mine if t.status == "failed"]
        following = next((t for t in mine if t.status != "done"), None)
        rows.append(
            [
                p,
                f"{sum(t.status == 'done' for t in mine)}/{len(mine)}",
                ", ".join(_failed(t) for t in failed) or "-",
                _next(following),
            ]
        )
    print(table(rows))
    total = sum(t.status == "done" for t in done)
    print(f"{total}/{len(done)} trials done")
    return 0


def _failed(t: TrialProgress) -> str:
    last = t.attempts[-1].outcome
    return f"{t.trial.folder} ({len(t.attempts)} attempt(s), last: {last[:60]})"


def _next(t: TrialProgress | None) -> str:
    if t is None:
        return "- (all done)"
    tr = t.trial
    return f"{tr.folder}: {tr.scenario}, {tr.condition}, seed {tr.seed}" + (", practice" if tr.practice else "")


def report_cmd(args: argparse.Namespace) -> int:
    try:
        study = load_study(args.study)
        root = study_dir(args.dir, study)
        report = write_report(study, root, args.out)
    except (StudyError, ValueError) as e:
        return fail(str(e))
    out = report.folder
    print(f"haven: study {study.name}: {report.trials_done}/{report.trials} trials done; {report.counts}")
    picture = f", {report.picture}" if report.picture else " (no measures to draw)"
    print(
        f"haven: wrote {out / 'study_long.csv'}, codebook.csv (and .json), "
        f"study_wide.csv, summary.csv, order_effects.csv{picture}"
    )
    if report.participants:
        print(f"haven: wrote {out / PARTICIPANTS_CSV}: {report.participants}")
    singular, unconverged, fitted = report.models
    model = "value ~ condition (+ position) + (1 | participant)"
    counted = f"{fitted} fitted, {singular} singular, {unconverged} not converged"
    print(f"haven: mixed models ({model}) per scenario and measure in mixed_models.csv: {counted}")
    if report.study_changed:
        print(f"haven: note: the study file changed since the first run in {root}")
    return 0
