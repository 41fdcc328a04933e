"""The study report's codebook (codebook.csv and codebook.json beside study_long.csv): one row per
measure in the long table, and per column of participants.csv, with its unit, definition, source
and where its formula is, so a reader of the data needs nothing else. Metrics come from
`metric_table` (ours, HuNavSim's, the installed plugins' documented columns), questionnaire scores
from the questionnaires themselves (`questionnaires.codebook_rows`), participants.csv's columns from
`record.participants`."""

from __future__ import annotations

import json
from collections.abc import Iterable, Sequence
from dataclasses import asdict, dataclass
from pathlib import Path

from haven_scenarios.record import metric_table
from haven_scenarios.record.participants import PARTICIPANTS_CSV, codebook_rows as participant_rows
from haven_scenarios.record.report import write_table
from haven_scenarios.study.instruments import StudyInstruments
from haven_scenarios.study.questionnaires import Questionnaire, codebook_rows, registered
from haven_sim.common import atomic

FIELDS = ("table", "measure", "per_person", "wide_column", "unit", "definition", "source", "formula")
LONG_CSV = "study_long.csv"
SCORING = "haven_scenarios/study/questionnaires.py:score"


@dataclass(frozen=True)
class Entry:
    table: str  # the report's file the measure is in: study_long.csv (and study_wide.csv) or participants.csv
    measure: str  # as in study_long.csv's `measure`
    per_person: bool  # the long table's `human` is a person's id
    wide_column: str  # as in study_wide.csv (`<h>_` for each person)
    unit: str
    definition: str
    source: str
    formula: str


def _scores(q: Questionnaire) -> dict[str, tuple[str, str, str, str]]:
    """Each of a questionnaire's score names -> (unit, definition, source, formula), as `score` names them."""
    return {name: (unit, definition, source or q.title, SCORING) for name, unit, definition, source in codebook_rows(q)}


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
                return Entry(LONG_CSV, measure, True, name, unit, definition, source, formula)
            if measure in self.scores:
                return Entry(LONG_CSV, measure, True, f"<h>_{measure}", *self.scores[measure])
            return Entry(LONG_CSV, measure, True, f"<h>_{measure}", "", "undocumented (no codebook row)", "", "")
        if measure in self.metrics:
            _, unit, definition, source, formula = self.metrics[measure]
            return Entry(LONG_CSV, measure, False, measure, unit, definition, source, formula)
        return Entry(LONG_CSV, measure, False, measure, "", "undocumented (no codebook row)", "", "")

    def unit(self, human: str, measure: str) -> str:
        return self.entry(human, measure).unit

    def entries(self, long: Sequence[dict[str, object]]) -> list[Entry]:
        """One entry per measure present in the long table's rows, in first-seen order."""
        seen = dict.fromkeys((bool(r["human"]), str(r["measure"]), str(r["human"])) for r in long)
        out: dict[tuple[bool, str], Entry] = {}
        for per_person, measure, human in seen:
            out.setdefault((per_person, measure), self.entry(human, measure))
        return list(out.values())


def participants(instruments: StudyInstruments) -> list[Entry]:
    """participants.csv's columns (consent, demographics, the before- and after-study scores)."""
    where = "haven_scenarios/record/participants.py"
    rows = participant_rows(instruments)
    return [
        Entry(PARTICIPANTS_CSV, name, False, name, unit, definition, source, where)
        for name, unit, definition, source in rows
    ]


def write(folder: Path, entries: Sequence[Entry]) -> None:
    """codebook.csv and codebook.json, each written whole (a reader never sees half a file)."""
    rows = [asdict(e) for e in entries]
    write_table(folder / "codebook.csv", rows, FIELDS)
    with atomic.replacing(folder / "codebook.json") as tmp:
        tmp.write_text(json.dumps(rows, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
