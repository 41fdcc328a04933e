"""`haven study power STUDY --metric M --effect E`: the power of the study's mixed model by simulation.

A pool of simulated participants runs the study's schedule in batch (every trial as `haven study
run --batch` runs it; the pool's participants p01.. get the study's seeds and orders), on every core
or a Dask cluster, into OUT/pool, where it is kept: a second run with another metric or effect
reuses it (delete it after changing the participant model or the parameters). Then replicate
studies of each participant count are drawn from it and fitted (record/power.py says how).
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

from haven_scenarios.conduct.power_pool import check_metric, measured_per_person, orders, simulate_pool
from haven_scenarios.record.mixed_model import observations
from haven_scenarios.record.power import POWER, Cell, Power, Question, cell, draw, estimate, table
from haven_scenarios.record.report import write_table
from haven_scenarios.run.sweep import LOCAL, cores, farm
from haven_scenarios.study.protocol import Study, StudyError, load_study
from haven_scenarios.study.scenario import ScenarioError
from haven_scenarios.study.schedule import sequence_count
from haven_scenarios.tools.commands.common import bounded_int, existing_file, fail, table as text

DEFAULT_COUNTS = "8,12,16,24"
MAX_PARTICIPANTS = 1000  # per replicate study, and in the pool: more is a typo, not a study
MAX_REPS = 100_000


def add(steps: argparse._SubParsersAction, spec: str) -> argparse.ArgumentParser:  # type: ignore[type-arg]
    about = "power of the study's mixed model per participant count, by simulating studies from a pool"
    power: argparse.ArgumentParser = steps.add_parser("power", help=about)
    power.add_argument("study", help=spec)
    power.add_argument("--metric", required=True, help="the measure (as in study_long.csv), e.g. time_to_finish_s")
    power.add_argument(
        "--effect",
        type=float,
        required=True,
        help="the difference to detect, condition minus reference, in the metric's units",
    )
    power.add_argument(
        "--participants", default=DEFAULT_COUNTS, help=f"participant counts to try (default {DEFAULT_COUNTS})"
    )
    power.add_argument(
        "--reps", type=bounded_int(1, MAX_REPS), default=200, help="simulated studies per count (default 200)"
    )
    power.add_argument("--condition", default=None, help="the condition C (default: the study's last)")
    power.add_argument("--reference", default=None, help="the reference condition R (default: the study's first)")
    power.add_argument(
        "--scenario", default=None, help="only this scenario: its trials alone are simulated (default: every scenario)"
    )
    power.add_argument("--alpha", type=float, default=0.05, help="the test's level (default 0.05)")
    power.add_argument(
        "--pool",
        type=bounded_int(2, MAX_PARTICIPANTS),
        default=None,
        help="simulated participants to draw from (default: the largest count)",
    )
    power.add_argument(
        "--workers",
        type=bounded_int(1, 256),
        default=None,
        help=f"worker processes (default: every core, {cores()} here)",
    )
    power.add_argument(
        "--cluster",
        default=None,
        metavar="local|ADDRESS",
        help="run on Dask: local, or a scheduler's address (tcp://host:8786)",
    )
    power.add_argument("--seed", type=bounded_int(0, 2**31 - 1), default=0, help="seed of the resampling (default 0)")
    power.add_argument(
        "--params-file", type=existing_file, default=None, help="ROS parameter YAML for every pool trial"
    )
    power.add_argument(
        "--out",
        type=Path,
        default=None,
        help="folder for the table, the plot and the pool (default: <study dir>/power)",
    )
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


def power_cmd(args: argparse.Namespace) -> int:
    from haven_scenarios.study.names import study_dir

    try:
        study = load_study(args.study)
        condition, reference = _question(args, study)
        check_metric(args.metric, study)
        ns = counts(args.participants)
        size = args.pool or max(ns)
        out = args.out if args.out is not None else study_dir(args.dir, study) / "power"
        results, ran = simulate_pool(
            study, size, out / "pool", args.scenario, args.params_file, args.workers, args.cluster
        )
        per_person = measured_per_person(results, args.metric)
        conditions = tuple(c.name for c in study.conditions)
        q = Question(
            args.metric, per_person, condition, reference, args.effect, conditions, args.alpha, args.reps, args.seed
        )
        scenarios = [args.scenario] if args.scenario else [s.name for s in study.scenarios]
        cells: list[Cell] = []
        for scenario in scenarios:
            pool = observations(results, scenario, args.metric, per_person)
            if not pool and args.scenario is None:
                continue
            cells += [cell(q, scenario, n, orders(study, n, scenario), pool) for n in ns]
        if not cells:
            raise ValueError(
                f"--scenario {args.scenario}: no valid trial of {args.metric} in it"
                if args.scenario
                else "no cell to estimate"
            )
        estimated = sorted(
            farm(cells, estimate, args.workers or cores(), args.cluster),
            key=lambda r: (r.cell.scenario, r.cell.participants),
        )
    except (StudyError, ScenarioError, ValueError) as e:
        return fail(str(e))
    except OSError as e:
        return fail(f"cannot write the power analysis: {e.strerror or e}")
    return _say(study, q, estimated, out, size, ran)


def file_stem(q: Question) -> str:
    """The output's name: the metric, the contrast and the effect (another question, another file)."""
    return f"power_{q.metric}_{q.condition}-{q.reference}_E{q.effect:g}"


def _say(study: Study, q: Question, estimated: list[Power], out: Path, size: int, ran: int) -> int:
    name = file_stem(q)
    write_table(out / f"{name}.csv", [r.row() for r in estimated], POWER)
    title = (
        f"{study.name}: {q.metric}, {q.condition} - {q.reference} = {q.effect:g}, "
        f"alpha {q.alpha:g}, {q.reps} simulated studies per count"
    )
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
    print(
        "at E=0: the same studies with the pool's difference set to 0, "
        f"the share with p < {q.alpha:g} (a calibrated test: about {q.alpha:g})"
    )
    rows = sequence_count(study)
    partial = sorted({r.cell.participants for r in estimated if r.cell.participants % rows})
    if partial:
        listed = ", ".join(map(str, partial))
        print(
            f"note: {listed} participant(s) do not complete the study's {rows} "
            "sequences: those studies are unbalanced, as real ones would be"
        )
    thin = sorted({(r.cell.scenario, r.cell.participants) for r in estimated if r.cell.thin()})
    if thin:
        cells = ", ".join(f"{s} at {n}" for s, n in thin)
        print(
            f"warning: {cells}: an order needs more participants than the pool "
            "has who ran it, so studies repeat people: use a larger --pool"
        )
    loose = sorted({r.cell.scenario for r in estimated if r.anticonservative()})
    if loose:
        print(
            f"warning: {', '.join(loose)}: the test finds an effect that is not there more "
            "often than alpha (marked !), so its power is overstated: do not plan on it (the "
            "effect may vary between people more than the model allows; docs/howto/power.md)"
        )
    print(f"haven study power: wrote {out / (name + '.csv')} and {name}.png")
    return 0
