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

SUMMARY = ("scenario", "condition", "human", "measure", "n", "n_invalid", "mean", "sd", "median")
# The main measures of the figure: (per person?, measure, axis label); questionnaire scores follow.
MAIN = (
    (False, "min_human_distance_m", "closest approach of the robot (m)"),
    (False, "robot_time_to_finish_s", "robot's time to finish its task (s)"),
    (True, "time_not_moving_s", "person standing still (s)"),
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
    """summary.png: a panel per main measure, per condition a box and the trials' points for each
    scenario, n under each; None when there is nothing to draw."""
    shown = panels(results, questionnaires)
    if not shown:
        return None
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    values, _ = _groups(results, pool_people=True)
    scenarios = sorted({k[0] for k in values})
    cols = min(3, len(shown))
    rows = math.ceil(len(shown) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(4.6 * cols, 3.6 * rows), squeeze=False)
    rng = np.random.default_rng(0)
    colors = plt.get_cmap("tab10").colors
    width = 0.8 / max(len(scenarios), 1)
    for ax, panel in zip(axes.flat, shown):
        for j, scenario in enumerate(scenarios):
            for i, condition in enumerate(conditions):
                v = values.get((scenario, condition, "person" if panel.per_person else "", panel.measure), [])
                x = i - 0.4 + width * (j + 0.5)
                if v:
                    ax.boxplot([v], positions=[x], widths=width * 0.8, showfliers=False, medianprops={"color": "black"})
                    ax.scatter(x + rng.uniform(-width / 5, width / 5, len(v)), v, s=12, color=colors[j % 10], alpha=0.7, zorder=3)
                ax.annotate(f"n={len(v)}", (x, 0), xycoords=("data", "axes fraction"), xytext=(0, 2), textcoords="offset points",
                            ha="center", va="bottom", fontsize=7, color=colors[j % 10])  # fmt: skip
        ax.set_xticks(range(len(conditions)), [c.replace("_", " ") for c in conditions], fontsize=8)
        ax.set_xlim(-0.6, len(conditions) - 0.4)
        ax.set_title(panel.label, fontsize=9)
        if panel.limits is not None:
            ax.set_ylim(panel.limits[0] - 0.05 * (panel.limits[1] - panel.limits[0]), panel.limits[1] * 1.02)
        ax.grid(axis="y", alpha=0.3)
    for ax in list(axes.flat)[len(shown) :]:
        ax.axis("off")
    handles = [plt.Line2D([], [], marker="o", ls="", color=colors[j % 10], label=s) for j, s in enumerate(scenarios)]
    fig.legend(handles=handles, loc="upper right", title="scenario", fontsize=8, title_fontsize=8)
    fig.suptitle(f"{title}\nper condition: box = quartiles and median, points = trials (valid, practice left out), n = trials", fontsize=10)
    fig.tight_layout(rect=(0, 0, 0.9 if len(scenarios) > 1 else 1, 0.95))
    fig.savefig(out, dpi=110)
    plt.close(fig)
    return out
