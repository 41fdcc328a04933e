"""A study's per-condition summary: summary.csv (n, mean, sd, median of every measure per scenario
and condition) and summary.png (the distributions of the main measures per condition: a first
look, not the analysis). Practice trials are left out, and so are trials flagged not valid (the
CSV counts them in `n_invalid`); per-person measures pool the people of a trial.
"""

from __future__ import annotations

import math
import statistics
from collections import defaultdict
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from haven_scenarios.record.study_table import TrialResults
from haven_scenarios.study.questionnaires import Questionnaire
from haven_sim.common import atomic

SUMMARY = ("scenario", "condition", "human", "measure", "n", "n_invalid", "mean", "sd", "median")
# The main measures of the figure: (per person?, measure, axis label); questionnaire scores follow.
MAIN = (
    (False, "min_human_centre_distance_m", "closest approach of the robot (m)"),
    (False, "robot_time_to_finish_s", "robot's time to finish its task (s)"),
    (True, "time_to_finish_s", "person's time to finish their task (s)"),
    (True, "detour_m", "person's detour (m)"),
    (True, "hesitations", "person's hesitations (count)"),
)
Key = tuple[str, str, str, str]  # scenario, condition, human ("" or "person"), measure


@dataclass(frozen=True)
class Panel:
    measure: str
    per_person: bool
    label: str
    limits: tuple[float, float] | None = None  # a questionnaire's scale


def _groups(results: Sequence[TrialResults], pool_people: bool) -> tuple[dict[Key, list[float]], dict[Key, int]]:
    values: dict[Key, list[float]] = defaultdict(list)
    invalid: dict[Key, int] = defaultdict(int)
    for r in results:
        if r.design["practice"]:
            continue
        for m in r.measures:
            human = ("person" if m.human else "") if pool_people else m.human
            key = (str(r.design["scenario"]), str(r.design["condition"]), human, m.measure)
            if r.design["valid"]:
                values[key].append(m.value)
            else:
                invalid[key] += 1
    return values, invalid


def summary_rows(results: Sequence[TrialResults], conditions: Sequence[str]) -> list[dict[str, Any]]:
    """One row per scenario x condition x person x measure, conditions in the study's order."""
    values, invalid = _groups(results, pool_people=False)
    rank = {c: i for i, c in enumerate(conditions)}
    rows = []
    for key in sorted(set(values) | set(invalid), key=lambda k: (k[0], rank.get(k[1], len(rank)), k[2], k[3])):
        v = values.get(key, [])
        rows.append(
            {
                **dict(zip(SUMMARY[:4], key)),
                "n": len(v),
                "n_invalid": invalid.get(key, 0),
                "mean": round(statistics.fmean(v), 4) if v else None,
                "sd": round(statistics.stdev(v), 4) if len(v) > 1 else None,
                "median": round(statistics.median(v), 4) if v else None,
            }
        )
    return rows


def panels(results: Sequence[TrialResults], questionnaires: Sequence[Questionnaire]) -> list[Panel]:
    """The main measures there are values of, then each questionnaire's overall scores (the raw TLX,
    the Godspeed series, a Likert questionnaire's mean), on their scale."""
    present = {(bool(m.human), m.measure) for r in results if not r.design["practice"] for m in r.measures}
    out = [Panel(m, person, label) for person, m, label in MAIN if (person, m) in present]
    for q in questionnaires:
        for scale, _ in q.scales:
            name = q.name if scale == q.name else f"{q.name}_{scale}"
            if q.name == "nasa_tlx" and scale != "raw":
                continue  # the subscales are in summary.csv
            if (True, name) in present:
                label = f"{q.title}: {scale}" if scale != q.name else q.title
                out.append(Panel(name, True, f"{label} ({q.minimum:g}-{q.maximum:g})", (q.minimum, q.maximum)))
    return out


def draw(results: Sequence[TrialResults], conditions: Sequence[str], questionnaires: Sequence[Questionnaire], out: Path, title: str) -> Path | None:
    """summary.png: for each main measure a panel per scenario (each on its own scale), per
    condition a box and the trials' points, n under each; None when there is nothing to draw."""
    shown = panels(results, questionnaires)
    if not shown:
        return None
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    values, _ = _groups(results, pool_people=True)
    scenarios = sorted({k[0] for k in values})
    cells = [(panel, scenario) for panel in shown for scenario in scenarios]
    cols = min(len(cells), len(scenarios) * max(1, 4 // len(scenarios)))
    rows = math.ceil(len(cells) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(3.9 * cols, 3.3 * rows), squeeze=False)
    rng = np.random.default_rng(0)
    for ax, (panel, scenario) in zip(axes.flat, cells):
        counts = []
        for i, condition in enumerate(conditions):
            v = values.get((scenario, condition, "person" if panel.per_person else "", panel.measure), [])
            counts.append(len(v))
            if v:
                ax.boxplot([v], positions=[i], widths=0.55, showfliers=False, medianprops={"color": "black"})
                ax.scatter(i + rng.uniform(-0.12, 0.12, len(v)), v, s=14, color=f"C{i % 10}", alpha=0.75, zorder=3)
        ticks = [c.replace("_", "\n") + f"\nn={n}" for c, n in zip(conditions, counts)]
        ax.set_xticks(range(len(conditions)), ticks, fontsize=8)
        ax.set_xlim(-0.6, len(conditions) - 0.4)
        ax.set_title(f"{panel.label}\n{scenario}", fontsize=9)
        if panel.limits is not None:
            low, high = panel.limits
            ax.set_ylim(low - 0.05 * (high - low), high + 0.05 * (high - low))
        ax.grid(axis="y", alpha=0.3)
    for ax in list(axes.flat)[len(cells) :]:
        ax.axis("off")
    fig.suptitle(f"{title}\nper condition: box = quartiles and median, whiskers to 1.5 IQR, points = trials (valid; practice left out)", fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 1 - 0.5 / (3.3 * rows)))  # (the title's two lines: about half an inch)
    try:
        with atomic.replacing(out) as tmp:
            fig.savefig(tmp, dpi=100, format="png")
    finally:
        plt.close(fig)
    return out
