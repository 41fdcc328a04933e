"""A study's per-condition summary, for a lab meeting: summary.csv and summary.png.

summary.csv, per scenario x condition x person x measure: the trials' n, mean, sd and median; the
participants' mean with its 95 % t interval; and against the reference condition (the study's
first) the paired difference over the participants with its 95 % interval and Cohen's d_z
(record/paired_stats.py). summary.png, per main measure and scenario: each participant's values
linked across the conditions (they are within-subject), the condition means with their 95 %
intervals, and under each condition its n and paired difference. Axes span at least a measure's
`min_span` in its units (a measure with nearly equal values does not fill the panel with noise),
questionnaire scores their instrument's range. Practice trials are left out, and so are trials
flagged not valid (the CSV counts them in `n_invalid`); the figure pools a trial's people.
"""

from __future__ import annotations

import math
import statistics
from collections import defaultdict
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from haven_scenarios.record.paired_stats import Interval, mean_interval, paired_difference, participant_means
from haven_scenarios.record.report import save_png
from haven_scenarios.record.study_table import TrialResults
from haven_scenarios.study.questionnaires import Questionnaire

SUMMARY = ("scenario", "condition", "human", "measure", "n", "n_invalid", "mean", "sd", "median", "participants",
           "ci_low", "ci_high", "reference", "diff_n", "diff_mean", "diff_ci_low", "diff_ci_high", "d_z")  # fmt: skip
# The main measures of the figure: (per person?, measure, axis label, least axis span in its unit:
# about what a reader would call a difference worth a look, so equal values stay a flat line).
MAIN = (
    (False, "min_human_centre_distance_m", "closest approach of the robot (m, centres)", 0.2),
    (False, "robot_time_to_finish_s", "robot's time to finish its task (s)", 5.0),
    (True, "time_to_finish_s", "person's time to finish their task (s)", 5.0),
    (True, "detour_m", "person's detour (m)", 0.5),
    (True, "hesitations", "person's hesitations (count)", 2.0),
)
Key = tuple[str, str, str, str]  # scenario, condition, human ("" or "person"), measure
Values = dict[Key, list[tuple[str, float]]]  # (participant, value) per trial and person


@dataclass(frozen=True)
class Panel:
    measure: str
    per_person: bool
    label: str
    limits: tuple[float, float] | None = None  # a questionnaire's scale
    min_span: float = 0.0


def _groups(results: Sequence[TrialResults], pool_people: bool) -> tuple[Values, dict[Key, int]]:
    values: Values = defaultdict(list)
    invalid: dict[Key, int] = defaultdict(int)
    for r in results:
        if r.design["practice"]:
            continue
        for m in r.measures:
            human = ("person" if m.human else "") if pool_people else m.human
            key = (str(r.design["scenario"]), str(r.design["condition"]), human, m.measure)
            if r.design["valid"]:
                values[key].append((str(r.design["participant"]), m.value))
            else:
                invalid[key] += 1
    return values, invalid


def _r(v: float | None) -> float | None:
    return round(v, 4) if v is not None and math.isfinite(v) else None


def _difference(values: Values, key: Key, reference: str) -> dict[str, Any]:
    if key[1] == reference:
        return {}
    mine = participant_means(values.get(key, []))
    theirs = participant_means(values.get((key[0], reference, key[2], key[3]), []))
    d = paired_difference(mine, theirs)
    return {
        "reference": reference,
        "diff_n": d.n,
        "diff_mean": _r(d.mean),
        "diff_ci_low": _r(d.low),
        "diff_ci_high": _r(d.high),
        "d_z": _r(d.d_z),
    }


def summary_rows(results: Sequence[TrialResults], conditions: Sequence[str]) -> list[dict[str, Any]]:
    """One row per scenario x condition x person x measure, conditions in the study's order."""
    values, invalid = _groups(results, pool_people=False)
    rank = {c: i for i, c in enumerate(conditions)}
    rows = []
    for key in sorted(set(values) | set(invalid), key=lambda k: (k[0], rank.get(k[1], len(rank)), k[2], k[3])):
        v = [x for _, x in values.get(key, [])]
        m = mean_interval(participant_means(values.get(key, [])).values())
        rows.append(
            {
                **dict(zip(SUMMARY[:4], key, strict=True)),
                "n": len(v),
                "n_invalid": invalid.get(key, 0),
                "mean": round(statistics.fmean(v), 4) if v else None,
                "sd": round(statistics.stdev(v), 4) if len(v) > 1 else None,
                "median": round(statistics.median(v), 4) if v else None,
                "participants": m.n,
                "ci_low": _r(m.low),
                "ci_high": _r(m.high),
                **(_difference(values, key, conditions[0]) if conditions else {}),
            }
        )
    return rows


def panels(results: Sequence[TrialResults], questionnaires: Sequence[Questionnaire]) -> list[Panel]:
    """The main measures there are values of, then each questionnaire's overall scores (the raw TLX,
    the Godspeed series, a Likert questionnaire's mean), on their scale."""
    present = {(bool(m.human), m.measure) for r in results if not r.design["practice"] for m in r.measures}
    out = [Panel(m, person, label, None, span) for person, m, label, span in MAIN if (person, m) in present]
    for q in questionnaires:
        for scale, _ in q.scales:
            name = q.name if scale == q.name else f"{q.name}_{scale}"
            if q.name == "nasa_tlx" and scale != "raw":
                continue  # the subscales are in summary.csv
            if (True, name) in present:
                label = f"{q.title}: {scale}" if scale != q.name else q.title
                out.append(Panel(name, True, f"{label} ({q.minimum:g}-{q.maximum:g})", (q.minimum, q.maximum)))
    return out


def _tick(condition: str, n: int, d: Interval | None, digits: int) -> str:
    text = condition.replace("_", "\n") + f"\nn={n}"
    if d is None:
        return text + ("\n(reference)" if n else "")
    if d.mean is None or d.low is None or d.high is None:
        return text
    dz = f"{d.d_z:+.2f}" if d.d_z is not None else "n/a (sd 0)"
    return text + f"\nΔ {d.mean:+.{digits}f}\n[{d.low:+.{digits}f}, {d.high:+.{digits}f}]\nd_z {dz}"


def _digits(span: float) -> int:
    """Decimals that resolve about a fiftieth of the axis: no more digits than the eye can use."""
    return max(0, math.ceil(-math.log10(span / 50))) if span > 0 else 0


def _limits(panel: Panel, low: float, high: float, nonnegative: bool) -> tuple[float, float]:
    """The y range: the instrument's scale, else the data's widened to the panel's least span."""
    if panel.limits is not None:
        a, b = panel.limits
        return a - 0.05 * (b - a), b + 0.05 * (b - a)
    span = max(high - low, panel.min_span, 1e-9)
    mid = (low + high) / 2
    a, b = mid - 0.55 * span, mid + 0.55 * span
    if nonnegative and a < 0 <= low:
        a, b = -0.05 * span, b - a - 0.05 * span
    return a, b


def _panel(ax: Any, panel: Panel, scenario: str, values: Values, conditions: Sequence[str]) -> None:
    """One measure in one scenario: participants' lines, means with 95 % intervals, paired Δ."""
    kind = "person" if panel.per_person else ""
    means = {c: participant_means(values.get((scenario, c, kind, panel.measure), [])) for c in conditions}
    everyone = sorted({p for m in means.values() for p in m})
    for p in everyone:
        xs = [i for i, c in enumerate(conditions) if p in means[c]]
        ax.plot(
            xs,
            [means[conditions[i]][p] for i in xs],
            color="0.55",
            alpha=0.55,
            linewidth=0.8,
            marker="o",
            markersize=3,
            zorder=2,
        )
    data = [v for m in means.values() for v in m.values()]
    for i, c in enumerate(conditions):
        m = mean_interval(means[c].values())
        if m.mean is not None:
            err = [[m.mean - m.low], [m.high - m.mean]] if m.low is not None and m.high is not None else None
            ax.errorbar(
                i + 0.15,
                m.mean,
                yerr=err,
                fmt="D",
                color=f"C{i % 10}",
                markersize=6,
                capsize=4,
                linewidth=1.6,
                zorder=4,
            )
            data += [x for x in (m.low, m.high) if x is not None]
    low, high = _limits(panel, min(data), max(data), min(data) >= 0) if data else (0.0, 1.0)
    ax.set_ylim(low, high)
    ticks = [
        _tick(c, len(means[c]), paired_difference(means[c], means[conditions[0]]) if i else None, _digits(high - low))
        for i, c in enumerate(conditions)
    ]
    ax.set_xticks(range(len(conditions)), ticks, fontsize=7)
    ax.set_xlim(-0.5, len(conditions) - 0.3)
    if all(float(v).is_integer() for v in data) or (panel.limits is None and panel.measure == "hesitations"):
        from matplotlib.ticker import MaxNLocator

        ax.yaxis.set_major_locator(MaxNLocator(integer=True))
    ax.set_title(f"{panel.label}\n{scenario}", fontsize=9)
    ax.grid(axis="y", alpha=0.3)


def draw(
    results: Sequence[TrialResults],
    conditions: Sequence[str],
    questionnaires: Sequence[Questionnaire],
    out: Path,
    title: str,
) -> Path | None:
    """summary.png: a panel per main measure and scenario (each on its own scale); None when there
    is nothing to draw."""
    shown = panels(results, questionnaires)
    if not shown or not conditions:
        return None
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    values, _ = _groups(results, pool_people=True)
    scenarios = sorted({k[0] for k in values})
    cells = [(panel, scenario) for panel in shown for scenario in scenarios]
    cols = min(len(cells), len(scenarios) * max(1, 4 // len(scenarios)))
    rows = math.ceil(len(cells) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(4.6 * cols, 4.4 * rows), squeeze=False)
    for ax, (panel, scenario) in zip(axes.flat, cells, strict=False):
        _panel(ax, panel, scenario, values, conditions)
    for ax in list(axes.flat)[len(cells) :]:
        ax.axis("off")
    fig.suptitle(
        f"{title}\ngrey: each participant's mean per condition, linked (within-subject); "
        "diamonds: mean over participants with its 95 % t interval;"
        f"\nΔ: paired difference from {conditions[0]} [95 % interval], "
        "d_z = mean / sd of the paired differences (Cohen 1988); valid trials, practice left out",
        fontsize=9,
    )
    fig.tight_layout(rect=(0, 0, 1, 1 - 0.55 / (4.4 * rows)))  # (the title's three lines: about half an inch)
    return save_png(fig, out)
