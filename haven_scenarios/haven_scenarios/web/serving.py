"""How every page server of HAVEN is served: an aiohttp application on its own event loop thread.

The four servers (the trial's front door, `haven serve`, `haven edit`, the instruments page) differ
only in their routes; what they share is here, once:
- the address is bound when the server is made, so a busy port is one line (ValueError), not a
  traceback from a thread;
- HTTPS with the study's certificate (web/tls.py) where asked: the TLS handshake is asyncio's, and a
  plain-http request to an https address gets one line saying to use https:// (a headset's browser
  otherwise shows only "invalid response");
- a client that does not finish its request's headers within `request_timeout_s` is cut off (aiohttp's
  keep-alive timer runs from the connection's start), and a body beyond `max_body` is refused;
- nothing is logged per request; a handler that fails is one line (at most every 10 s) and a 500;
- every answer carries the same headers (`common_headers`): never cached, a Content-Security-Policy,
  no MIME sniffing, no Referer beyond this origin.
Handlers are plain functions run on a worker thread (they read files and take locks), so the event
loop only moves bytes; a WebSocket route is a coroutine (`Routes.sockets`).
"""

from __future__ import annotations

import asyncio
import base64
import hashlib
import json
import logging
import re
import socket
import ssl
import sys
import threading
import time
from collections.abc import Awaitable, Callable
from dataclasses import dataclass, field

from aiohttp import web

Handler = Callable[[web.Request], web.StreamResponse]
SocketHandler = Callable[[web.Request], Awaitable[web.StreamResponse]]

REQUEST_TIMEOUT_S = 10.0  # a request's headers must come within this (a client that sends them slowly is cut off)
TLS_HANDSHAKE = b"\x16"  # the first byte of every TLS connection (a handshake record, RFC 8446 5.1)
PLAIN_TO_TLS = b"this address is served over HTTPS: open it with https://"
SAY_EVERY_S = 10.0  # a failing handler is said at most this often
HTML = "text/html; charset=utf-8"
TEXT = "text/plain; charset=utf-8"
JSON = "application/json"
MAX_BODY = 64 << 20  # no request body beyond this, whatever its route allows (each has its own, smaller limit)
LOOP = web.AppKey("loop", asyncio.AbstractEventLoop)

# (a page's own code: `<script src>` and JSON data blocks are not it)
INLINE_SCRIPT = re.compile(rb"<script>(.*?)</script>", re.S)
_HOST = re.compile(r"^[A-Za-z0-9.:\[\]-]{1,300}$")


def content_policy(host: str, body: bytes) -> str:
    """The Content-Security-Policy of every answer: scripts, styles and fonts from this server only
    (a page's own inline code by its hash), its WebSocket on the same host (named too, for browsers
    before CSP 3's 'self' for ws:), images and glTF buffers also as data: and blob: URLs (three.js
    decodes a model's textures that way), no plugins, no <base>, never inside another site's frame."""
    hashes = "".join(
        f" 'sha256-{base64.b64encode(hashlib.sha256(m).digest()).decode()}'" for m in INLINE_SCRIPT.findall(body)
    )
    sockets = f" ws://{host} wss://{host}" if _HOST.match(host) else ""
    return (
        f"default-src 'self'; script-src 'self'{hashes}; style-src 'self' 'unsafe-inline'; "
        f"img-src 'self' data: blob:; connect-src 'self'{sockets} data: blob:; "
        "object-src 'none'; base-uri 'none'; form-action 'self'; frame-ancestors 'none'"
    )


def common_headers(host: str, body: bytes) -> dict[str, str]:
    """What every answer of every page server says beside its content: never cached (the pages carry
    tokens), its Content-Security-Policy, no MIME sniffing, and no Referer to any other site or port
    (addresses carry tokens and session keys: a completion redirect must not hand them to the panel).
    (`same-origin`, not `no-referrer`: under no-referrer a browser sends `Origin: null` with a form's
    POST, and the study server checks a join's Origin.)"""
    return {
        "Cache-Control": "no-store",
        "Content-Security-Policy": content_policy(host, body),
        "X-Content-Type-Options": "nosniff",
        "Referrer-Policy": "same-origin",
    }


def reply(request: web.BaseRequest, code: int, body: bytes, kind: str = TEXT) -> web.Response:
    """One whole answer with the common headers."""
    response = web.Response(status=code, body=body if code not in (204, 304) else None)
    response.headers.update(common_headers(request.host, body))
    if code not in (204, 304):
        response.headers["Content-Type"] = kind
    return response


def reply_json(request: web.BaseRequest, code: int, data: object) -> web.Response:
    return reply(request, code, json.dumps(data).encode(), JSON)


def redirect(request: web.BaseRequest, location: str) -> web.Response:
    """303 See Other to `location` on this server (after a form's POST: a reload does not post again)."""
    response = reply(request, 303, b"")
    response.headers["Location"] = location
    return response


def secure(request: web.BaseRequest) -> bool:
    return request.transport is not None and request.transport.get_extra_info("sslcontext") is not None


def set_token_cookie(response: web.Response, request: web.BaseRequest, name: str, token: str) -> web.Response:
    """Keep a page's token for its bundle and socket requests: never for scripts (HttpOnly), never
    sent from other sites (SameSite=Strict), and over HTTPS never sent in clear (Secure)."""
    response.set_cookie(name, token, path="/", httponly=True, samesite="Strict", secure=secure(request) or None)
    return response


def read_body(request: web.Request, limit: int, what: str) -> bytes:
    """(In a handler.) A POST's body of 1..`limit` bytes, by its Content-Length; ValueError (one line
    naming `what`) otherwise, answered before a byte of the body is read."""
    length = request.content_length or 0
    if not 0 < length <= limit:
        raise ValueError(f"{what} of {length} bytes (at most {limit})")
    return asyncio.run_coroutine_threadsafe(request.read(), request.app[LOOP]).result()


@dataclass
class Routes:
    """A server's routes: GET and POST handlers by path pattern (aiohttp's: `/session/{participant}`),
    and WebSocket routes (coroutines). A path nobody serves gets 404 "no such page"."""

    get: dict[str, Handler] = field(default_factory=dict)
    post: dict[str, Handler] = field(default_factory=dict)
    sockets: dict[str, SocketHandler] = field(default_factory=dict)


class PageServer:
    """An aiohttp application on `host:port` (0: a free port), served on its own thread until `stop()`."""

    def __init__(
        self,
        name: str,
        host: str,
        port: int,
        routes: Routes,
        tls: ssl.SSLContext | None = None,
        request_timeout_s: float = REQUEST_TIMEOUT_S,
        on_start: Callable[[], Awaitable[None]] | None = None,
    ) -> None:
        """`on_start`: a coroutine started on the server's loop (a periodic task)."""
        self.name, self.host, self.tls, self.timeout_s, self._on_start = name, host, tls, request_timeout_s, on_start
        self.said_at = -SAY_EVERY_S
        family = socket.AF_INET6 if ":" in host else socket.AF_INET
        try:
            self.sock = socket.create_server((host, port), family=family, backlog=128)
        except (OSError, OverflowError) as e:
            raise ValueError(f"cannot serve {name} on {host}:{port}: {getattr(e, 'strerror', None) or e}") from None
        self.sock.setblocking(False)
        self.loop = asyncio.new_event_loop()
        # (each route holds a POST to its own limit first: `read_body`)
        self.app = web.Application(client_max_size=MAX_BODY, middlewares=[self._answers])
        self.app[LOOP] = self.loop
        for path, ws in routes.sockets.items():  # (first: a page route may match any path)
            self.app.router.add_get(path, ws, allow_head=False)
        for path, get in routes.get.items():
            self.app.router.add_get(path, self._sync(get), allow_head=False)
        for path, post in routes.post.items():
            self.app.router.add_post(path, self._sync(post))
        self._started = threading.Event()
        self._stopping: asyncio.Event | None = None
        self.thread = threading.Thread(target=self._serve, name=name, daemon=True)

    @property
    def port(self) -> int:
        return int(self.sock.getsockname()[1])

    @property
    def scheme(self) -> str:
        return "https" if self.tls is not None else "http"

    def start(self) -> None:
        self.thread.start()
        self._started.wait()

    def wait(self) -> None:
        """Until the server is stopped (a stop signal's KeyboardInterrupt ends the wait)."""
        self.thread.join()

    def stop(self) -> None:
        """Close every connection and the address; returns once the server's thread has ended."""
        if self.thread.is_alive() and self._stopping is not None:
            self.loop.call_soon_threadsafe(self._stopping.set)
            self.thread.join()
        self.sock.close()

    # -- the loop's thread -------------------------------------------------------------------
    def _serve(self) -> None:
        asyncio.set_event_loop(self.loop)
        try:
            self.loop.run_until_complete(self._main())
        finally:
            self.loop.close()

    async def _main(self) -> None:
        self._stopping = asyncio.Event()
        runner = web.AppRunner(self.app, handle_signals=False, access_log=None, keepalive_timeout=self.timeout_s)
        await runner.setup()
        tasks = [asyncio.create_task(self._accept(runner))]
        if self._on_start is not None:
            tasks.append(asyncio.create_task(self._on_start()))  # type: ignore[arg-type]
        self._started.set()
        await self._stopping.wait()
        for task in tasks:
            task.cancel()
        await runner.cleanup()

    async def _accept(self, runner: web.AppRunner) -> None:
        loop = asyncio.get_running_loop()
        assert runner.server is not None
        greeting: set[asyncio.Task[None]] = set()
        while True:
            conn, _ = await loop.sock_accept(self.sock)
            task = asyncio.create_task(self._greet(conn, runner.server))
            greeting.add(task)
            task.add_done_callback(greeting.discard)

    async def _greet(self, conn: socket.socket, server: web.Server) -> None:
        """Hand a new connection to aiohttp (over HTTPS after its handshake; a plain-http request to
        an https address gets one line instead)."""
        loop = asyncio.get_running_loop()
        conn.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)  # small frames: no Nagle delay
        try:
            if self.tls is not None:
                first = await asyncio.wait_for(_peek(loop, conn), self.timeout_s)
                if first not in (TLS_HANDSHAKE, b""):
                    await loop.sock_sendall(conn, PLAIN_ANSWER)
                    conn.close()
                    return
            await loop.connect_accepted_socket(
                server, conn, ssl=self.tls, ssl_handshake_timeout=self.timeout_s if self.tls else None
            )
        except (OSError, TimeoutError, ssl.SSLError):  # gone, silent, or a browser that does not trust us yet
            conn.close()

    # -- answers -----------------------------------------------------------------------------
    @web.middleware
    async def _answers(
        self, request: web.Request, handler: Callable[[web.Request], Awaitable[web.StreamResponse]]
    ) -> web.StreamResponse:
        """aiohttp's own answers (no such page, a method not served, a body too large) with the
        common headers, in one line; a handler that fails is said once and answered 500."""
        try:
            return await handler(request)
        except web.HTTPException as e:
            if e.status == 404:
                return reply(request, 404, b"no such page")
            if e.status == 413:
                return reply(request, 413, f"a request body of at most {MAX_BODY} bytes".encode())
            return reply(request, e.status, (e.reason or "error").encode())
        except (ConnectionError, asyncio.CancelledError):
            raise
        except Exception as e:
            self.said(request, e)
            return reply(request, 500, b"the server failed on this request")

    def said(self, request: web.BaseRequest, e: BaseException) -> None:
        if time.monotonic() - self.said_at >= SAY_EVERY_S:
            self.said_at = time.monotonic()
            print(
                f"web: a request from {request.remote} failed: {type(e).__name__}: {str(e)[:120]}",
                file=sys.stderr,
                flush=True,
            )

    def _sync(self, handler: Handler) -> Callable[[web.Request], Awaitable[web.StreamResponse]]:
        async def run(request: web.Request) -> web.StreamResponse:
            return await asyncio.get_running_loop().run_in_executor(None, handler, request)

        return run


async def _peek(loop: asyncio.AbstractEventLoop, conn: socket.socket) -> bytes:
    """The connection's first byte, left in place (b"" when it closed first)."""
    ready: asyncio.Future[None] = loop.create_future()

    def readable() -> None:
        if not ready.done():
            ready.set_result(None)

    loop.add_reader(conn.fileno(), readable)
    try:
        await ready
    finally:
        loop.remove_reader(conn.fileno())
    return conn.recv(1, socket.MSG_PEEK)


def _quiet_aiohttp() -> None:
    """aiohttp logs a failed request with its traceback (the researcher's terminal stays quiet:
    `PageServer.said` says one line); its logger is silenced once."""
    for name in ("aiohttp.server", "aiohttp.web", "aiohttp.access"):
        logger = logging.getLogger(name)
        logger.addHandler(logging.NullHandler())
        logger.propagate = False


_quiet_aiohttp()
# (written by hand: no HTTP parser has seen the request; the common headers as every answer has them)
PLAIN_ANSWER = (
    b"HTTP/1.1 400 Bad Request\r\nContent-Type: text/plain\r\nConnection: close\r\n"
    + "".join(f"{k}: {v}\r\n" for k, v in common_headers("", PLAIN_TO_TLS).items()).encode()
    + b"Content-Length: %d\r\n\r\n%s" % (len(PLAIN_TO_TLS), PLAIN_TO_TLS)
)
