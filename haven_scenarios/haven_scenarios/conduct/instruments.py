"""`haven study run`: the instruments before the first trial and after the last (study/instruments.py).

Asked once per participant, at the terminal (a researcher reads them out or hands over the
keyboard), or with `--web` in the participant's page (web/instrument_server.py); answers go to the
participant's instruments.json (record/participants.py), so a run stopped half-way asks only what
is missing. Consent comes first; no agreement, no trial. A `--batch` pilot's simulated
participants are asked nothing: each instrument is stored as not asked, never invented.
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Sequence
from datetime import UTC, datetime
from pathlib import Path
from typing import Any, Protocol

from haven_scenarios.record.participants import InstrumentBook
from haven_scenarios.study.questionnaires import CHOICE, TEXT, Item, Questionnaire, in_order, item_order
from haven_sim.runtime.process import interrupted, on_stop_signals

BATCH_REASON = "simulated participant (--batch pilot)"
Read = Callable[[str], str]
Write = Callable[[str], None]


def now_utc() -> str:
    return datetime.now(UTC).isoformat(timespec="seconds")


def order_key(study: str, participant: str) -> str:
    """What seeds a participant's item order for the study-level instruments."""
    return f"{study}/{participant}/study"


def _choices(q: Questionnaire, item: Item) -> tuple[str, range]:
    if item.kind == CHOICE:
        return "  ".join(f"{k}: {o}" for k, o in enumerate(item.options, 1)), range(1, len(item.options) + 1)
    values = range(q.minimum, q.maximum + 1, q.step)
    return f"{q.minimum} = {item.low} .. {q.maximum} = {item.high}", values


def ask_item(q: Questionnaire, item: Item, k: int, read: Read, write: Write) -> int | str:
    """One item until it has a valid answer (EOFError when nobody is at the terminal)."""
    if item.kind == TEXT:
        return read(f"  {k}/{len(q.items)} {item.text} (Enter to leave it empty): ").strip()[:100]
    shown, values = _choices(q, item)
    text = item.text if not q.differential else f"{item.low} - {item.high}"
    while True:
        answer = read(f"  {k}/{len(q.items)} {text}\n      {shown}: ").strip()
        if answer.lstrip("-").isdigit() and int(answer) in values:
            return int(answer)
        write(f"      please type one of {values.start}..{values.stop - 1}")


def ask(q: Questionnaire, read: Read, write: Write) -> dict[str, Any]:
    """Every item of `q` in the order given; a ranking again until each rank is used once."""
    write(f"\n== {q.title}" + (f"  ({q.source})" if q.source else ""))
    write(q.instructions)
    while True:
        prompt = ""
        answers: dict[str, Any] = {}
        for k, item in enumerate(q.items, 1):
            if item.prompt and item.prompt != prompt:
                write(item.prompt)
                prompt = item.prompt
            answers[item.id] = ask_item(q, item, k, read, write)
        if not q.distinct or len(set(answers.values())) == len(answers):
            return answers
        write(f"Each of {q.minimum}..{q.maximum} once, please: again.")


def terminal_asker(read: Read | None = None, write: Write | None = None) -> Callable[[Questionnaire], dict[str, Any]]:
    """Asks at this terminal (`input`, `print`) unless told otherwise."""
    return lambda q: ask(q, read or input, write or print)


def run_instruments(
    book: InstrumentBook, qs: Sequence[Questionnaire], key: str, asker: Callable[[Questionnaire], dict[str, Any]] | None
) -> bool:
    """Ask what is pending of `qs` (None: a batch pilot, each stored as not asked); False when the
    participant declined consent (nothing after it is asked)."""
    for q in book.pending(qs):
        if asker is None:
            book.not_asked(q, BATCH_REASON)
            continue
        order = item_order(q, key)
        book.take(q, asker(in_order(q, order)), now_utc(), order)
        if book.declined():
            return False
    return not book.declined()


class Served(Protocol):
    """Where the instruments page is served (a study run's options)."""

    @property
    def host(self) -> str: ...
    @property
    def port(self) -> int: ...
    @property
    def tls_cert(self) -> str | None: ...
    @property
    def tls_key(self) -> str | None: ...
    @property
    def next_url(self) -> str | None: ...


DONE_BEFORE = "Thank you. Please wait: the researcher starts the first trial."
DONE_AFTER = "Thank you for taking part: the study is over."


def ask_in_browser(book: InstrumentBook, qs: Sequence[Questionnaire], key: str, where: Served, first: bool) -> bool:
    """The participant answers what is pending of `qs` in their browser (web/instrument_server.py):
    prints the address, returns once all is answered (False: consent declined). `where`: the
    study run's host, port and TLS files. ValueError (one line) if the address cannot be served; Ctrl-C ends the wait
    (KeyboardInterrupt)."""
    from haven_scenarios.web.instrument_server import InstrumentServer  # (only with --web)
    from haven_scenarios.web.tls import server_context, tls_files

    files = tls_files(where.tls_cert, where.tls_key)
    tls = server_context(*files) if files else None
    server = InstrumentServer(
        where.host, where.port, book, qs, key, DONE_BEFORE if first else DONE_AFTER, tls, where.next_url or ""
    )
    server.start()
    # Every stop signal ends the wait, as it ends `haven run`: also where the shell started this
    # in the background with SIGINT ignored (Python then leaves Ctrl-C ignored; the wait hung).
    try:
        with on_stop_signals(interrupted):
            when = "before the first trial" if first else "after the last trial"
            print(
                f"web: participant {book.path.parent.name} ({when}: "
                f"{', '.join(q.name for q in book.pending(qs))}): {server.url}",
                flush=True,
            )
            server.finished.wait()
    finally:
        server.stop()
    return not book.declined()


def say_declined(participant: str, folder: Path) -> None:
    print(
        f"haven study: participant {participant} did not agree to take part: "
        f"no trial is run (their answer is in {folder})",
        file=sys.stderr,
    )
