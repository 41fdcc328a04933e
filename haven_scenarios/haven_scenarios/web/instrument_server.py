"""The page a participant answers the study's instruments on, before the first trial and after the
last (`haven study run --web`; study/instruments.py says which).

No ROS and no trial: a page server (web/serving.py) on the study's web address serves
`/instruments/<participant>` (instruments.html, its settings embedded) and its bundle, and takes
each instrument's answers as a POST of `{"questionnaire": name, "answers": {...}}` to
`/instruments/<participant>/answers`: checked and stored in the participant's instruments.json
(record/participants.py), or refused with one line the page shows. Every request needs the
participant's token (in the address `haven study run` prints, then the cookie the page sets), as the
trial pages do (web/access.py). It is stopped before the first trial's web node takes the same port.
"""

from __future__ import annotations

import json
import ssl
import threading
from collections.abc import Sequence
from datetime import UTC, datetime
from typing import Any

from aiohttp import web

from haven_scenarios.record.answers import MAX_MESSAGE_BYTES
from haven_scenarios.record.participants import InstrumentBook
from haven_scenarios.study.questionnaires import Questionnaire, in_order, item_order
from haven_scenarios.web.access import TOKEN_PARAM, new_token, role_token, token_ok
from haven_scenarios.web.front_door import STATIC, address_for_others
from haven_scenarios.web.serving import HTML, PageServer, Routes, read_body, reply, reply_json, set_token_cookie

PAGE, COOKIE = "instruments", "haven_instruments_"  # the page's path and its token cookie (+ participant)
SERVED = ("instruments.js", "haven.css")


class InstrumentServer:
    """One participant's instruments page until they have answered `qs` (or declined consent)."""

    def __init__(
        self,
        host: str,
        port: int,
        book: InstrumentBook,
        qs: Sequence[Questionnaire],
        key: str,
        done_text: str,
        tls: ssl.SSLContext | None = None,
        next_url: str = "",
    ) -> None:
        """`next_url`: where the page goes once all is answered (`haven serve`'s session page)."""
        self.book, self.participant, self.done_text, self.next_url = book, book.path.parent.name, done_text, next_url
        self.qs = {q.name: q for q in qs}
        self.order = {q.name: item_order(q, key) for q in qs}
        self.token = role_token(new_token(), self.participant)
        self.finished = threading.Event()
        self._lock = threading.Lock()
        routes = Routes(get={"/{path:.*}": self.get}, post={"/{path:.*}": self.post})
        self.server = PageServer("the instruments page", host, port, routes, tls)
        self.host = host
        self._check_done()

    @property
    def url(self) -> str:
        where = f"{self.server.scheme}://{address_for_others(self.host)}:{self.server.port}"
        return f"{where}/{PAGE}/{self.participant}?{TOKEN_PARAM}={self.token}"

    def start(self) -> None:
        self.server.start()

    def stop(self) -> None:
        self.server.stop()

    def config(self) -> dict[str, Any]:
        return {
            "participant": self.participant,
            "questionnaires": [in_order(q, self.order[q.name]).to_dict() for q in self.qs.values()],
            "answered": [n for n in self.qs if n in self.book.data],
            "declined": self.book.declined(),
            "answers_url": f"/{PAGE}/{self.participant}/answers",
            "done_text": self.done_text,
            "next_url": self.next_url,
        }

    def _check_done(self) -> None:
        if self.book.declined() or not self.book.pending(list(self.qs.values())):
            self.finished.set()

    def get(self, request: web.Request) -> web.Response:
        parts = [p for p in request.path.split("/") if p]
        if parts == ["favicon.ico"]:
            return reply(request, 204, b"")
        if not self._token_ok(request):
            return reply(request, 403, b"this page needs its token: open the address `haven study run` printed for it")
        if parts == [PAGE, self.participant]:
            with self._lock:
                text = json.dumps(self.config()).replace("<", "\\u003c")
            page = (STATIC / "instruments.html").read_text().replace("{{CONFIG}}", text).encode()
            return set_token_cookie(reply(request, 200, page, HTML), request, COOKIE + self.participant, self.token)
        if len(parts) == 2 and parts[0] == "static" and parts[1] in SERVED:
            kind = "text/javascript" if parts[1].endswith(".js") else "text/css"
            return reply(request, 200, (STATIC / parts[1]).read_bytes(), kind)
        return reply(request, 404, b"no such page")

    def _token_ok(self, request: web.BaseRequest) -> bool:
        given = request.query.get(TOKEN_PARAM) or request.cookies.get(COOKIE + self.participant, "")
        return token_ok(given, self.token)

    def post(self, request: web.Request) -> web.Response:
        if [p for p in request.path.split("/") if p] != [PAGE, self.participant, "answers"]:
            return reply(request, 404, b"no such page")
        if not self._token_ok(request):
            return reply_json(
                request, 403, {"error": "not this participant's page: open the address `haven study run` printed"}
            )
        try:
            msg = json.loads(read_body(request, MAX_MESSAGE_BYTES, "answers"))
            if (
                not isinstance(msg, dict)
                or set(msg) != {"questionnaire", "answers"}
                or msg["questionnaire"] not in self.qs
            ):
                raise ValueError(f"answers must name one of {', '.join(self.qs)}")
            name = msg["questionnaire"]
            with self._lock:
                self.book.take(
                    self.qs[name], msg["answers"], datetime.now(UTC).isoformat(timespec="seconds"), self.order[name]
                )
                self._check_done()
                answer = {"answered": [n for n in self.qs if n in self.book.data], "declined": self.book.declined()}
        except (ValueError, RecursionError) as e:
            return reply_json(
                request, 400, {"error": str(e) if not isinstance(e, json.JSONDecodeError) else "answers: not JSON"}
            )
        except OSError as e:  # (a full disk: the page can send them again)
            return reply_json(request, 500, {"error": f"cannot write {e.filename}: {e.strerror or e}"})
        return reply_json(request, 200, answer)
