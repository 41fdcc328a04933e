"""Power of the study's mixed model by simulation, resampling a pool of simulated participants.

Simulating every participant of every replicate study afresh costs hours (a batch trial takes
about a second of CPU); instead a pool of simulated participants runs the study's schedule once
(`haven study power` does that, in batch, on every core or Dask), and each replicate study of n
participants is drawn from it:

* the replicate's participants take the study's counterbalanced orders as the study would give n
  participants (`schedule`), and each slot is filled by a pool participant, drawn with replacement,
  who ran that scenario's conditions in the same order (their trials are used as they ran, positions
  included); one drawn twice counts as two participants;
* the effect: every pool trial in condition C is shifted by E minus the pool's own mean C - R
  difference, so the pool's C - R difference is exactly E while the spread between participants and
  between trials is the simulation's own (nothing is added or removed);
* each replicate is fitted with the study's mixed model (`record.mixed_model`, reference R); it
  detects the effect when C's coefficient has p < alpha. Power is the share of replicates that do,
  with a Wilson 95 % interval (its uncertainty from the number of replicates only);
* the same replicate, shifted so the pool's C - R difference is 0, is fitted too: the share of
  those that "detect" an effect is the test's false-positive rate on this pool. It should be about
  alpha; when its interval lies above alpha the test is anticonservative here (e.g. the effect
  varies between people more than the model's one residual assumes) and the power is overstated,
  which the output says.

Limits, said in the output: resampling cannot show more variety than the pool holds, so a pool
much smaller than the largest n understates the spread between studies; a fit that fails counts
as not detecting; singular fits (participant variance 0, as with deterministic simulated
participants) are counted and reported, their p values being those of a model that ignores the
pairing.
"""

from __future__ import annotations

import warnings
from collections import defaultdict
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from haven_scenarios.record.mixed_model import Observation, fit
from haven_scenarios.record.report import save_png

TARGET = 0.8  # the conventional power to plan for (Cohen 1988, Statistical Power Analysis, ch. 2.4)
POWER = ("scenario", "metric", "condition", "reference", "effect", "participants", "reps",
         "detected", "power", "ci_low", "ci_high", "singular", "failed", "mean_estimate", "pool", "pool_effect",
         "false_positives", "false_positive_rate", "fp_ci_low", "fp_ci_high")  # fmt: skip
Order = tuple[str, ...]  # a participant's conditions, in the order they ran them in one scenario


@dataclass(frozen=True)
class Question:
    metric: str
    per_person: bool
    condition: str  # C
    reference: str  # R
    effect: float  # E: the C - R difference to detect, in the metric's units
    conditions: tuple[str, ...]  # the study's, for its model
    alpha: float = 0.05
    reps: int = 200
    seed: int = 0


@dataclass(frozen=True)
class Cell:
    """One scenario at one participant count: what a worker needs to estimate its power."""

    question: Question
    scenario: str
    participants: int
    slots: tuple[Order, ...]  # the orders the study gives that many participants
    pool: dict[Order, tuple[tuple[Observation, ...], ...]]  # per order, each pool participant's trials (as they ran)
    pool_size: int
    pool_effect: float  # the pool's own C - R difference, before the shift

    def thin(self) -> list[tuple[Order, int, int]]:
        """The orders more slots need than the pool has distinct participants for: (order, slots,
        pool participants). Their replicates repeat people, so they vary less than real studies."""
        needed = {o: self.slots.count(o) for o in set(self.slots)}
        return [(o, n, len(self.pool[o])) for o, n in sorted(needed.items()) if len(self.pool[o]) < n]

    def shifted(self, trials: Sequence[Observation], slot: int, effect: float) -> list[Observation]:
        """A drawn participant's trials as participant `s<slot>`, C shifted so the pool's C - R difference is
        `effect`."""
        c, shift = self.question.condition, effect - self.pool_effect
        return [
            Observation(f"s{slot}", o.condition, o.position, o.value + shift if o.condition == c else o.value)
            for o in trials
        ]


@dataclass(frozen=True)
class Power:
    cell: Cell
    detected: int
    singular: int
    failed: int
    mean_estimate: float | None
    false_positives: int = 0  # the same replicates at E = 0 with p < alpha

    @property
    def false_positive_rate(self) -> float:
        return self.false_positives / self.cell.question.reps

    def anticonservative(self) -> bool:
        """The false-positive rate's interval lies wholly above alpha."""
        return wilson(self.false_positives, self.cell.question.reps)[0] > self.cell.question.alpha

    @property
    def power(self) -> float:
        return self.detected / self.cell.question.reps

    def interval(self) -> tuple[float, float]:
        return wilson(self.detected, self.cell.question.reps)

    def row(self) -> dict[str, Any]:
        q, low_high = self.cell.question, self.interval()
        return {
            "scenario": self.cell.scenario, "metric": q.metric, "condition": q.condition, "reference": q.reference,
            "effect": q.effect, "participants": self.cell.participants, "reps": q.reps, "detected": self.detected,
            "power": round(self.power, 4), "ci_low": round(low_high[0], 4), "ci_high": round(low_high[1], 4),
            "singular": self.singular, "failed": self.failed,
            "mean_estimate": round(self.mean_estimate, 6) if self.mean_estimate is not None else None,
            "pool": self.cell.pool_size, "pool_effect": round(self.cell.pool_effect, 6),
            "false_positives": self.false_positives, "false_positive_rate": round(self.false_positive_rate, 4),
            **dict(zip(("fp_ci_low", "fp_ci_high"),
                       (round(x, 4) for x in wilson(self.false_positives, q.reps)), strict=True)),
        }  # fmt: skip


def wilson(successes: int, n: int, alpha: float = 0.05) -> tuple[float, float]:
    """The Wilson score interval of a proportion (Wilson 1927, JASA 22:209; statsmodels' "wilson")."""
    from statsmodels.stats.proportion import proportion_confint

    low, high = proportion_confint(successes, n, alpha=alpha, method="wilson")
    return float(low), float(high)


def pool_effect(pool: Sequence[Observation], question: Question) -> float:
    """The pool's mean in C minus its mean in R; ValueError (one line) when either has no trial."""
    means = {}
    for c in (question.condition, question.reference):
        values = [o.value for o in pool if o.condition == c]
        if not values:
            raise ValueError(f"the pool has no valid trial of {question.metric} in condition {c}")
        means[c] = sum(values) / len(values)
    return means[question.condition] - means[question.reference]


def cell(
    question: Question, scenario: str, participants: int, slots: Sequence[Order], pool: Sequence[Observation]
) -> Cell:
    """The cell's pool, grouped by each pool participant's order; ValueError (one line) when an
    order the study needs has no pool participant."""
    delta = pool_effect(pool, question)
    trials: dict[str, list[Observation]] = defaultdict(list)
    for o in pool:
        trials[o.participant].append(o)
    groups: dict[Order, list[tuple[Observation, ...]]] = defaultdict(list)
    for person in sorted(trials):
        ran = tuple(sorted(trials[person], key=lambda o: o.position))
        groups[tuple(o.condition for o in ran)].append(ran)
    for order in slots:
        if order not in groups:
            raise ValueError(
                f"{scenario}: no pool participant ran the order "
                f"{', '.join(order)} with valid trials: use a larger --pool"
            )
    return Cell(
        question, scenario, participants, tuple(slots), {k: tuple(v) for k, v in groups.items()}, len(trials), delta
    )


def estimate(c: Cell) -> Power:
    """The cell's replicate studies, each drawn from the pool and fitted (a picklable task)."""
    q = c.question
    rng = np.random.default_rng([q.seed, c.participants, *c.scenario.encode()])
    detected = singular = failed = false_positives = 0
    estimates = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # (the fits say what they need to in their results)
        for _ in range(q.reps):
            drawn = [(slot, c.pool[order][int(rng.integers(len(c.pool[order])))]) for slot, order in enumerate(c.slots)]
            null = fit(
                [o for slot, trials in drawn for o in c.shifted(trials, slot, 0.0)], q.conditions, q.reference
            ).term(q.condition)
            false_positives += null is not None and null.p is not None and null.p < q.alpha
            f = fit([o for slot, trials in drawn for o in c.shifted(trials, slot, q.effect)], q.conditions, q.reference)
            term = f.term(q.condition)
            if term is None or term.p is None:
                failed += 1
                continue
            singular += f.singular
            detected += term.p < q.alpha
            estimates.append(term.coef)
    return Power(c, detected, singular, failed, float(np.mean(estimates)) if estimates else None, false_positives)


def table(results: Sequence[Power]) -> list[list[str]]:
    """The printed table: power with its interval per scenario and participant count."""
    rows = [
        ["scenario", "participants", "power", "95 % CI (Wilson)", "detected", "at E=0", "singular fits", "failed fits"]
    ]
    for r in results:
        low, high = r.interval()
        reps = r.cell.question.reps
        null = f"{r.false_positive_rate:.2f}" + (" !" if r.anticonservative() else "")
        rows.append([r.cell.scenario, str(r.cell.participants), f"{r.power:.2f}", f"{low:.2f}-{high:.2f}",
                     f"{r.detected}/{reps}", null, f"{r.singular}/{reps}", f"{r.failed}/{reps}"])  # fmt: skip
    return rows


def draw(results: Sequence[Power], out: Path, title: str) -> Path:
    """The power curve per scenario, Wilson intervals as error bars, the 0.8 target dashed."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for i, scenario in enumerate(sorted({r.cell.scenario for r in results})):
        mine = sorted((r for r in results if r.cell.scenario == scenario), key=lambda r: r.cell.participants)
        n = [r.cell.participants for r in mine]
        p = np.array([r.power for r in mine])
        low, high = np.array([r.interval() for r in mine]).T
        loose = any(r.anticonservative() for r in mine)  # (overstated power: its line dashed and said)
        label = f"{scenario} (! finds absent effects too often)" if loose else scenario
        ax.errorbar(
            n,
            p,
            yerr=[np.clip(p - low, 0, None), np.clip(high - p, 0, None)],
            marker="o",
            capsize=4,
            color=f"C{i}",
            label=label,
            linestyle="--" if loose else "-",
        )
    ax.axhline(TARGET, color="grey", linestyle="--", linewidth=1, label=f"{TARGET:g}: the usual target (Cohen 1988)")
    ax.set_ylim(-0.03, 1.03)
    ax.set_xticks(sorted({r.cell.participants for r in results}))
    ax.set_xlabel("participants")
    ax.set_ylabel("power: share of studies with p < alpha")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="lower right")
    ax.set_title(title, fontsize=9)
    fig.tight_layout()
    return save_png(fig, out)
