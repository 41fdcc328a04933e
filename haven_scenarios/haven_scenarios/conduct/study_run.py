"""`haven study run`: one participant's trials in order, each into its own trial folder.

Each trial is a recorded trial as `haven run` makes it (conduct/recorded_trial.py, called here: its
nodes are this process's children; with `--web` the participant plays in the browser and answers
the study's questionnaires after it), or with `--batch` a batch trial. A stop signal (Ctrl-C) ends
the current trial cleanly (its session folder says "interrupted") and stops the study; the nodes
die with this process however it ends. A trial that does not finish stops the study: the same
command later runs it again.
One runner works on a participant at a time (an OS lock on their folder, which a crash releases):
a second `haven study run` for them says who holds it and exits.
"""

from __future__ import annotations

import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from haven_scenarios.conduct.instruments import ask_in_browser, order_key, run_instruments, say_declined, terminal_asker
from haven_scenarios.conduct.recorded_trial import (
    RosOptions,
    TrialError,
    TrialRequest,
    WebRequest,
    plan_trial,
    record_trial,
    tell,
)
from haven_scenarios.record.participants import InstrumentBook
from haven_scenarios.record.progress import TrialProgress, attempts, bind, progress, questionnaire_specs, trial_dir
from haven_scenarios.run.domains import DomainRange
from haven_scenarios.run.locks import FileLock, Locked
from haven_scenarios.run.session_batch import run_batch_session
from haven_scenarios.run.suite import TRIAL_SETS, load_suite_config
from haven_scenarios.study.names import study_dir
from haven_scenarios.study.participants import in_session
from haven_scenarios.study.presence import DEFAULT_RECONNECT_TIMEOUT_S, OnDisconnect
from haven_scenarios.study.protocol import Study, StudyError, load_study
from haven_scenarios.study.questionnaires import Questionnaire
from haven_scenarios.study.scenario import ScenarioError, load_scenario
from haven_scenarios.study.schedule import PlannedTrial
from haven_sim.common.params import ParamsError
from haven_sim.robots.robot_kind import resolve_robot
from haven_sim.runtime.process import interrupted, on_stop_signals

INTERRUPTED = 130
RUNNER_LOCK = ".runner.lock"  # in the participant's folder, held while a `haven study run` works on it


@dataclass(frozen=True)
class StudyRun:
    """One participant's run of a study (`haven study run`'s options; the Python API's arguments)."""

    study: str  # a study file or a shipped study's name
    participant: str
    dir: Path | None = None  # the study's folder (default: studies/<name>)
    replan: bool = False  # accept a study file changed since the first run
    batch: bool = False  # simulated participants in this process without ROS (no bag)
    web: bool = False  # the participant plays in the browser, questionnaires after each trial
    host: str = "127.0.0.1"
    port: int = 8088
    tls_cert: str | None = None  # with tls_key: the pages over HTTPS
    tls_key: str | None = None
    on_disconnect: str = OnDisconnect.KEEP.value  # a participant's drop-out during a trial: keep | pause | abort
    reconnect_timeout: float = DEFAULT_RECONNECT_TIMEOUT_S  # with pause: abort after this long away
    next_url: str | None = None  # with web: the participant's browser goes here after each page (`haven serve`)
    teleop: tuple[str, ...] | None = None  # these humans (() for all) are driven by the participant
    no_pause: bool = True  # with a person: do not wait for Enter between trials
    params_file: str | None = None
    domain_id: int | None = None
    domains: DomainRange | None = None  # the lab's ROS domains (None: $HAVEN_DOMAINS, if set)
    network: bool = False


def study_extra(study: str, trial: PlannedTrial) -> dict[str, Any]:
    """What session.json records of the trial's place in the study: its design, order columns included."""
    keys = (
        "trial_id",
        "position",
        "condition",
        "practice",
        "sequence",
        "block",
        "position_in_block",
        "previous_condition",
    )
    return {"study": {"name": study, **{k: getattr(trial, k) for k in keys}}}


def person_of(study: Study, trial: PlannedTrial) -> tuple[int, int]:
    """(person seed, position) of the trial's simulated participant: the same people for all of a
    participant's trials, whatever the seed policy, new ones with another seed base."""
    return study.seed_base + study.participants.index(trial.participant), trial.position


def trial_request(
    args: StudyRun, trial: PlannedTrial, questionnaires: list[str], study: Study | None = None
) -> TrialRequest:
    """The recorded trial for one trial of the schedule (`study`: for session.json, and who the
    simulated participant is)."""
    web = None
    if args.web:
        tls = (args.tls_cert or "", args.tls_key or "")
        web = WebRequest(
            args.host, args.port, False, True, *tls, args.on_disconnect, args.reconnect_timeout, args.next_url or ""
        )
    teleop = tuple(args.teleop or ()) if args.web or args.teleop is not None else None
    return TrialRequest(
        trial.scenario_spec,
        trial.participant,
        tuple(trial.cues),
        trial.seed,
        params_file=str(Path(args.params_file).resolve()) if args.params_file else None,
        teleop=teleop,
        web=web,
        questionnaires=tuple(questionnaires) if args.web else (),
        extra=study_extra(study.name, trial) if study else {},
        person=person_of(study, trial) if study else None,
        robot=trial.robot or None,
    )


def run_recorded_trial(
    args: StudyRun, trial: PlannedTrial, sessions: Path, questionnaires: list[str], study: Study
) -> bool:
    """The trial with the whole node suite; True if a stop signal (Ctrl-C) cut it short."""
    try:
        plan = plan_trial(trial_request(args, trial, questionnaires, study))
        result = record_trial(plan, sessions, RosOptions(args.domain_id, args.network, args.domains))
    except TrialError as e:
        print(f"haven: error: {e}", file=sys.stderr)
        return False
    tell(result)
    return result.stopped


def run_batch_trial(args: StudyRun, trial: PlannedTrial, sessions: Path, study: Study) -> bool:
    """The trial in this process; True if a stop signal (Ctrl-C, SIGTERM, ...) cut it short: its
    session then says "interrupted" (run/session_batch.py), and the same command runs it again.
    Every stop signal raises KeyboardInterrupt at once, a BaseException that no plugin's containment
    (`except Exception`) swallows, also a SIGINT the shell had ignored (a background job)."""
    try:
        with on_stop_signals(interrupted):
            batch_session(trial, sessions, study, args.params_file)
    except KeyboardInterrupt:
        return True
    return False


def batch_session(trial: PlannedTrial, sessions: Path, study: Study, params_file: str | None) -> None:
    """The trial as a batch session under `sessions` (`--batch`; `haven study power` runs its pool so)."""
    scenario = load_scenario(trial.scenario_spec)
    if trial.robot:  # (the study's robot factor; otherwise the scenario's own)
        scenario = scenario.for_robot(resolve_robot(trial.robot), trial.robot)
    scenario = in_session(scenario, *person_of(study, trial))
    extra = study_extra(study.name, trial)
    run_batch_session(
        scenario, trial.participant, trial.cues, trial.seed, sessions, extra, load_suite_config(params_file, TRIAL_SETS)
    )


def describe(trial: PlannedTrial, total: int) -> str:
    practice = " (practice)" if trial.practice else ""
    cues = " ".join(trial.cues)
    return (
        f"trial {trial.position}/{total} {trial.trial_id}{practice}: "
        f"{trial.scenario}, condition {trial.condition} ({cues}), seed {trial.seed}"
    )


def wait_for_enter(args: StudyRun, person: bool) -> None:
    """With a person, between trials: until the researcher presses Enter (not with --no-pause, or
    when nobody is at the terminal)."""
    if person and not args.no_pause and sys.stdin.isatty():
        input("haven study: press Enter to start it (Ctrl-C stops the study here; it resumes from this trial) ")


def _check(args: StudyRun, study: Study) -> str | None:
    """What is wrong with the command line for this study, if anything."""
    if args.participant not in study.participants:
        shown = ", ".join(study.participants[:6]) + (" .." if len(study.participants) > 6 else "")
        return f"--participant: {args.participant!r} is not a participant of study {study.name} ({shown})"
    if args.batch and (args.web or args.teleop is not None):
        return "--batch runs simulated participants in this process: not with --web or --teleop"
    if args.batch:
        for s in sorted({s.spec for s in study.scenarios} | {p.scenario.spec for p in study.practice}):
            if any(h.teleoperated for h in load_scenario(s).humans):
                return f"--batch: scenario {s} has a teleoperated participant (run it without --batch)"
    return None


def run_participant(args: StudyRun) -> int:
    """Run the participant's trials that are not done yet, in order; the exit code (0: all done,
    1: a trial did not finish, 130: stopped). TrialError (one line) when the run is refused: the
    study, the participant, the options, or another runner on the participant."""
    try:
        study = load_study(args.study)
        load_suite_config(args.params_file, TRIAL_SETS)  # (each trial reads it: refused now, not at the first)
        problem = _check(args, study)
        if problem:
            raise TrialError(problem)
        root = study_dir(args.dir, study)
        trials = [t for t in bind(study, root, args.replan) if t.participant == args.participant]
        questionnaires = questionnaire_specs(study, root) if args.web else []
    except (StudyError, ScenarioError, ParamsError) as e:
        raise TrialError(str(e)) from None
    except OSError as e:
        raise TrialError(f"cannot write the study's folder: {e.strerror or e}") from None
    try:  # one runner per participant: a second one would run the same trials again
        lock = FileLock(root / args.participant / RUNNER_LOCK).acquire()
    except Locked as e:
        who = e.holder.describe()
        raise TrialError(
            f"participant {args.participant} of study {study.name} is already "
            f"being run ({who}); wait for it to end or stop it"
        ) from None
    except OSError as e:
        raise TrialError(f"cannot lock {root / args.participant}: {e.strerror or e}") from None
    with lock:
        code = _instruments(args, study, root, study.instruments().first, True)
        if code is None:
            code = _run_trials(args, study, root, trials, questionnaires)
        if code == 0:
            code = _instruments(args, study, root, study.instruments().after, False) or 0
        return code


def _instruments(args: StudyRun, study: Study, root: Path, qs: tuple[Questionnaire, ...], first: bool) -> int | None:
    """The study-level instruments still pending for the participant (study_instruments.py): None to
    go on, else the exit code (0: they declined consent, so no trial; 130: stopped while asking)."""
    book = InstrumentBook(root, args.participant)
    if book.declined():
        say_declined(args.participant, book.path)
        return 0
    if not book.pending(qs):
        return None
    asker = None if args.batch else terminal_asker()
    key = order_key(study.name, args.participant)
    try:
        agreed = ask_in_browser(book, qs, key, args, first) if args.web else run_instruments(book, qs, key, asker)
        if not agreed:
            say_declined(args.participant, book.path)
            return 0
    except ValueError as e:
        raise TrialError(str(e)) from None
    except EOFError:
        print(
            f"\nhaven study: no answers for {args.participant} at the terminal "
            "(its input is closed): run it at a terminal, or with --web",
            file=sys.stderr,
        )
        return INTERRUPTED
    except KeyboardInterrupt:
        print(
            f"\nhaven study: stopped while asking {args.participant}; the same command asks what is missing",
            file=sys.stderr,
        )
        return INTERRUPTED
    return None


def _run_trials(args: StudyRun, study: Study, root: Path, trials: list[PlannedTrial], questionnaires: list[str]) -> int:
    todo = [t for t in progress(root, trials) if t.status != "done"]
    done = len(trials) - len(todo)
    print(
        f"haven study: {study.name}, participant {args.participant}: "
        f"{done}/{len(trials)} trials done; folder {root / args.participant}",
        flush=True,
    )
    person = args.web or args.teleop is not None
    asked = [q.name for q in (*study.resolved_questionnaires(), *study.instruments().first, *study.instruments().after)]
    if args.batch and todo and asked:
        print(
            "haven study: --batch: simulated participants answer "
            f"nothing ({', '.join(asked)} not asked; nothing is invented)",
            flush=True,
        )
    for p in todo:
        code = _one(args, study, p, len(trials), root, questionnaires, person)
        if code:
            return code
    where = f" --dir {args.dir}" if args.dir is not None else ""
    print(
        f"haven study: participant {args.participant}: all {len(trials)} "
        f"trials done (`haven study report {args.study}{where}` for the tables)"
    )
    return 0


def _one(
    args: StudyRun, study: Study, p: TrialProgress, total: int, root: Path, questionnaires: list[str], person: bool
) -> int:
    """Run one trial; 0 when it finished, else the study's exit code (and why, said)."""
    trial = p.trial
    again = f" (again: {len(p.attempts)} attempt(s) did not finish)" if p.attempts else ""
    print(f"haven study: next: {describe(trial, total)}{again}", flush=True)
    try:
        wait_for_enter(args, person)
    except (KeyboardInterrupt, EOFError):
        print(f"\nhaven study: stopped before {trial.folder}; the same command goes on from it", file=sys.stderr)
        return INTERRUPTED
    sessions = trial_dir(root, trial)
    try:
        stopped = (
            run_batch_trial(args, trial, sessions, study)
            if args.batch
            else run_recorded_trial(args, trial, sessions, questionnaires, study)
        )
    except KeyboardInterrupt:
        stopped = True
    except (OSError, ValueError) as e:
        print(f"haven: error: {trial.folder}: {e}", file=sys.stderr)
        return 1
    made = attempts(sessions, trial)
    if made and made[-1].finished:
        print(f"haven study: {trial.folder}: {made[-1].outcome} -> {made[-1].folder}", flush=True)
        if not stopped:
            return 0
    if stopped:
        print(
            f"haven study: stopped during {trial.folder}; the same command goes on from the first trial not finished",
            file=sys.stderr,
        )
        return INTERRUPTED
    outcome = made[-1].outcome if made else "no session folder was made"
    print(
        f"haven study: {trial.folder} did not finish ({outcome}); the study stops here: the same command runs it again",
        file=sys.stderr,
    )
    return 1
