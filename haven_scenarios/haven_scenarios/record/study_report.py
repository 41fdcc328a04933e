"""A study's report from its finished trials: the long and wide tables, the codebook, the summary
and its picture, order effects, participants and mixed models (`haven study report`, api.report)."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from haven_scenarios.record import codebook
from haven_scenarios.record.mixed_model import MIXED, fit_counts, model_rows
from haven_scenarios.record.order_table import ORDER_EFFECTS, order_rows
from haven_scenarios.record.participants import summary_line, write_participants
from haven_scenarios.record.progress import differences, progress, stored
from haven_scenarios.record.report import write_table
from haven_scenarios.record.study_summary import SUMMARY, draw, panels, summary_rows
from haven_scenarios.record.study_table import DESIGN, LONG, TrialResults, long_rows, trial_results, wide_rows
from haven_scenarios.study.protocol import Study
from haven_scenarios.study.questionnaires import Questionnaire
from haven_scenarios.study.schedule import (
    schedule,
)


@dataclass(frozen=True)
class Report:
    """What `haven study report` wrote."""

    # study_long.csv, codebook, study_wide.csv, summary.csv, order_effects.csv, mixed_models.csv, summary.png
    folder: Path
    trials_done: int
    trials: int
    counts: str  # participants, trials, practice trials, flagged not valid
    picture: str  # the summary picture(s) drawn ("": none)
    study_changed: bool  # the study file changed since the first run
    participants: str = ""  # participants.csv's summary line ("" when the study asks no instruments)
    models: tuple[int, int, int] = (0, 0, 0)  # mixed models singular, not converged, fitted (mixed_models.csv)


def write_report(study: Study, root: Path, out: Path | None = None) -> Report:
    """The study's tables, summary picture and mixed models from its finished trials; ValueError (one line) when
    there are none or they cannot be written."""
    questionnaires = study.resolved_questionnaires()
    done = progress(root, schedule(study))
    results = [r for r in (trial_results(t) for t in done) if r is not None]
    if not results:
        raise ValueError(
            f"no finished trials of study {study.name} in {root} (see `haven study status {study.name} --dir {root}`)"
        )
    out = out if out is not None else root / "report"
    try:
        book = codebook.Codebook(questionnaires)
        long = long_rows(results, book.unit)
        write_table(out / "study_long.csv", long, LONG)
        instruments = study.instruments()
        codebook.write(out, [*book.entries(long), *(codebook.participants(instruments) if instruments else ())])
        write_table(out / "study_wide.csv", wide_rows(results), DESIGN)
        conditions = [c.name for c in study.conditions]
        picture = _summaries(results, conditions, questionnaires, out, study.name)
        write_table(out / "order_effects.csv", order_rows(results, conditions), ORDER_EFFECTS)
        said = (
            summary_line(write_participants(out, root, study.participants, instruments), instruments)
            if instruments
            else ""
        )
        models = model_rows(results, [(p.measure, p.per_person) for p in panels(results, questionnaires)], conditions)
        write_table(out / "mixed_models.csv", models, MIXED)
    except OSError as e:
        raise ValueError(f"--out {out}: cannot write the report: {e.strerror or e}") from None
    old = stored(root)
    changed = old is not None and bool(differences(old["study"], study.describe()))
    return Report(out, len(results), len(done), _counts(results), picture, changed, said, fit_counts(models))


def _summaries(
    results: list[TrialResults], conditions: list[str], questionnaires: Sequence[Questionnaire], out: Path, name: str
) -> str:
    """summary.csv and summary.png; when the robot varies, per robot: summary.csv with a `robot`
    column first, and summary_<robot>.png each. The pictures drawn ("": none)."""
    robots = list(dict.fromkeys(str(r.design["robot"]) for r in results))
    if len(robots) == 1:
        write_table(out / "summary.csv", summary_rows(results, conditions), SUMMARY)
        return (
            "summary.png"
            if draw(results, conditions, questionnaires, out / "summary.png", f"{name}: {_counts(results)}")
            else ""
        )
    rows, drawn = [], []
    for robot in robots:
        mine = [r for r in results if r.design["robot"] == robot]
        rows += [{"robot": robot, **row} for row in summary_rows(mine, conditions)]
        if (
            draw(
                mine,
                conditions,
                questionnaires,
                out / f"summary_{robot}.png",
                f"{name}, robot {robot}: {_counts(mine)}",
            )
            is not None
        ):
            drawn.append(f"summary_{robot}.png")
    write_table(out / "summary.csv", rows, ("robot", *SUMMARY))
    return ", ".join(drawn)


def _counts(results: list[TrialResults]) -> str:
    practice = sum(1 for r in results if r.design["practice"])
    invalid = sum(1 for r in results if not r.design["valid"])
    participants = len({r.design["participant"] for r in results})
    return (
        f"{participants} participant(s), {len(results) - practice} trials and {practice} "
        f"practice trial(s) (left out of the summary), {invalid} flagged not valid"
    )
