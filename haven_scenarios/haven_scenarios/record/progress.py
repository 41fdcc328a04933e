"""A study's folder: its stored schedule, and how far each participant has got.

    studies/<name>/
        study.json                      the study as first run, who takes which sequence and the
                                        whole schedule (a changed study file is refused against it)
        questionnaires/<name>.yaml      the study's own Likert questionnaires, as `haven run` takes them
        <participant>/<NN>_<trial id>/  one trial: each attempt a session folder inside
            <scenario>_<participant>_<time>/   session.json, metrics.json, events.jsonl, ...

A trial is done when one of its attempts has a finished outcome (the trial ended: completed,
timeout, contact, battery_empty, stopped by the researcher, or plugin_failed: a plugin's code
failed, the trial is not valid with the reason and the study goes on, as a sweep does) and ran as the schedule says
(scenario, cues and seed, as its session.json records them), and is never run again; an attempt
that was interrupted, cut short, or aborted by the researcher is kept, and the trial runs again; so
is a finished attempt that ran otherwise (the study was re-planned with another seed or condition
since): the table never labels a session with what it did not run.
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

from haven_scenarios.record.session import SESSION_FILE, session_info, write_json
from haven_scenarios.study.conditions import condition_name, parse_condition
from haven_scenarios.study.protocol import Study, StudyError
from haven_scenarios.study.rules import EndReason
from haven_scenarios.study.schedule import PlannedTrial, assignment, schedule
from haven_sim.common import atomic

STORED = "study.json"
FINISHED = (
    EndReason.COMPLETED,
    EndReason.TIMEOUT,
    EndReason.CONTACT,
    EndReason.BATTERY_EMPTY,
    EndReason.STOPPED,
    EndReason.PLUGIN_FAILED,
)


def finished(outcome: Any) -> bool:
    """Whether session.json's `outcome` says the trial ended (notes such as a repaired bag may follow ';')."""
    return isinstance(outcome, str) and outcome.split(";")[0].strip() in {str(r) for r in FINISHED}


@dataclass(frozen=True)
class Attempt:
    folder: Path
    outcome: str

    @property
    def finished(self) -> bool:
        return finished(self.outcome)


@dataclass(frozen=True)
class TrialProgress:
    trial: PlannedTrial
    attempts: tuple[Attempt, ...]

    @property
    def session(self) -> Path | None:
        """The finished attempt's session folder (the first, should there be two)."""
        return next((a.folder for a in self.attempts if a.finished), None)

    @property
    def status(self) -> str:
        """done, failed (attempts, none finished) or to run."""
        return "done" if self.session is not None else ("failed" if self.attempts else "to run")


def trial_dir(root: Path, trial: PlannedTrial) -> Path:
    return root / trial.participant / trial.folder


def ran_otherwise(info: dict[str, Any], trial: PlannedTrial) -> str | None:
    """How a session ran other than the trial is planned (scenario, condition, seed, the study's
    robot), if it did."""
    ran = (info.get("scenario"), info.get("condition"), info.get("seed"))
    planned = (trial.scenario, condition_name(parse_condition(trial.cues)), trial.seed)
    if trial.robot_name and info.get("robot_name") != trial.robot_name:
        return (
            f"ran with robot {info.get('robot_name') or 'turtlebot2'}; the schedule now says robot {trial.robot_name}"
        )
    if ran == planned:
        return None
    return (
        f"ran as {ran[0]}, condition {ran[1]}, seed {ran[2]}; the schedule "
        f"now says {planned[0]}, condition {planned[1]}, seed {planned[2]}"
    )


def attempts(folder: Path, trial: PlannedTrial) -> tuple[Attempt, ...]:
    """The session folders in a trial's folder, oldest first (their names end in the start time);
    a finished one that ran other than `trial` is planned does not count as finished."""
    if not folder.is_dir():
        return ()
    out = []
    for session in sorted(p for p in folder.iterdir() if p.is_dir()):
        if (session / SESSION_FILE).exists() or (session / "bag").is_dir():
            info = session_info(session)
            outcome = str(info.get("outcome", "unknown: no readable session.json"))
            otherwise = ran_otherwise(info, trial) if finished(outcome) else None
            out.append(Attempt(session, f"replanned: {otherwise}" if otherwise else outcome))
    return tuple(out)


def progress(root: Path, trials: Sequence[PlannedTrial]) -> list[TrialProgress]:
    return [TrialProgress(t, attempts(trial_dir(root, t), t)) for t in trials]


def stored(root: Path) -> dict[str, Any] | None:
    path = root / STORED
    if not path.exists():
        return None
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as e:
        raise StudyError(
            f"{path}: unreadable ({str(e)[:80]}); move it away to start the study's folder afresh"
        ) from None
    if (
        not isinstance(data, dict)
        or not isinstance(data.get("study"), dict)
        or not isinstance(data.get("schedule"), list)
    ):
        raise StudyError(f"{path}: not a study record of haven; move it away to start the study's folder afresh")
    return data


# What a study recorded before a key existed did: scenario blocks in the file's order, participants
# by id (a study folder from then compares as that, so a file now counterbalancing blocks is a change).
BEFORE_KEYS = {"blocks": "none", "assignment": {"policy": "by_id"}}


def differences(old: dict[str, Any], new: dict[str, Any]) -> list[str]:
    """The keys of `describe()` that differ between a stored study and the file's."""
    old = {**BEFORE_KEYS, **old}
    return [k for k in sorted(set(old) | set(new)) if old.get(k) != new.get(k)]


def bind(study: Study, root: Path, replan: bool = False) -> list[PlannedTrial]:
    """The study's schedule, stored in `root` on first use; a study file changed since then is
    refused (StudyError, one line) unless `replan` (then the new schedule is stored; trials done
    keep their folders, and one stays done if it ran as the new schedule says: see `attempts`)."""
    trials = schedule(study)
    record: dict[str, Any] = {
        "study": study.describe(),
        "source": study.source,
        "assignment": assignment(study),  # participant -> sequence (1..), as `assignment` in the file made it
        "schedule": [t.to_json() for t in trials],
    }
    old = stored(root)
    if old is not None and not replan:
        changed = differences(old["study"], record["study"])
        if changed:
            raise StudyError(
                f"{study.source}: the study changed since its first run in {root} "
                f"({', '.join(changed)} differ from {root / STORED}); run it with "
                "--replan to go on with the new schedule, or --dir for a new study folder"
            )
    if old is None or replan:
        root.mkdir(parents=True, exist_ok=True)
        write_json(root / STORED, record)
    return trials


def questionnaire_specs(study: Study, root: Path) -> list[str]:
    """What `haven run --questionnaire` is given: built-in names, and the study's Likert mappings
    as YAML files written into `root`/questionnaires."""
    out = []
    for spec in study.questionnaires:
        if isinstance(spec, str):
            out.append(spec)
            continue
        path = root / "questionnaires" / f"{spec['name']}.yaml"
        path.parent.mkdir(parents=True, exist_ok=True)
        atomic.write_text(path, yaml.safe_dump(spec, sort_keys=False, allow_unicode=True))
        out.append(str(path.resolve()))
    return out
