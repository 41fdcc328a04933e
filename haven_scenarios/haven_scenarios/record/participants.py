"""A participant's answers before and after the study, and the study's one-row-per-participant table.

`<study folder>/<participant>/instruments.json` holds, per instrument (study/instruments.py), what
`answers_record` makes of the answers (answers, scores, when, the items' order), and for consent
also `agreed`; or `{"not_asked": reason}` for a simulated participant of a `--batch` pilot, whose
answers are not invented. It is replaced whole after each instrument, so a run stopped half-way
keeps what was answered and asks the rest next time.

`participants.csv` (`haven study report`): one row per participant: `consent` (yes / no / not
asked / empty while not yet asked) and when, each demographic answer as its option's words, the
NARS subscale sums, each condition's preference rank, any other instrument's scores, and
`not_asked` (the instruments a simulated participant was not asked; their cells are empty). Its
columns' definitions are `codebook_rows` (name, unit, definition, source), as the metric codebook's.
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from haven_scenarios.record.report import write_table
from haven_scenarios.record.session import write_json
from haven_scenarios.study.instruments import CONSENT, StudyInstruments, agreed
from haven_scenarios.study.questionnaires import (
    CHOICE,
    Questionnaire,
    answers_record,
    codebook_rows as questionnaire_rows,
)

INSTRUMENTS_FILE = "instruments.json"
PARTICIPANTS_CSV = "participants.csv"
NOT_ASKED = "not_asked"


class InstrumentBook:
    """One participant's instruments.json."""

    def __init__(self, root: Path, participant: str) -> None:
        self.path = root / participant / INSTRUMENTS_FILE
        self.data = read_instruments(root, participant)

    def pending(self, qs: Sequence[Questionnaire]) -> list[Questionnaire]:
        """The instruments of `qs` not answered (nor marked not asked) yet, in order."""
        return [q for q in qs if q.name not in self.data]

    def take(
        self, q: Questionnaire, answers: Any, answered_at: str, order: Sequence[str] | None = None
    ) -> dict[str, Any]:
        """Check and store one instrument's answers (ValueError, one line, if they do not fit)."""
        if q.name in self.data:
            raise ValueError(f"{q.name} is answered already")
        record = answers_record(q, answers, answered_at, order)
        if q.name == CONSENT:  # (with the text agreed to: a study file may change later)
            record |= {"agreed": agreed(record["answers"]), "text": q.instructions}
        self._put(q.name, record)
        return record

    def not_asked(self, q: Questionnaire, reason: str) -> None:
        self._put(q.name, {NOT_ASKED: reason})

    def declined(self) -> bool:
        """Whether the participant answered the consent question with no."""
        c = self.data.get(CONSENT)
        return isinstance(c, dict) and c.get("agreed") is False

    def _put(self, name: str, record: dict[str, Any]) -> None:
        data = {**self.data, name: record}
        self.path.parent.mkdir(parents=True, exist_ok=True)
        write_json(self.path, data)
        self.data = data


def read_instruments(root: Path, participant: str) -> dict[str, Any]:
    """A participant's instruments so far ({} if none or unreadable)."""
    try:
        data = json.loads((root / participant / INSTRUMENTS_FILE).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
    return data if isinstance(data, dict) else {}


def _columns(q: Questionnaire) -> list[str]:
    if q.name == CONSENT:
        return ["consent", "consent_at"]
    if not q.scales:  # (demographics: the answers themselves)
        return [f"{q.name}_{i.id}" for i in q.items]
    return [q.name if s == q.name else f"{q.name}_{s}" for s, _ in q.scales]


def columns(instruments: StudyInstruments) -> list[str]:
    return ["participant", *(c for q in (*instruments.first, *instruments.after) for c in _columns(q)), NOT_ASKED]


def _values(q: Questionnaire, record: Any) -> dict[str, Any]:
    if not isinstance(record, dict):
        return {}
    if NOT_ASKED in record:  # (numbers stay empty, so the columns read as numbers)
        return {"consent": "not asked"} if q.name == CONSENT else {}
    if q.name == CONSENT:
        return {"consent": "yes" if record.get("agreed") else "no", "consent_at": record.get("answered_at", "")}
    if not q.scales:
        answers = record.get("answers", {})
        out = {}
        for i in q.items:
            v = answers.get(i.id, "")
            out[f"{q.name}_{i.id}"] = (
                i.options[v - 1] if i.kind == CHOICE and isinstance(v, int) and 1 <= v <= len(i.options) else v
            )
        return out
    return {k: v for k, v in record.get("scores", {}).items() if k in _columns(q)}


def participant_rows(root: Path, participants: Sequence[str], instruments: StudyInstruments) -> list[dict[str, Any]]:
    """One row per participant (empty cells for what is not answered yet)."""
    rows = []
    for p in participants:
        data = read_instruments(root, p)
        row: dict[str, Any] = dict.fromkeys(columns(instruments), "") | {"participant": p}
        for q in (*instruments.first, *instruments.after):
            row |= _values(q, data.get(q.name))
        skipped = [
            q.name
            for q in (*instruments.first, *instruments.after)
            if isinstance(data.get(q.name), dict) and NOT_ASKED in data[q.name]
        ]
        row[NOT_ASKED] = " ".join(skipped)
        rows.append(row)
    return rows


def write_participants(
    out: Path, root: Path, participants: Sequence[str], instruments: StudyInstruments
) -> list[dict[str, Any]]:
    """participants.csv in `out`; its rows."""
    rows = participant_rows(root, participants, instruments)
    write_table(out / PARTICIPANTS_CSV, rows, columns(instruments))
    return rows


def codebook_rows(instruments: StudyInstruments) -> list[tuple[str, str, str, str]]:
    """participants.csv's columns as codebook rows (name, unit, definition, source)."""
    rows: list[tuple[str, str, str, str]] = [("participant", "", "the participant's id in the study", "")]
    for q in (*instruments.first, *instruments.after):
        if q.name == CONSENT:
            rows += [
                (
                    "consent",
                    "",
                    "yes: agreed to the study's consent text; no: declined (no trial run)",
                    "the study file",
                )
            ]
            rows += [("consent_at", "UTC", "when the consent was answered (ISO 8601)", "")]
        elif not q.scales:
            for i in q.items:
                kind = f"one of: {'; '.join(i.options)}" if i.kind == CHOICE else "free text (optional)"
                rows.append((f"{q.name}_{i.id}", "", f"{i.text} ({kind})", q.source))
        else:
            rows += questionnaire_rows(q)
    return [
        *rows,
        (
            NOT_ASKED,
            "",
            "the instruments not asked (a --batch pilot's simulated participant): their columns are empty",
            "",
        ),
    ]


def summary_line(rows: Sequence[dict[str, Any]], instruments: StudyInstruments) -> str:
    """What the report says of participants.csv: who consented, and each instrument's count of answers."""
    parts = []
    if instruments.consent:
        said = [r["consent"] for r in rows]
        parts.append(f"consent: {said.count('yes')} yes, {said.count('no')} no, {said.count('not asked')} not asked")
    for q in (*instruments.before, *instruments.after):
        first = _columns(q)[0]
        answered = sum(1 for r in rows if r[first] != "" and q.name not in r[NOT_ASKED].split())
        parts.append(f"{q.name}: {answered}/{len(rows)} answered")
    return "; ".join(parts)
