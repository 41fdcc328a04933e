"""Within-subject summary statistics: a mean with its 95 % confidence interval, and a condition's
paired difference from the reference with its interval and Cohen's d_z.

The participant is the unit: each participant's values in a condition are averaged first (their
repetitions and the people of a trial), so a participant counts once however many trials they ran.
Intervals are Student's t intervals over the participants; d_z is the mean paired difference over
the standard deviation of the paired differences (Cohen 1988, Statistical Power Analysis for the
Behavioral Sciences, eq. 2.3.5; Lakens 2013, Front. Psychol. 4:863, eq. 6), the effect size a
paired t test's power depends on, not comparable with a between-subjects d.
"""

from __future__ import annotations

import math
import statistics
from collections import defaultdict
from collections.abc import Iterable, Mapping
from dataclasses import dataclass

LEVEL = 0.95  # the confidence intervals' level


@dataclass(frozen=True)
class Interval:
    """A mean (of values, or of paired differences) with its t interval; low/high None below 2 values."""

    n: int
    mean: float | None
    low: float | None = None
    high: float | None = None
    d_z: float | None = None  # for paired differences: mean / sd (None when the sd is 0)


def participant_means(values: Iterable[tuple[str, float]]) -> dict[str, float]:
    """(participant, value) pairs to each participant's mean."""
    groups: dict[str, list[float]] = defaultdict(list)
    for participant, v in values:
        groups[participant].append(v)
    return {p: statistics.fmean(v) for p, v in groups.items()}


def mean_interval(values: Iterable[float]) -> Interval:
    v = list(values)
    if not v:
        return Interval(0, None)
    mean = statistics.fmean(v)
    if len(v) < 2:
        return Interval(1, mean)
    from scipy.stats import t

    half = float(t.ppf(0.5 + LEVEL / 2, len(v) - 1)) * statistics.stdev(v) / math.sqrt(len(v))
    return Interval(len(v), mean, mean - half, mean + half)


def paired_difference(condition: Mapping[str, float], reference: Mapping[str, float]) -> Interval:
    """The condition minus the reference over the participants who have both, with d_z."""
    diffs = [condition[p] - reference[p] for p in sorted(condition.keys() & reference.keys())]
    got = mean_interval(diffs)
    if got.n < 2 or got.mean is None:
        return got
    sd = statistics.stdev(diffs)
    return Interval(got.n, got.mean, got.low, got.high, got.mean / sd if sd > 0 else None)
