"""`haven serve`'s book of who is who: remote participants' panel ids and the design's participants.

A participant arrives with the id their recruitment panel appends to the link; they take the next
free participant of the study's design (p01, p02, ... in order: the design's `assignment` already
decides who of them takes which order) and keep it: a reload, a return the next day or a visit to
another server on the same study folder finds the same place. The book is `online.json` in the
study's folder, each change made under an OS lock (run/locks.py), so servers that share the
folder never hand out one place twice. A key per place (in the participant's session address) keeps
others out of it: the book holds every key, so it is readable by its owner only (0600, written whole,
never through a symbolic link: haven_sim/common/atomic.py).
"""

from __future__ import annotations

import json
import secrets
from collections.abc import Sequence
from dataclasses import asdict, dataclass
from datetime import UTC, datetime
from enum import StrEnum
from pathlib import Path

from haven_scenarios.record.participants import InstrumentBook
from haven_scenarios.record.progress import progress
from haven_scenarios.run.locks import FileLock
from haven_scenarios.study.names import check_name
from haven_scenarios.study.protocol import Study
from haven_scenarios.study.schedule import PlannedTrial
from haven_sim.common.atomic import write_secret

BOOK, BOOK_LOCK = "online.json", ".online.lock"  # in the study's folder


class Standing(StrEnum):
    """Where a participant's session is (the session page's `state`, the researcher's list)."""

    NEW = "new"  # joined, nothing asked yet
    STARTED = "started"  # some of it done, not running now
    WAITING = "waiting"  # in line for a place
    PREPARING = "preparing"  # their runner is opening the next page
    RUNNING = "running"  # on a page of their runner's
    DONE = "done"  # every trial and instrument
    DECLINED = "declined"  # did not consent
    FAILED = "failed"  # their runner did not get on: the researcher looks


LIVE = (Standing.RUNNING, Standing.PREPARING)


class Full(Exception):
    """Every participant of the design has been given to somebody."""


@dataclass(frozen=True)
class Seat:
    panel_id: str  # as the panel gave it
    participant: str  # the design's participant (p01, ...)
    key: str  # in their session address
    joined: str  # ISO time, UTC


class Seats:
    """The study folder's panel ids and their participants (shared by every server on the folder)."""

    def __init__(self, root: Path, participants: Sequence[str]) -> None:
        self.root, self.participants = root, tuple(participants)
        root.mkdir(parents=True, exist_ok=True)
        book = root / BOOK
        # (a book an earlier version left readable)
        if book.is_file() and not book.is_symlink() and book.stat().st_mode & 0o077:
            book.chmod(0o600)

    def _read(self) -> dict[str, Seat]:
        try:
            data = json.loads((self.root / BOOK).read_text())
        except FileNotFoundError:
            return {}
        return {pid: Seat(**s) for pid, s in data.items()}

    def _write(self, seats: dict[str, Seat]) -> None:
        text = json.dumps({pid: asdict(s) for pid, s in seats.items()}, indent=1) + "\n"
        write_secret(self.root / BOOK, text.encode())  # (whole or not at all: a reader never sees half a book)

    def join(self, panel_id: str) -> Seat:
        """Their place: the one they had, else the next free participant of the design. ValueError
        (one line) for an id that is not one; Full when every participant has been given."""
        check_name(panel_id, "participant")
        with FileLock(self.root / BOOK_LOCK, "haven serve").acquire(wait=True):
            seats = self._read()
            if panel_id in seats:
                return seats[panel_id]
            taken = {s.participant for s in seats.values()}
            free = [p for p in self.participants if p not in taken]
            if not free:
                raise Full(f"all {len(self.participants)} participants of the study have taken part or are taking part")
            seat = Seat(panel_id, free[0], secrets.token_urlsafe(16), datetime.now(UTC).isoformat(timespec="seconds"))
            seats[panel_id] = seat
            self._write(seats)
            return seat

    def by_panel_id(self, panel_id: str) -> Seat | None:
        return self._read().get(panel_id)

    def by_participant(self, participant: str) -> Seat | None:
        return next((s for s in self._read().values() if s.participant == participant), None)

    def all(self) -> list[Seat]:
        return sorted(self._read().values(), key=lambda s: s.participant)


def standing(study: Study, root: Path, participant: str, trials: Sequence[PlannedTrial]) -> Standing:
    """Where a participant stands, from the study folder alone: declined (consent), done (every
    trial and every instrument), or started / new."""
    book = InstrumentBook(root, participant)
    if book.declined():
        return Standing.DECLINED
    mine = [t for t in trials if t.participant == participant]
    instruments = study.instruments()
    if all(p.status == "done" for p in progress(root, mine)) and not book.pending(
        [*instruments.first, *instruments.after]
    ):
        return Standing.DONE
    return Standing.STARTED if (root / participant).is_dir() else Standing.NEW
