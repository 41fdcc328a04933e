"""`haven study power STUDY --metric M --effect E`: the power of the study's mixed model by simulation.

A pool of simulated participants runs the study's schedule in batch (every trial as `haven study
run --batch` runs it; the pool's participants p01.. get the study's seeds and orders), on every core
or a Dask cluster, into OUT/pool, where it is kept: a second run with another metric or effect
reuses it (delete it after changing the participant model or the parameters). Then replicate
studies of each participant count are drawn from it and fitted (record/power.py says how).
"""

from __future__ import annotations

import argparse
import difflib
import math
import sys
from dataclasses import dataclass, replace
from pathlib import Path

from haven_scenarios.record import metric_table
from haven_scenarios.record.mixed_model import observations
from haven_scenarios.record.power import POWER, Cell, Order, Power, Question, cell, draw, estimate, table
from haven_scenarios.record.report import write_table
from haven_scenarios.record.study_table import TrialResults, trial_results
from haven_scenarios.run.sweep import LOCAL, cores, farm
from haven_scenarios.study.progress import attempts, bind, progress, trial_dir
from haven_scenarios.study.protocol import Study, StudyError, load_study
from haven_scenarios.study.questionnaires import codebook_rows
from haven_scenarios.study.scenario import ScenarioError, load_scenario
from haven_scenarios.study.schedule import PlannedTrial, participant_schedule, sequence_count
from haven_scenarios.tools.commands.common import bounded_int, existing_file, fail

DEFAULT_COUNTS = "8,12,16,24"
MAX_PARTICIPANTS = 1000  # per replicate study, and in the pool: more is a typo, not a study
MAX_REPS = 100_000


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


def add(steps: argparse._SubParsersAction, spec: str) -> argparse.ArgumentParser:  # type: ignore[type-arg]
    about = "power of the study's mixed model per participant count, by simulating studies from a pool"
    power: argparse.ArgumentParser = steps.add_parser("power", help=about)
    power.add_argument("study", help=spec)
    power.add_argument("--metric", required=True, help="the measure (as in study_long.csv), e.g. time_to_finish_s")
    power.add_argument("--effect", type=float, required=True, help="the difference to detect, condition minus reference, in the metric's units")
    power.add_argument("--participants", default=DEFAULT_COUNTS, help=f"participant counts to try (default {DEFAULT_COUNTS})")
    power.add_argument("--reps", type=bounded_int(1, MAX_REPS), default=200, help="simulated studies per count (default 200)")
    power.add_argument("--condition", default=None, help="the condition C (default: the study's last)")
    power.add_argument("--reference", default=None, help="the reference condition R (default: the study's first)")
    power.add_argument("--scenario", default=None, help="only this scenario: its trials alone are simulated (default: every scenario)")
    power.add_argument("--alpha", type=float, default=0.05, help="the test's level (default 0.05)")
    power.add_argument(
        "--pool", type=bounded_int(2, MAX_PARTICIPANTS), default=None, help="simulated participants to draw from (default: the largest count)"
    )
    power.add_argument("--workers", type=bounded_int(1, 256), default=None, help=f"worker processes (default: every core, {cores()} here)")
    power.add_argument("--cluster", default=None, metavar="local|ADDRESS", help="run on Dask: local, or a scheduler's address (tcp://host:8786)")
    power.add_argument("--seed", type=bounded_int(0, 2**31 - 1), default=0, help="seed of the resampling (default 0)")
    power.add_argument("--params-file", type=existing_file, default=None, help="ROS parameter YAML for every pool trial")
    power.add_argument("--out", type=Path, default=None, help="folder for the table, the plot and the pool (default: <study dir>/power)")
    power.set_defaults(func=power_cmd)
    return power


def counts(text: str) -> list[int]:
    """`8,12,16` as participant counts; ValueError (one line) otherwise."""
    try:
        values = sorted({int(v) for v in text.split(",")})
    except ValueError:
        raise ValueError(f"--participants: expected counts like {DEFAULT_COUNTS}, got {text!r}") from None
    if not values or not all(2 <= v <= MAX_PARTICIPANTS for v in values):
        raise ValueError(f"--participants: each count must be 2..{MAX_PARTICIPANTS}, got {text!r}")
    return values


def with_participants(study: Study, n: int) -> Study:
    return replace(study, participants=tuple(f"p{k:02d}" for k in range(1, n + 1)))


def pool_study(study: Study, n: int) -> Study:
    """The study the pool runs: n participants taking the sequences in turn, whatever the study's
    assignment, so every condition order is in a pool at least as large as their count."""
    return replace(with_participants(study, n), assignment="by_id")


def _question(args: argparse.Namespace, study: Study) -> tuple[str, str]:
    names = [c.name for c in study.conditions]
    condition, reference = args.condition or names[-1], args.reference or names[0]
    for option, value in (("--condition", condition), ("--reference", reference)):
        if value not in names:
            raise ValueError(f"{option}: {value!r} is not a condition of study {study.name} ({', '.join(names)})")
    if condition == reference:
        raise ValueError(f"--condition and --reference are both {condition}: nothing to compare")
    if not math.isfinite(args.effect):
        raise ValueError(f"--effect: must be a finite number, got {args.effect}")
    if not 0 < args.alpha < 1:
        raise ValueError(f"--alpha: must be within (0, 1), got {args.alpha:g}")
    if args.cluster is not None and args.cluster != LOCAL and "://" not in args.cluster:
        raise ValueError(f"--cluster: expected local or a scheduler address like tcp://host:8786, got {args.cluster!r}")
    return condition, reference


def simulate_participant(job: PoolJob) -> tuple[str, int, str]:
    """Run the pool participant's trials not done yet; (participant, trials run, what went wrong)."""
    from haven_scenarios.tools.commands.study_run import batch_session  # (the runner's own batch trial)

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
            return job.participant, ran, f"{p.trial.folder} did not finish ({made[-1].outcome if made else 'no session'})"
    return job.participant, ran, ""


def simulate_pool(study: Study, size: int, root: Path, args: argparse.Namespace) -> tuple[list[TrialResults], int]:
    """The pool's trial results (simulating what is not there yet) and how many trials ran now."""
    pool = pool_study(study, size)
    for s in sorted({s.spec for s in pool.scenarios} | {p.scenario.spec for p in pool.practice}):
        if any(h.teleoperated for h in load_scenario(s).humans):
            raise ValueError(f"scenario {s} has a teleoperated participant: the pool needs simulated ones")
    trials = bind(pool, root, replan=True)
    if args.scenario is not None and args.scenario not in [s.name for s in study.scenarios]:
        raise ValueError(f"--scenario: {args.scenario!r} is not a scenario of study {study.name} ({', '.join(s.name for s in study.scenarios)})")
    todo = sorted({p.trial.participant for p in progress(root, trials) if p.status != "done" and wanted(p.trial, args.scenario)})
    params = str(Path(args.params_file).resolve()) if args.params_file else None
    jobs = [PoolJob(study.source, size, p, root, params, args.scenario) for p in todo]
    workers = args.workers or cores()
    ran = 0
    if jobs:
        print(
            f"haven study power: simulating {len(jobs)} pool participant(s) on {args.cluster or f'{min(workers, len(jobs))} process(es)'}", flush=True
        )
    for participant, n, problem in farm(jobs, simulate_participant, workers, args.cluster):
        ran += n
        if problem:
            raise ValueError(f"pool participant {participant}: {problem}")
        print(f"haven study power: pool participant {participant} done ({n} trial(s) run)", file=sys.stderr, flush=True)
    results = [r for r in (trial_results(t) for t in progress(root, trials)) if r is not None]
    return results, ran


def orders(study: Study, n: int, scenario: str) -> list[Order]:
    """The condition orders the study gives n participants in one scenario (practice left out)."""
    s = with_participants(study, n)
    return [tuple(t.condition for t in participant_schedule(s, p) if t.scenario == scenario and not t.practice) for p in s.participants]


def _per_person(results: list[TrialResults], metric: str) -> bool:
    kinds = {bool(m.human) for r in results for m in r.measures if m.measure == metric}
    if not kinds:
        names = sorted({m.measure for r in results for m in r.measures})
        raise ValueError(f"--metric: no measure {metric!r} in the pool's trials (some there are: {', '.join(names[:12])} ...)")
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


def power_cmd(args: argparse.Namespace) -> int:
    from haven_scenarios.tools.commands.study import study_dir

    try:
        study = load_study(args.study)
        condition, reference = _question(args, study)
        check_metric(args.metric, study)
        ns = counts(args.participants)
        size = args.pool or max(ns)
        out = args.out if args.out is not None else study_dir(args.dir, study) / "power"
        results, ran = simulate_pool(study, size, out / "pool", args)
        per_person = _per_person(results, args.metric)
        conditions = tuple(c.name for c in study.conditions)
        q = Question(args.metric, per_person, condition, reference, args.effect, conditions, args.alpha, args.reps, args.seed)
        scenarios = [args.scenario] if args.scenario else [s.name for s in study.scenarios]
        cells: list[Cell] = []
        for scenario in scenarios:
            pool = observations(results, scenario, args.metric, per_person)
            if not pool and args.scenario is None:
                continue
            cells += [cell(q, scenario, n, orders(study, n, scenario), pool) for n in ns]
        if not cells:
            raise ValueError(f"--scenario {args.scenario}: no valid trial of {args.metric} in it" if args.scenario else "no cell to estimate")
        estimated = sorted(farm(cells, estimate, args.workers or cores(), args.cluster), key=lambda r: (r.cell.scenario, r.cell.participants))
    except (StudyError, ScenarioError, ValueError) as e:
        return fail(str(e))
    except OSError as e:
        return fail(f"cannot write the power analysis: {e.strerror or e}")
    return _say(study, q, estimated, out, size, ran)


def file_stem(q: Question) -> str:
    """The output's name: the metric, the contrast and the effect (another question, another file)."""
    return f"power_{q.metric}_{q.condition}-{q.reference}_E{q.effect:g}"


def _say(study: Study, q: Question, estimated: list[Power], out: Path, size: int, ran: int) -> int:
    from haven_scenarios.tools.commands.study import table as text

    name = file_stem(q)
    write_table(out / f"{name}.csv", [r.row() for r in estimated], POWER)
    title = f"{study.name}: {q.metric}, {q.condition} - {q.reference} = {q.effect:g}, alpha {q.alpha:g}, {q.reps} simulated studies per count"
    draw(estimated, out / f"{name}.png", title.replace(", alpha", "\nalpha") + f", a pool of {size}")
    shifts = ", ".join(f"{s} {c.pool_effect:+.4g}" for s, c in {r.cell.scenario: r.cell for r in estimated}.items())
    print(f"haven study power: {title}")
    print(f"pool: {size} simulated participant(s) ({ran} trial(s) simulated now) in {out / 'pool'}")
    print(f"the pool's own {q.condition} - {q.reference} difference: {shifts}")
    print(
        f"each study: participants drawn from the pool with replacement; the trials in condition {q.condition} shifted"
        f" so the pool's {q.condition} - {q.reference} difference is {q.effect:g}"
    )
    print(text(table(estimated)))
    singular = sum(r.singular for r in estimated)
    if singular:
        print(f"note: {singular} fit(s) singular (participant variance 0): their p values ignore the pairing")
    print(f"at E=0: the same studies with the pool's difference set to 0, the share with p < {q.alpha:g} (a calibrated test: about {q.alpha:g})")
    rows = sequence_count(study)
    partial = sorted({r.cell.participants for r in estimated if r.cell.participants % rows})
    if partial:
        listed = ", ".join(map(str, partial))
        print(f"note: {listed} participant(s) do not complete the study's {rows} sequences: those studies are unbalanced, as real ones would be")
    thin = sorted({(r.cell.scenario, r.cell.participants) for r in estimated if r.cell.thin()})
    if thin:
        cells = ", ".join(f"{s} at {n}" for s, n in thin)
        print(f"warning: {cells}: an order needs more participants than the pool has who ran it, so studies repeat people: use a larger --pool")
    loose = sorted({r.cell.scenario for r in estimated if r.anticonservative()})
    if loose:
        print(
            f"warning: {', '.join(loose)}: the test finds an effect that is not there more often than alpha (marked !), so its power is"
            " overstated: do not plan on it (the effect may vary between people more than the model allows; docs/howto/power.md)"
        )
    print(f"haven study power: wrote {out / (name + '.csv')} and {name}.png")
    return 0
