"""Questionnaire answers in a session folder: what the web node takes from a participant's page,
checks and writes (`ANSWERS_FILE`, `{"<human>": {"<questionnaire>": answers_record(...)}}`), and
what `haven run` reads back to know when the questionnaires are over.

A page sends one JSON object per questionnaire, `{"human": id, "questionnaire": name, "answers":
{item: value}}`; it is refused (ValueError, one line) unless it is the page's own participant's,
names a questionnaire of the session not yet answered, and answers every item on its scale. The
file is replaced atomically after each questionnaire (written beside it, then renamed), so an
interrupted session keeps every questionnaire that was submitted, whole.

Questionnaires follow a trial that started and was not called off (`aborted`). They are over when
the file holds every teleoperated participant's answers to every questionnaire and the recorder has
each `questionnaire_answered` event (so the bag has them too), or when the recorder has the
researcher's skip (an `intervention` event, action `skip_questionnaires`).
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from haven_scenarios.record.session import EVENTS_FILE, write_json
from haven_scenarios.study.questionnaires import (
    ANSWERS_FILE,
    Questionnaire,
    answers_record,
    item_order,
    resolve,
    trial_key,
)
from haven_scenarios.study.rules import EndReason
from haven_sim.common.events import Event, EventKind, Source, event

MAX_MESSAGE_BYTES = 64 * 1024  # a 100-item questionnaire's answers take about 3 KB
SKIP = "skip_questionnaires"  # the console's intervention action: the researcher ends the wait
# what is read of it
RECORDED = (EventKind.TRIAL_START, EventKind.TRIAL_END, EventKind.QUESTIONNAIRE_ANSWERED, EventKind.INTERVENTION)


def read_answers(folder: Path) -> dict[str, Any]:
    """The session's answers so far ({} if there are none or the file is unreadable)."""
    try:
        data = json.loads((folder / ANSWERS_FILE).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
    return data if isinstance(data, dict) else {}


def from_parameter(text: str) -> tuple[Questionnaire, ...]:
    """The web node's `questionnaires` parameter (JSON of the specs `resolve` takes); ValueError in one line."""
    try:
        specs = json.loads(text)
    except (ValueError, RecursionError):
        raise ValueError("parameter questionnaires: not JSON") from None
    if not isinstance(specs, list):
        raise ValueError("parameter questionnaires: must be a JSON list of built-in names and Likert mappings")
    return resolve(specs, "parameter questionnaires")


def _message(text: str) -> tuple[str, str, Any]:
    if len(text) > MAX_MESSAGE_BYTES:
        raise ValueError(f"questionnaire answers of {len(text)} bytes (at most {MAX_MESSAGE_BYTES})")
    try:
        msg = json.loads(text)
    except (ValueError, RecursionError):
        raise ValueError("questionnaire answers: not JSON") from None
    if not isinstance(msg, dict) or set(msg) != {"human", "questionnaire", "answers"}:
        raise ValueError("questionnaire answers: must be a JSON object with human, questionnaire and answers")
    human, name = msg["human"], msg["questionnaire"]
    if not isinstance(human, str) or not isinstance(name, str):
        raise ValueError("questionnaire answers: human and questionnaire must be strings")
    return human, name, msg["answers"]


class AnswerBook:
    """The answers of one session's teleoperated participants, kept in the session folder."""

    def __init__(self, folder: Path, humans: Sequence[str], questionnaires: Sequence[Questionnaire]) -> None:
        self.path = folder / ANSWERS_FILE
        self.humans = tuple(humans)
        self.questionnaires = {q.name: q for q in questionnaires}
        self.data: dict[str, Any] = read_answers(folder)  # (a web node started again goes on from the file)

    def take(self, page: str, text: str, now: float, answered_at: str) -> Event:
        """Check a page's message and write its answers; the event that says so. ValueError (one
        line) for a message that is not the page's own participant's, or answers that do not fit."""
        human, name, answers = _message(text)
        if human != page:
            raise ValueError(f"{page}'s page may not answer for {human[:40]!r}")
        q = self.questionnaires.get(name)
        if human not in self.humans or q is None:
            raise ValueError(f"no questionnaire {name[:40]!r} for {human} in this session")
        if name in self.data.get(human, {}):
            raise ValueError(f"{human} has answered {name} already")
        record = answers_record(q, answers, answered_at, item_order(q, trial_key(self.path.parent.name, human)))
        data = {**self.data, human: {**self.data.get(human, {}), name: record}}
        write_json(self.path, data)
        self.data = data
        scores, checked = record["scores"], record["answers"]
        return event(
            EventKind.QUESTIONNAIRE_ANSWERED,
            now,
            Source.WEB,
            by=human,
            questionnaire=name,
            scores=scores,
            answers=checked,
        )


def answered(folder: Path, humans: Sequence[str], names: Sequence[str]) -> dict[str, list[str]]:
    """For session.json: the questionnaires each participant answered, in the session's order."""
    data = read_answers(folder)
    return {h: [n for n in names if isinstance(data.get(h), dict) and n in data[h]] for h in humans}


def _recorded(folder: Path) -> list[dict[str, Any]]:
    try:
        lines = (folder / EVENTS_FILE).read_text(encoding="utf-8", errors="replace").splitlines()
    except OSError:
        return []
    out = []
    for line in lines:
        try:
            e = json.loads(line)
        except ValueError:
            continue  # (a line being written)
        if isinstance(e, dict) and e.get("type") in RECORDED:
            out.append(e)
    return out


def wanted(folder: Path) -> bool:
    """Whether the recorded trial is one that questionnaires follow (it started, and was neither
    aborted nor interrupted: such a trial runs again, and is asked about then)."""
    kinds = {e["type"]: e for e in _recorded(folder)}
    end = kinds.get(EventKind.TRIAL_END)
    return (
        EventKind.TRIAL_START in kinds
        and end is not None
        and end.get("reason") not in (EndReason.ABORTED, EndReason.INTERRUPTED)
    )


def over(folder: Path, humans: Sequence[str], names: Sequence[str]) -> str | None:
    """ "answered" once every answer is in the file and in the recording, "skipped" once the
    researcher's skip is recorded; None while the questionnaires go on."""
    events = [e for e in _recorded(folder) if e["type"] in (EventKind.QUESTIONNAIRE_ANSWERED, EventKind.INTERVENTION)]
    if any(e["type"] == EventKind.INTERVENTION and e.get("action") == SKIP for e in events):
        return "skipped"
    in_file = answered(folder, humans, names)
    recorded = {(e.get("by"), e.get("questionnaire")) for e in events if e["type"] == EventKind.QUESTIONNAIRE_ANSWERED}
    wanted = {(h, n) for h in humans for n in names}
    return "answered" if all(len(in_file[h]) == len(names) for h in humans) and wanted <= recorded else None
