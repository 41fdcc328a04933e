"""The study report's codebook (codebook.csv and codebook.json beside study_long.csv): one row per
measure in the long table, with its unit, definition, source and where its formula is, so a reader
of the data needs nothing else. Metrics come from `metric_table` (ours, HuNavSim's, the installed
plugins' documented columns), questionnaire scores from the study's questionnaires."""

from __future__ import annotations

import json
from collections.abc import Iterable, Sequence
from dataclasses import asdict, dataclass
from pathlib import Path

from haven_scenarios.record import metric_table
from haven_scenarios.record.report import write_table
from haven_scenarios.study.questionnaires import Questionnaire, registered
from haven_sim.common import atomic

FIELDS = ("measure", "per_person", "wide_column", "unit", "definition", "source", "formula")
SCORING = "haven_scenarios/study/questionnaires.py:score"


@dataclass(frozen=True)
class Entry:
    measure: str  # as in study_long.csv's `measure`
    per_person: bool  # the long table's `human` is a person's id
    wide_column: str  # as in study_wide.csv (`<h>_` for each person)
    unit: str
    definition: str
    source: str
    formula: str


def _scores(q: Questionnaire) -> dict[str, tuple[str, str, str, str]]:
    """Each of a questionnaire's score names -> (unit, definition, source, formula), as `score` names them."""
    reversed_ = {i.id for i in q.items if i.reverse}
    source = str(getattr(q, "citation", "") or f"{q.title} (see haven_scenarios/study/questionnaires.py)")
    out = {}
    for scale, ids in q.scales:
        key = q.name if scale == q.name else f"{q.name}_{scale}"
        turned = [i for i in ids if i in reversed_]
        how = f"; reverse-scored ({q.minimum}+{q.maximum}-answer): {', '.join(turned)}" if turned else ""
        definition = f"{q.title}: mean of the {len(ids)} item(s) of '{scale}' ({', '.join(ids)}), answered {q.minimum}..{q.maximum}{how}"
        out[key] = (f"points {q.minimum}-{q.maximum}", definition, source, SCORING)
    return out


class Codebook:
    """What each long-table measure is: metrics (by name, per-person ones by their `<h>_` pattern)
    and the given questionnaires' scores (the registered ones too)."""

    def __init__(self, questionnaires: Iterable[Questionnaire] = ()) -> None:
        self.metrics = {r[0]: r for r in metric_table.rows()}
        self.scores: dict[str, tuple[str, str, str, str]] = {}
        for q in (*registered().values(), *questionnaires):
            self.scores.update(_scores(q))

    def entry(self, human: str, measure: str) -> Entry:
        """The row of one (human, measure) of the long table; an undocumented one says so."""
        if human:
            name = metric_table.pattern(f"{human}_{measure}", [human])
            if name in self.metrics:
                _, unit, definition, source, formula = self.metrics[name]
                return Entry(measure, True, name, unit, definition, source, formula)
            if measure in self.scores:
                return Entry(measure, True, f"<h>_{measure}", *self.scores[measure])
            return Entry(measure, True, f"<h>_{measure}", "", "undocumented (no codebook row)", "", "")
        if measure in self.metrics:
            _, unit, definition, source, formula = self.metrics[measure]
            return Entry(measure, False, measure, unit, definition, source, formula)
        return Entry(measure, False, measure, "", "undocumented (no codebook row)", "", "")

    def unit(self, human: str, measure: str) -> str:
        return self.entry(human, measure).unit

    def entries(self, long: Sequence[dict[str, object]]) -> list[Entry]:
        """One entry per measure present in the long table's rows, in first-seen order."""
        seen = dict.fromkeys((bool(r["human"]), str(r["measure"]), str(r["human"])) for r in long)
        out: dict[tuple[bool, str], Entry] = {}
        for per_person, measure, human in seen:
            out.setdefault((per_person, measure), self.entry(human, measure))
        return list(out.values())


def write(folder: Path, entries: Sequence[Entry]) -> None:
    """codebook.csv and codebook.json, each written whole (a reader never sees half a file)."""
    rows = [asdict(e) for e in entries]
    write_table(folder / "codebook.csv", rows, FIELDS)
    with atomic.replacing(folder / "codebook.json") as tmp:
        tmp.write_text(json.dumps(rows, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
