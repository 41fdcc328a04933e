"""The simulated pool behind `haven study power`: its participants' batch trials (in worker
processes or on a Dask cluster), the orders they take, and the measure asked for."""

from __future__ import annotations

import difflib
import sys
from dataclasses import dataclass, replace
from pathlib import Path

from haven_scenarios.conduct.study_run import batch_session
from haven_scenarios.record import metric_table
from haven_scenarios.record.power import Order
from haven_scenarios.record.progress import attempts, bind, progress, trial_dir
from haven_scenarios.record.study_table import TrialResults, trial_results
from haven_scenarios.run.sweep import cores, farm
from haven_scenarios.study.protocol import Study, load_study
from haven_scenarios.study.questionnaires import codebook_rows
from haven_scenarios.study.scenario import load_scenario
from haven_scenarios.study.schedule import PlannedTrial, participant_schedule


@dataclass(frozen=True)
class PoolJob:
    """One pool participant's trials (a picklable task for a worker process or Dask)."""

    study: str  # the study file (its source)
    size: int
    participant: str
    root: Path
    params_file: str | None
    scenario: str | None = None  # only this scenario's trials (practice left out too); None: every trial


def wanted(trial: PlannedTrial, scenario: str | None) -> bool:
    """Whether the pool needs this trial: all of them, or with --scenario that scenario's study trials."""
    return scenario is None or (trial.scenario == scenario and not trial.practice)


def with_participants(study: Study, n: int) -> Study:
    return replace(study, participants=tuple(f"p{k:02d}" for k in range(1, n + 1)))


def pool_study(study: Study, n: int) -> Study:
    """The study the pool runs: n participants taking the sequences in turn, whatever the study's
    assignment, so every condition order is in a pool at least as large as their count."""
    return replace(with_participants(study, n), assignment="by_id")


def simulate_participant(job: PoolJob) -> tuple[str, int, str]:
    """Run the pool participant's trials not done yet; (participant, trials run, what went wrong)."""
    study = pool_study(load_study(job.study), job.size)
    ran = 0
    for p in progress(job.root, participant_schedule(study, job.participant)):
        if p.status == "done" or not wanted(p.trial, job.scenario):
            continue
        sessions = trial_dir(job.root, p.trial)
        batch_session(p.trial, sessions, study, job.params_file)
        ran += 1
        made = attempts(sessions, p.trial)
        if not (made and made[-1].finished):
            return (
                job.participant,
                ran,
                f"{p.trial.folder} did not finish ({made[-1].outcome if made else 'no session'})",
            )
    return job.participant, ran, ""


def simulate_pool(
    study: Study,
    size: int,
    root: Path,
    scenario: str | None,
    params_file: str | None,
    workers: int | None,
    cluster: str | None,
) -> tuple[list[TrialResults], int]:
    """The pool's trial results (simulating what is not there yet: `scenario`'s trials only, if
    given; on `workers` processes, or a Dask `cluster`) and how many trials ran now."""
    pool = pool_study(study, size)
    for s in sorted({s.spec for s in pool.scenarios} | {p.scenario.spec for p in pool.practice}):
        if any(h.teleoperated for h in load_scenario(s).humans):
            raise ValueError(f"scenario {s} has a teleoperated participant: the pool needs simulated ones")
    trials = bind(pool, root, replan=True)
    if scenario is not None and scenario not in [s.name for s in study.scenarios]:
        raise ValueError(
            f"--scenario: {scenario!r} is not a scenario of study "
            f"{study.name} ({', '.join(s.name for s in study.scenarios)})"
        )
    todo = sorted(
        {p.trial.participant for p in progress(root, trials) if p.status != "done" and wanted(p.trial, scenario)}
    )
    params = str(Path(params_file).resolve()) if params_file else None
    jobs = [PoolJob(study.source, size, p, root, params, scenario) for p in todo]
    workers = workers or cores()
    ran = 0
    if jobs:
        print(
            f"haven study power: simulating {len(jobs)} pool "
            f"participant(s) on {cluster or f'{min(workers, len(jobs))} process(es)'}",
            flush=True,
        )
    for participant, n, problem in farm(jobs, simulate_participant, workers, cluster):
        ran += n
        if problem:
            raise ValueError(f"pool participant {participant}: {problem}")
        print(f"haven study power: pool participant {participant} done ({n} trial(s) run)", file=sys.stderr, flush=True)
    results = [r for r in (trial_results(t) for t in progress(root, trials)) if r is not None]
    return results, ran


def orders(study: Study, n: int, scenario: str) -> list[Order]:
    """The condition orders the study gives n participants in one scenario (practice left out)."""
    s = with_participants(study, n)
    return [
        tuple(t.condition for t in participant_schedule(s, p) if t.scenario == scenario and not t.practice)
        for p in s.participants
    ]


def measured_per_person(results: list[TrialResults], metric: str) -> bool:
    kinds = {bool(m.human) for r in results for m in r.measures if m.measure == metric}
    if not kinds:
        names = sorted({m.measure for r in results for m in r.measures})
        raise ValueError(
            f"--metric: no measure {metric!r} in the pool's trials (some there are: {', '.join(names[:12])} ...)"
        )
    return False not in kinds  # (a trial-level measure wins over a per-person one of the same name)


def check_metric(metric: str, study: Study) -> None:
    """ValueError (one line) for a --metric no simulated trial has, before any trial is simulated."""
    names = {r[0] for r in metric_table.rows()}
    if metric in names or metric_table.pattern(f"h_{metric}", ["h"]) in names:
        return
    scores = {r[0] for q in study.resolved_questionnaires() for r in codebook_rows(q)}
    if metric in scores:
        raise ValueError(f"--metric: {metric} is a questionnaire score: simulated participants answer no questionnaire")
    known = sorted({n.removeprefix("<h>_") for n in names if "<" not in n.removeprefix("<h>_")})
    close = difflib.get_close_matches(metric, known, n=1)
    hint = f"did you mean {close[0]}?" if close else "the measures are the long table's (docs/reference/sessions.md)"
    raise ValueError(f"--metric: no measure {metric!r}: {hint}")
