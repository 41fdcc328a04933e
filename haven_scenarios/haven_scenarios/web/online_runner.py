"""One remote participant's `haven study run --web`, as `haven serve` runs it: a child process in its
own process group, whose printed page addresses say where the participant goes next.

The runner prints each page's address as it opens it (the consent and questionnaires before the
first trial, each trial's participant page and researcher console, the questionnaires after the
last: conduct/study_run.py); its output also goes to `online.log` in the participant's
folder, for the researcher (readable by its owner only: the addresses in it carry tokens). A page
the participant has finished (their browser came back from it) is never handed out again, though
its server may linger for a moment.
"""

from __future__ import annotations

import contextlib
import os
import re
import signal
import subprocess
import threading
import time
from collections.abc import Mapping, Sequence
from pathlib import Path
from urllib.parse import parse_qs, urlsplit

from haven_scenarios.web.access import TOKEN_PARAM
from haven_sim.common.atomic import open_secret_log
from haven_sim.runtime.process import die_with_parent

PAGE_LINE = re.compile(r"web: participant (\S+)(?: \([^)]*\))?: (\S+)$")
CONSOLE_LINE = re.compile(r"web: researcher console: (\S+)$")
NEXT_LINE = re.compile(r"haven study: next: (.+)$")
PAGE_GONE = ("haven: session in ", "haven study: next: ")  # the page printed before is over
STOP_WAIT_S = 30.0  # a stopped runner ends its trial cleanly within this, else it is killed
LOG = "online.log"  # in the participant's folder
# the runner's next page (it holds the session key): in its environment, not its command line
NEXT_URL_ENV = "HAVEN_NEXT_URL"


def token(url: str) -> str:
    return (parse_qs(urlsplit(url).query).get(TOKEN_PARAM) or [""])[0]


class Runner:
    """`haven study run ... --web` for one participant. Start it from a thread that lives as long as
    the server (the kernel stops it when the thread that started it ends: die_with_parent)."""

    def __init__(self, participant: str, argv: Sequence[str], env: Mapping[str, str], folder: Path) -> None:
        self.participant = participant
        self.page: str | None = None  # the participant's page now open
        self.console: str | None = None  # the trial's researcher console
        self.trial = ""  # what the runner said it runs now
        self.left: set[str] = set()  # tokens of pages the participant has finished
        self.last = ""  # its last line of output (why it ended, when it fails)
        self._lock = threading.Lock()
        folder.mkdir(parents=True, exist_ok=True)
        self.log = os.fdopen(open_secret_log(folder / LOG), "a", buffering=1)  # (its page addresses carry tokens: 0600)
        self.proc = subprocess.Popen(
            list(argv),
            env=dict(env),
            stdin=subprocess.DEVNULL,
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            text=True,
            start_new_session=True,  # (its nodes are its children: one group to stop)
            preexec_fn=die_with_parent(),
        )
        self.reader = threading.Thread(target=self._read, name=f"runner {participant}", daemon=True)
        self.reader.start()

    def _read(self) -> None:
        assert self.proc.stdout is not None
        for line in self.proc.stdout:
            self.log.write(line)
            line = line.rstrip("\n")
            with self._lock:
                self.last = line or self.last
                if line.startswith(PAGE_GONE):
                    self.page = None
                if m := PAGE_LINE.match(line):
                    # (the first human's page: theirs is h1's in a scenario for several)
                    self.page = self.page or m.group(2)
                elif m := CONSOLE_LINE.match(line):
                    self.console = m.group(1)
                elif m := NEXT_LINE.match(line):
                    self.trial, self.console = m.group(1), None
        self.log.close()

    def current_page(self) -> str | None:
        """The page to send the participant to now, if one is open they have not finished."""
        with self._lock:
            return self.page if self.page and token(self.page) not in self.left else None

    def finished_page(self, page_token: str) -> None:
        with self._lock:
            self.left.add(page_token)

    @property
    def code(self) -> int | None:
        return self.proc.poll()

    def stop(self, wait_s: float = STOP_WAIT_S) -> None:
        """As Ctrl-C: the trial ends cleanly ("interrupted": the same trial runs again on their
        return); killed if it has not ended within `wait_s` (its nodes then get SIGTERM from the
        kernel, so the recorder still closes its bag; the session, not finished, runs again)."""
        self.interrupt()
        self.finish(time.monotonic() + wait_s)

    def interrupt(self) -> None:
        """Ctrl-C to the runner, returning at once (`haven serve` stops every runner together)."""
        with contextlib.suppress(ProcessLookupError):
            if self.proc.poll() is None:
                os.killpg(self.proc.pid, signal.SIGINT)

    def finish(self, deadline: float) -> None:
        """Wait for the runner until `deadline` (time.monotonic()), then kill it."""
        try:
            self.proc.wait(max(0.0, deadline - time.monotonic()))
        except subprocess.TimeoutExpired:
            with contextlib.suppress(ProcessLookupError):
                os.killpg(self.proc.pid, signal.SIGKILL)
            self.proc.wait()
        self.reader.join(max(0.1, deadline - time.monotonic()))
