"""`haven serve`: one server that runs a study for remote participants.

A participant opens the study's link with the id their panel appends (`/?participant=ID`), reads
the welcome and the consent text, and joins (a POST from that page's button: opening the link only
shows it): they take the next participant of the design (web/online_seats.py), as far as the
study's rules for joining allow (web/online_gate.py: one place per browser and a few per network
address, signed links, an allow-list), and land on their session page, which takes them from page
to page as their own `haven study run --web` (web/online_runner.py: its own processes and ROS
domain) opens them: consent and questionnaires, each trial (they press Start themselves), the
questionnaires after it, and at the end the study's completion code or redirect (study/online.py).
At most `capacity` runners at once; who arrives beyond that waits on their session page, first come
first served. A reload, a closed tab or a return later finds the same place: a trial that did not
finish runs again. The researcher's list (`/console`, its own token) shows every session.
"""

from __future__ import annotations

import os
import sys
import threading
import time
from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any
from urllib.parse import parse_qs, quote

from aiohttp import web

from haven_scenarios.run.domains import DomainRange
from haven_scenarios.study.presence import OnDisconnect
from haven_scenarios.study.protocol import Study
from haven_scenarios.study.schedule import PlannedTrial
from haven_scenarios.web import online_pages as pages
from haven_scenarios.web.access import TOKEN_PARAM, new_token, token_ok
from haven_scenarios.web.front_door import STATIC, address_for_others
from haven_scenarios.web.online_gate import (
    SIG_PARAM,
    TOO_MANY,
    Gate,
    Refusal,
    cookie_place,
    same_origin,
    set_place_cookie,
)
from haven_scenarios.web.online_runner import LOG, NEXT_URL_ENV, Runner
from haven_scenarios.web.online_seats import LIVE, Full, Seat, Seats, Standing, standing
from haven_scenarios.web.serving import (
    HTML,
    PageServer,
    Routes,
    read_body,
    redirect,
    reply,
    reply_json,
    set_token_cookie,
)

DEFAULT_CAPACITY = 2  # live trials at once: what a 2-core machine holds at a 100 ms p95 (bench/RESULTS.md)
MAX_STARTS = 5  # a participant's runner starts again this often at most (their trial did not finish)
GONE_S = 15.0  # a waiting participant whose page has not asked for this long has left the queue
TICK_S = 0.5
STOP_S = 4.5  # `haven serve` ends within 5 s of Ctrl-C or SIGTERM: what its runners have to end their trials cleanly
CONSOLE_COOKIE = "haven_serve_console"
MAX_JOIN_BODY = 4096  # a join's form: the panel id and its signature


@dataclass(frozen=True)
class ServeOptions:
    """`haven serve`'s options (the Python API's arguments)."""

    study: str  # the study file's path
    root: Path  # the study's folder
    host: str = "127.0.0.1"
    port: int = 8090
    capacity: int = DEFAULT_CAPACITY
    tls: tuple[str, str] | None = None  # HTTPS: the certificate and its key (checked: web/tls.py)
    trial_ports: tuple[int, int] | None = None  # the runners' pages on these ports (None: any free port)
    id_param: str = "participant"  # the landing page's query key the panel fills in
    on_disconnect: str = OnDisconnect.PAUSE.value  # a participant gone mid-trial: their place frees after the timeout
    reconnect_timeout: float = 60.0
    params_file: str | None = None
    network: bool = False
    # each runner's ROS domain from these (None: $HAVEN_DOMAINS, if set, else any free one)
    domains: DomainRange | None = None


class StudyServer:
    def __init__(self, options: ServeOptions, study: Study, trials: Sequence[PlannedTrial]) -> None:
        from haven_scenarios.web.tls import server_context

        self.o, self.study, self.trials = options, study, list(trials)
        self.seats = Seats(options.root, study.participants)
        self.gate = Gate(study.online)
        self._joining = threading.Lock()  # (a new place and its count per address: one join at a time)
        self.runners: dict[str, Runner] = {}
        self.ports: dict[str, int] = {}  # each runner's port (0: any free one)
        self.starts: Counter[str] = Counter()
        self.waiting: dict[str, float] = {}  # participant -> when their page last asked (arrival order)
        self.token = new_token()
        self._lock = threading.Lock()
        self._stopping = threading.Event()
        tls = server_context(*options.tls) if options.tls else None
        routes = Routes(get={"/{path:.*}": self.get}, post={"/{path:.*}": self.post})
        self.server = PageServer("the study", options.host, options.port, routes, tls)
        self.ticker = threading.Thread(target=self._tick_loop, name="serve runners", daemon=True)

    @property
    def base(self) -> str:
        return f"{self.server.scheme}://{address_for_others(self.o.host)}:{self.server.port}"

    @property
    def join_url(self) -> str:
        # (SIG: the id's signature, web/online_gate.py)
        signed = f"&{SIG_PARAM}=SIG" if self.gate.secret is not None else ""
        return f"{self.base}/?{self.o.id_param}=ID{signed}"

    @property
    def console_url(self) -> str:
        return f"{self.base}/console?{TOKEN_PARAM}={self.token}"

    def start(self) -> None:
        self.server.start()
        self.ticker.start()

    def stop(self, wait_s: float = STOP_S) -> None:
        """Every runner at once as Ctrl-C (their trials end cleanly, to run again), then the pages,
        then the runners waited for together: one not ended by `wait_s` from now is killed (its
        nodes still stop cleanly: the kernel sends them SIGTERM; its session, not finished, runs
        again). The runners are told first, as their trials take the longest to end: on a busy
        machine closing the pages took seconds of the runners' time."""
        deadline = time.monotonic() + wait_s
        self._stopping.set()
        told: set[str] = set()

        def tell() -> None:  # (each runner once: a second Ctrl-C would cut its trial's clean end short)
            for participant, runner in list(self.runners.items()):
                if participant not in told:
                    told.add(participant)
                    runner.interrupt()

        tell()
        self.server.stop()
        self.ticker.join()
        tell()  # (one the last tick started)
        for runner in list(self.runners.values()):
            runner.finish(deadline)

    # -- the runners: started and reaped by one long-lived thread ------------------------------
    def _tick_loop(self) -> None:
        while not self._stopping.wait(TICK_S):
            self.tick(time.monotonic())

    def tick(self, now: float) -> None:
        with self._lock:
            for p in [p for p, r in self.runners.items() if r.code is not None]:
                self._ended_runner(p, self.runners.pop(p))
                del self.ports[p]
            for p in [p for p, asked in self.waiting.items() if now - asked > GONE_S]:
                del self.waiting[p]
            for p in list(self.waiting):
                if len(self.runners) >= self.o.capacity:
                    break
                seat = self.seats.by_participant(p)
                del self.waiting[p]
                if seat is not None:
                    self.starts[p] += 1
                    # (the next page's address holds the session key: in the environment, which only
                    # its owner can read, not on the command line, which `ps` shows anyone)
                    env = {**os.environ, NEXT_URL_ENV: f"{self.base}/session/{seat.participant}?key={seat.key}"}
                    self.runners[p] = Runner(p, self.runner_argv(seat), env, self.o.root / p)
                    print(f"serve: {seat.panel_id} ({p}): session started (pid {self.runners[p].proc.pid})", flush=True)

    def _ended_runner(self, p: str, runner: Runner) -> None:
        """Said on the researcher's terminal: how a participant's runner ended (its log: online.log)."""
        seat = self.seats.by_participant(p)
        who = f"{seat.panel_id if seat else '?'} ({p})"
        if runner.code == 0:
            print(f"serve: {who}: session ended", flush=True)
            return
        again = (
            "; it starts again when they come back"
            if self.starts[p] < MAX_STARTS
            else f"; given up after {MAX_STARTS} starts"
        )
        log = self.o.root / p / LOG
        print(
            f"serve: {who}: session stopped (code {runner.code}: {runner.last[:200]}){again} (log: {log})",
            file=sys.stderr,
            flush=True,
        )

    def runner_argv(self, seat: Seat) -> list[str]:
        o = self.o
        port = (
            next((q for q in range(o.trial_ports[0], o.trial_ports[1] + 1) if q not in self.ports.values()), 0)
            if o.trial_ports
            else 0
        )
        self.ports[seat.participant] = port
        argv = [
            sys.executable,
            "-m",
            "haven_scenarios",
            "study",
            "run",
            o.study,
            "--participant",
            seat.participant,
            "--dir",
            str(o.root),
        ]
        argv += ["--web", "--no-pause", "--host", o.host, "--port", str(port)]
        argv += ["--on-disconnect", o.on_disconnect, "--reconnect-timeout", str(o.reconnect_timeout)]
        argv += ["--tls-cert", o.tls[0], "--tls-key", o.tls[1]] if o.tls else []
        argv += ["--params-file", o.params_file] if o.params_file else []
        argv += ["--domains", o.domains.text] if o.domains else []
        return argv + (["--network"] if o.network else [])

    # -- what a participant's session page is told --------------------------------------------
    def state(self, seat: Seat, now: float) -> dict[str, Any]:
        p = seat.participant
        with self._lock:
            runner = self.runners.get(p)
            live = runner is not None and runner.code is None
            where = standing(self.study, self.o.root, p, self.trials) if not live else Standing.STARTED
            if where in (Standing.DONE, Standing.DECLINED):
                return self._ended(where)
            if live and runner is not None:
                page = runner.current_page()
                if page:
                    return {"state": Standing.RUNNING, "title": "Go on", "text": "Taking you there…", "url": page}
                return {"state": Standing.PREPARING, "title": "One moment", "text": "Your next part is being prepared…"}
            if self.starts[p] >= MAX_STARTS:
                return {
                    "state": Standing.FAILED,
                    "title": "Sorry",
                    "text": "Your session cannot go on: please tell the researcher.",
                }
            self.waiting[p] = now  # (a participant already in line keeps their place)
            ahead = list(self.waiting).index(p) - (self.o.capacity - len(self.runners))
            if ahead < 0:
                return {"state": Standing.PREPARING, "title": "One moment", "text": "Your session is starting…"}
            return {
                "state": Standing.WAITING,
                "title": "Please wait",
                "text": (
                    f"All places are in use right now: you are number {ahead + 1} in line. This page goes on by itself."
                ),
            }

    def _ended(self, where: Standing) -> dict[str, Any]:
        online = self.study.online
        if where == Standing.DECLINED:
            return {
                "state": Standing.DECLINED,
                "title": "Thank you",
                "text": "You chose not to take part: nothing more is asked. You can close this page.",
            }
        code = online.completion_code
        text = "You have finished the study. Thank you!" + (" Your completion code:" if code else "")
        return {
            "state": Standing.DONE,
            "title": "Thank you",
            "text": text,
            "code": code or None,
            "url": online.completion_url or None,
        }

    def sessions(self) -> list[dict[str, Any]]:
        """The researcher's list: every participant who joined, live ones first."""
        rows = []
        for seat in self.seats.all():
            with self._lock:
                runner = self.runners.get(seat.participant)
                live = runner is not None and runner.code is None
                waiting = seat.participant in self.waiting
            if live and runner is not None:
                state, now, console = (
                    (Standing.RUNNING if runner.page else Standing.PREPARING),
                    runner.trial,
                    runner.console,
                )
            elif self.starts[seat.participant] >= MAX_STARTS and standing(
                self.study, self.o.root, seat.participant, self.trials
            ) not in (
                Standing.DONE,
                Standing.DECLINED,
            ):
                state, now, console = Standing.FAILED, "", None
            else:
                state, now, console = (
                    (Standing.WAITING if waiting else standing(self.study, self.o.root, seat.participant, self.trials)),
                    "",
                    None,
                )
            row = {
                "panel_id": seat.panel_id,
                "participant": seat.participant,
                "state": state,
                "now": now,
                "joined": seat.joined,
            }
            rows.append({**row, "console": console})
        return sorted(rows, key=lambda r: (r["state"] not in (*LIVE, Standing.WAITING), r["participant"]))

    # -- HTTP ---------------------------------------------------------------------------------
    def get(self, request: web.Request) -> web.Response:
        parts, query = [p for p in request.path.split("/") if p], request.query
        if parts in ([], ["join"]):  # (a GET only shows the way in: a link preview takes no place)
            return self._landing(request, query.get(self.o.id_param, "").strip(), query.get(SIG_PARAM, ""))
        if parts == ["static", "haven.css"]:
            return reply(request, 200, (STATIC / "haven.css").read_bytes(), "text/css")
        if parts and parts[0] == "console":
            return self._console(request, parts)
        if len(parts) in (2, 3) and parts[0] == "session" and parts[2:] in ([], ["state"]):
            seat = self.seats.by_participant(parts[1])
            if seat is None or not token_ok(query.get("key", ""), seat.key):
                wrong = pages.message("Not found", "This session address is not right: open the study's link again.")
                return reply(request, 403, wrong, HTML)
            if parts[2:]:
                return reply_json(request, 200, self.state(seat, time.monotonic()))
            if "left" in query:  # back from a page they finished
                with self._lock:
                    runner = self.runners.get(seat.participant)
                if runner is not None:
                    runner.finished_page(query["left"])
            return reply(request, 200, pages.session(f"/session/{seat.participant}/state?key={quote(seat.key)}"), HTML)
        if parts == ["favicon.ico"]:
            return reply(request, 204, b"")
        return reply(request, 404, b"no such page")

    def post(self, request: web.Request) -> web.Response:
        """A join: the landing page's form (the panel id and any signature), from this server's page."""
        if [p for p in request.path.split("/") if p] != ["join"]:
            return reply(request, 404, b"no such page")
        if not same_origin(request):
            return reply(request, 403, b"a join comes from the study's own page")
        try:
            form = {k: v[0] for k, v in parse_qs(read_body(request, MAX_JOIN_BODY, "a join").decode("latin-1")).items()}
        except ValueError as e:
            return reply(request, 400, str(e).encode())
        return self._join(request, form.get(self.o.id_param, "").strip(), form.get(SIG_PARAM, ""))

    def _mine(self, request: web.BaseRequest) -> Seat | None:
        """The place this browser took (its cookie), if any."""
        participant, key = cookie_place(request)
        seat = self.seats.by_participant(participant) if participant else None
        return seat if seat is not None and token_ok(key, seat.key) else None

    def _landing(self, request: web.BaseRequest, panel_id: str, sig: str) -> web.Response:
        mine = self._mine(request)
        if mine is None and (panel_id or self.gate.secret is not None):  # (a typed id cannot be signed)
            refused = self.gate.refusal(panel_id, sig)
            if refused is not None:
                return reply(request, refused.code, pages.message(refused.title, refused.text), HTML)
        returning = mine is not None or (bool(panel_id) and self.seats.by_panel_id(panel_id) is not None)
        return reply(request, 200, pages.landing(self.study, panel_id, self.o.id_param, returning, sig), HTML)

    def _join(self, request: web.BaseRequest, panel_id: str, sig: str) -> web.Response:
        seat = self._mine(request)  # (one place per browser: whatever id it sends now)
        outcome = seat or self.gate.refusal(panel_id, sig) or self._take(panel_id, request.remote or "")
        if isinstance(outcome, Refusal):
            return reply(request, outcome.code, pages.message(outcome.title, outcome.text), HTML)
        there = redirect(request, f"/session/{outcome.participant}?key={quote(outcome.key)}")
        return set_place_cookie(there, request, outcome.participant, outcome.key)

    def _take(self, panel_id: str, address: str) -> Seat | Refusal:
        """This id's place (the one it had, else a new one if `address` may take one more)."""
        now = time.monotonic()
        with self._joining:
            new = self.seats.by_panel_id(panel_id) is None
            if new and not self.gate.may_take(address, now):
                return TOO_MANY
            try:
                seat = self.seats.join(panel_id)
            except ValueError as e:
                return Refusal(400, "Cannot join", str(e).replace("participant: ", "Your participant id "))
            except Full:
                return Refusal(
                    200, "The study is full", "Every place in this study has been taken. Thank you for your interest."
                )
            if new:
                self.gate.took(address, now)
            return seat

    def _console(self, request: web.BaseRequest, parts: list[str]) -> web.Response:
        given = request.query.get(TOKEN_PARAM) or request.cookies.get(CONSOLE_COOKIE, "")
        if not token_ok(given, self.token):
            return reply(request, 403, b"this page needs its token: open the address `haven serve` printed")
        if parts == ["console", "sessions.json"]:
            return reply_json(request, 200, {"capacity": self.o.capacity, "sessions": self.sessions()})
        page = reply(request, 200, pages.researcher_list(self.study, self.sessions(), self.o.capacity), HTML)
        return set_token_cookie(page, request, CONSOLE_COOKIE, self.token)
