"""Exclusive OS file locks that say who holds them: one runner per study participant, one HAVEN
suite per ROS domain on this machine.

The lock is the `filelock` library's (`flock(2)` on a small file: the kernel drops it when the
holder's process ends in any way, a crash or SIGKILL, so a lock is never left stale). The file is
kept on release (deleting one while another process waits on it would let two holders in at once),
and the holder writes who it is into it (pid, command, when), which a refused taker reads back to
say who is in the way.
"""

from __future__ import annotations

import json
import os
import sys
import time
from dataclasses import dataclass
from pathlib import Path
from types import TracebackType

import filelock


@dataclass(frozen=True)
class Holder:
    """Who holds a lock, as its holder wrote it (fields may be missing in a file from elsewhere)."""

    pid: int | None
    command: str
    since: str

    def describe(self) -> str:
        parts = [f"pid {self.pid}" if self.pid else "", self.command, f"since {self.since}" if self.since else ""]
        return ", ".join(p for p in parts if p) or "another process"


class Locked(Exception):
    """The lock is held by another process (`holder` says who, as far as it is known)."""

    def __init__(self, path: Path, holder: Holder) -> None:
        super().__init__(f"{path}: held by {holder.describe()}")
        self.path, self.holder = path, holder


class FileLock:
    """`with FileLock(path, what)`: held until the block ends or the process does; `Locked` when
    another process holds it. OSError when the file cannot be opened at all."""

    def __init__(self, path: Path, what: str = "") -> None:
        self.path, self.what = Path(path), what or command_line()
        self._lock = filelock.FileLock(
            self.path, thread_local=False, preserve_lock_file=True, on_acquired=self._say_who
        )

    def _say_who(self, fd: int) -> None:
        info = {"pid": os.getpid(), "command": self.what[:200], "since": time.strftime("%Y-%m-%d %H:%M:%S")}
        try:  # (a lock file another user made may not be writable: the lock holds all the same)
            os.ftruncate(fd, 0)
            os.pwrite(fd, (json.dumps(info) + "\n").encode(), 0)
        except OSError:
            pass

    @property
    def held(self) -> bool:
        return self._lock.is_locked

    def acquire(self, wait: bool = False) -> FileLock:
        """Take the lock (`wait`: block until the holder lets go, for short critical sections)."""
        self.path.parent.mkdir(parents=True, exist_ok=True)
        try:
            self._lock.acquire(timeout=-1, blocking=wait)
        except filelock.Timeout:
            raise Locked(self.path, read_holder(self.path)) from None
        return self

    def release(self) -> None:
        if self._lock.is_locked:
            self._lock.release(force=True)

    def __enter__(self) -> FileLock:
        return self if self.held else self.acquire()

    def __exit__(self, et: type[BaseException] | None, ev: BaseException | None, tb: TracebackType | None) -> None:
        self.release()


def command_line() -> str:
    """This process's command as a user typed it (`python -m haven_scenarios ...` is `haven ...`)."""
    program = Path(sys.argv[0]).name if sys.argv and sys.argv[0] else "python"
    program = "haven" if program in ("__main__.py", "cli.py", "haven") else program
    return " ".join([program, *sys.argv[1:]])


# a holder writes who it is just after it takes the lock: a taker that finds the file empty waits this long for it
HOLDER_WAIT_S = 0.5


def read_holder(path: Path) -> Holder:
    d = None
    deadline = time.monotonic() + HOLDER_WAIT_S
    while True:
        try:
            text = path.read_text(encoding="utf-8", errors="replace")[:1000]
        except OSError:
            break
        if text.strip() or time.monotonic() >= deadline:
            try:
                d = json.loads(text)
            except ValueError:
                d = None
            break
        time.sleep(0.01)
    if not isinstance(d, dict):
        return Holder(None, "", "")
    pid = d.get("pid")
    return Holder(
        pid if isinstance(pid, int) and not isinstance(pid, bool) else None,
        str(d.get("command", ""))[:200],
        str(d.get("since", ""))[:40],
    )
