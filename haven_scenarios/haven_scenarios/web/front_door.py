"""The study's one web address: pages, their code, and each page's WebSocket, behind the token.

A small threaded HTTP server (the standard library's): `/participant/<id>` and `/console` are the
pages (their settings embedded as JSON), `/static/*` the built bundles, `/robot/model.glb` the
trial robot's glTF model if its robot file names one, and `/ws/participant/<id>`,
`/ws/console` are passed through, byte for byte, to that role's Foxglove WebSocket server on
127.0.0.1 once the token is checked. So a lab network sees one port, every request needs the token,
and each role's server knows who its clients are (a participant's can publish only their velocity).
"""

from __future__ import annotations

import base64
import hashlib
import json
import mimetypes
import re
import selectors
import socket
import ssl
import sys
import threading
import time
from collections.abc import Callable, Mapping
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from importlib import resources
from pathlib import Path
from typing import Any

from haven_scenarios.web.access import (
    CONSOLE,
    TOKEN_COOKIE,
    cookie_tokens,
    door_key,
    role_token,
    route,
    token_of,
    token_ok,
)
from haven_scenarios.web.door_hello import BackendGuard, hello_frames

STATIC = resources.files("haven_scenarios.web") / "static"
CONFIG_MARK = "{{CONFIG}}"


def page_html(role: str, config: Mapping[str, Any]) -> bytes:
    """The page of a role with its settings embedded (safe inside a <script> element)."""
    template = (STATIC / ("console.html" if role == CONSOLE else "participant.html")).read_text()
    text = json.dumps(config).replace("<", "\\u003c")
    return template.replace(CONFIG_MARK, text).encode()


def address_for_others(host: str) -> str:
    """The host part of the printed addresses: `localhost` for this machine only; for every
    interface (0.0.0.0), this machine's network address, which another machine can use."""
    if host in ("127.0.0.1", "localhost", "::1"):
        return "localhost"
    if host not in ("0.0.0.0", "::", ""):
        return host
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        try:
            s.connect(("192.0.2.1", 9))  # sends nothing: picks the interface a packet would leave by
            return str(s.getsockname()[0])
        except OSError:
            return socket.gethostname()


def _pump(a: socket.socket, b: socket.socket) -> None:
    """Copy bytes both ways until either side closes."""
    sel = selectors.DefaultSelector()
    sel.register(a, selectors.EVENT_READ, b)
    sel.register(b, selectors.EVENT_READ, a)
    try:
        while True:
            for key, _ in sel.select():
                src: socket.socket = key.fileobj  # type: ignore[assignment]
                data = src.recv(65536)
                if not data:
                    return
                key.data.sendall(data)
                while isinstance(src, ssl.SSLSocket) and src.pending():  # (decrypted bytes select() cannot see)
                    key.data.sendall(src.recv(src.pending()))
    except OSError:
        return
    finally:
        sel.close()


SWEEP_PERIOD_S = 1.0  # how often connections that skipped the door are looked for (and on their first request)
MAX_ANSWER_HEAD = 16384  # a role server's answer to the upgrade: its headers within this
TLS_HANDSHAKE = b"\x16"  # the first byte of every TLS connection (a handshake record, RFC 8446 5.1)
PLAIN_HEADERS = (
    b"Content-Security-Policy: default-src 'none'\r\n"
    b"X-Content-Type-Options: nosniff\r\nReferrer-Policy: same-origin\r\n"
)
REQUEST_TIMEOUT_S = 10.0  # a request's headers must come within this (a client that sends them slowly is cut off)


class _Server(ThreadingHTTPServer):
    """A client that leaves mid-request (a closed tab, a slow or broken client) is its own business:
    nothing is said; anything else that fails a request is one line, at most every 10 s. With `tls`
    (web/tls.py), every connection is HTTPS: its handshake runs in the request's own thread, so a
    slow client holds up no one else."""

    daemon_threads = True
    said_at = 0.0

    def __init__(
        self, address: tuple[str, int], handler: type[BaseHTTPRequestHandler], tls: ssl.SSLContext | None = None
    ) -> None:
        self.tls = tls
        super().__init__(address, handler)

    @property
    def scheme(self) -> str:
        return "https" if self.tls is not None else "http"

    def finish_request(self, request: Any, client_address: Any) -> None:
        """(In the request's own thread.) Over HTTPS: a plain-http request gets one line saying to use
        https, anything else its TLS handshake."""
        if self.tls is not None:
            request.settimeout(REQUEST_TIMEOUT_S)
            if request.recv(1, socket.MSG_PEEK)[:1] not in (TLS_HANDSHAKE, b""):
                body = b"this address is served over HTTPS: open it with https://"
                request.sendall(
                    b"HTTP/1.1 400 Bad Request\r\nContent-Type: text/plain\r\nConnection: close\r\n" + PLAIN_HEADERS
                )
                request.sendall(b"Content-Length: %d\r\n\r\n%s" % (len(body), body))
                return
            with self.tls.wrap_socket(request, server_side=True) as secure:  # (the handshake, under the timeout)
                super().finish_request(secure, client_address)
            return
        super().finish_request(request, client_address)

    def handle_error(self, request: Any, client_address: Any) -> None:
        e = sys.exc_info()[1]
        # (a browser that does not trust the certificate yet)
        if isinstance(e, (ConnectionError, TimeoutError, ssl.SSLError)):
            return
        if time.monotonic() - self.said_at >= 10.0:
            self.said_at = time.monotonic()
            print(
                f"web: a request from {client_address[0]} failed: {type(e).__name__}: {str(e)[:120]}",
                file=sys.stderr,
                flush=True,
            )


# (a page's own code: `<script src>` and JSON data blocks are not it)
INLINE_SCRIPT = re.compile(rb"<script>(.*?)</script>", re.S)
_HOST = re.compile(r"^[A-Za-z0-9.:\[\]-]{1,300}$")


def content_policy(h: BaseHTTPRequestHandler, body: bytes) -> str:
    """The Content-Security-Policy of every answer: scripts, styles and fonts from this server only
    (a page's own inline code by its hash), its WebSocket on the same host (named too, for browsers
    before CSP 3's 'self' for ws:), images and glTF buffers also as data: and blob: URLs (three.js
    decodes a model's textures that way), no plugins, no <base>, never inside another site's frame."""
    hashes = "".join(
        f" 'sha256-{base64.b64encode(hashlib.sha256(m).digest()).decode()}'" for m in INLINE_SCRIPT.findall(body)
    )
    host = h.headers.get("Host") or ""
    sockets = f" ws://{host} wss://{host}" if _HOST.match(host) else ""
    return (
        f"default-src 'self'; script-src 'self'{hashes}; style-src 'self' 'unsafe-inline'; "
        f"img-src 'self' data: blob:; connect-src 'self'{sockets} data: blob:; "
        "object-src 'none'; base-uri 'none'; form-action 'self'; frame-ancestors 'none'"
    )


def send_common_headers(h: BaseHTTPRequestHandler, body: bytes, cookie: str = "") -> None:
    """What every answer of every page server says beside its content: never cached (the pages carry
    tokens), its Content-Security-Policy, no MIME sniffing, and no Referer to any other site or port
    (addresses carry tokens and session keys: a completion redirect must not hand them to the panel).
    (`same-origin`, not `no-referrer`: under no-referrer a browser sends `Origin: null` with a form's
    POST, and the study server checks a join's Origin.)"""
    h.send_header("Content-Length", str(len(body)))
    h.send_header("Cache-Control", "no-store")
    h.send_header("Content-Security-Policy", content_policy(h, body))
    h.send_header("X-Content-Type-Options", "nosniff")
    h.send_header("Referrer-Policy", "same-origin")
    if cookie:
        h.send_header("Set-Cookie", cookie)


def reply(
    h: BaseHTTPRequestHandler, code: int, body: bytes, kind: str = "text/plain; charset=utf-8", cookie: str = ""
) -> None:
    """One whole HTTP answer (send_common_headers)."""
    h.send_response(code)
    h.send_header("Content-Type", kind)
    send_common_headers(h, body, cookie)
    h.end_headers()
    h.wfile.write(body)


def redirect(h: BaseHTTPRequestHandler, location: str, cookie: str = "") -> None:
    """303 See Other to `location` on this server (after a form's POST: a reload does not post again)."""
    h.send_response(303)
    h.send_header("Location", location)
    send_common_headers(h, b"", cookie)
    h.end_headers()


def token_cookie(h: BaseHTTPRequestHandler, name: str, token: str) -> str:
    """The Set-Cookie value that keeps a page's token for its bundle and socket requests: never
    for scripts (HttpOnly), never sent from other sites, and over HTTPS never sent in clear."""
    secure = "; Secure" if getattr(h.server, "tls", None) is not None else ""
    return f"{name}={token}; Path=/; HttpOnly; SameSite=Strict{secure}"


def reply_json(h: BaseHTTPRequestHandler, code: int, data: Mapping[str, Any]) -> None:
    reply(h, code, json.dumps(data).encode(), "application/json")


def read_body(h: BaseHTTPRequestHandler, limit: int, what: str) -> bytes:
    """A POST's body of 1..`limit` bytes; ValueError (one line naming `what`) otherwise."""
    try:
        length = int(h.headers.get("Content-Length") or 0)
    except ValueError:
        length = -1
    if not 0 < length <= limit:
        raise ValueError(f"{what} of {length} bytes (at most {limit})")
    return h.rfile.read(length)


class QuietHandler(BaseHTTPRequestHandler):
    """Every page server's request handler: nothing logged (the researcher's terminal stays quiet),
    and the standard library's own error answers (a bad request line, a method not served) carry
    the same headers as every page (send_common_headers)."""

    server_version = "haven"
    timeout = REQUEST_TIMEOUT_S

    def log_message(self, format: str, *args: Any) -> None:
        pass

    def send_error(self, code: int, message: str | None = None, explain: str | None = None) -> None:
        self.close_connection = True
        text = message or self.responses.get(code, ("error",))[0]
        reply(self, code, text.encode("latin-1", "replace") if code >= 200 and code not in (204, 304) else b"")


def quiet_handler(
    on_get: Callable[[BaseHTTPRequestHandler], None], on_post: Callable[[BaseHTTPRequestHandler], None]
) -> type[BaseHTTPRequestHandler]:
    """A request handler class for a standalone page server (the instruments, the editor): GET and
    POST passed on, nothing logged (the researcher's terminal stays quiet)."""

    class Handler(QuietHandler):
        def do_GET(self) -> None:
            on_get(self)

        def do_POST(self) -> None:
            on_post(self)

    return Handler


class FrontDoor:
    def __init__(
        self,
        host: str,
        port: int,
        secret: str,
        backends: Mapping[str, int],
        config: Callable[[str], Mapping[str, Any]],
        request_timeout_s: float = REQUEST_TIMEOUT_S,
        robot_model: str = "",
        tls: ssl.SSLContext | None = None,
        guard: BackendGuard | None = None,
        on_socket: Callable[[str, bool], None] | None = None,
    ) -> None:
        """`secret`: the session's (each role's token derives from it); `backends`: role -> its
        Foxglove server's port on 127.0.0.1; `config(role)`: the page's settings; `robot_model`:
        the trial robot's glTF file (its look.model), served at ROBOT_MODEL_PATH; `tls`: serve HTTPS
        (web/tls.py); `guard`: the one the role servers call on a stranger (web/door_hello.py);
        `on_socket(role, open)`: a page's WebSocket opened or closed (study/presence.py)."""
        self.robot_model = Path(robot_model) if robot_model else None
        self.tokens = {role: role_token(secret, role) for role in backends}
        self.door_keys = {role: door_key(secret, role) for role in backends}
        self.guard = guard or BackendGuard()
        self.guard.watch(backends.values())
        self._stopped = threading.Event()
        self.on_socket = on_socket or (lambda role, opened: None)
        self.backends, self.config = dict(backends), config
        door = self

        class Handler(QuietHandler):
            timeout = request_timeout_s

            def do_GET(self) -> None:
                door.handle(self)

        try:
            self.httpd = _Server((host, port), Handler, tls)
        except OSError as e:  # one line for the user, not a traceback
            raise ValueError(f"cannot serve the study pages on {host}:{port}: {e.strerror}") from None
        self.thread = threading.Thread(target=self.httpd.serve_forever, name="front_door", daemon=True)
        self.sweeper = threading.Thread(target=self._sweep, name="front_door_guard", daemon=True)

    @property
    def port(self) -> int:
        return int(self.httpd.server_address[1])

    def base_url(self, host: str) -> str:
        """The address others open (`host` as bound: see address_for_others)."""
        return f"{self.httpd.scheme}://{address_for_others(host)}:{self.port}"

    def start(self) -> None:
        self.thread.start()
        self.sweeper.start()

    def _sweep(self) -> None:
        """Connections that skipped the door and never asked for anything are cut too, within a second."""
        while not self._stopped.wait(SWEEP_PERIOD_S):
            self.guard.sweep()

    def stop(self) -> None:
        self._stopped.set()
        self.httpd.shutdown()
        self.httpd.server_close()

    def _allowed(self, h: BaseHTTPRequestHandler, role: str) -> bool:
        cookies = h.headers.get("Cookie")
        if role:  # a page or a socket: that role's token
            return token_ok(token_of(h.path, cookies, role), self.tokens[role])
        given = token_of(h.path, None, "") or ""  # the pages' code: any role's token
        return any(token_ok(t, expected) for t in [given, *cookie_tokens(cookies)] for expected in self.tokens.values())

    def handle(self, h: BaseHTTPRequestHandler) -> None:
        req = route(h.path)
        if req.kind == "favicon":
            return reply(h, 204, b"")
        if not req.kind or (req.role and req.role not in self.backends):
            return reply(h, 404, b"no such page")
        if not self._allowed(h, req.role):
            return reply(h, 403, b"this page needs its token: open the address `haven run` printed for it")
        if req.kind == "page":
            cookie = token_cookie(h, TOKEN_COOKIE + req.role, self.tokens[req.role])
            return reply(h, 200, page_html(req.role, self.config(req.role)), "text/html; charset=utf-8", cookie)
        if req.kind == "robot_model":
            if self.robot_model is None or self.robot_model.suffix != f".{req.rest}" or not self.robot_model.is_file():
                return reply(h, 404, b"no such file")
            return reply(
                h, 200, self.robot_model.read_bytes(), "model/gltf-binary" if req.rest == "glb" else "model/gltf+json"
            )
        if req.kind == "static":
            asset = STATIC / req.rest
            if not asset.is_file() or req.rest.endswith(".html"):
                return reply(h, 404, b"no such file")
            kind = mimetypes.guess_type(req.rest)[0] or "application/octet-stream"
            return reply(h, 200, asset.read_bytes(), kind)
        if h.headers.get("Upgrade", "").lower() != "websocket":
            return reply(h, 400, b"a WebSocket address")
        self._proxy(h, req.role)

    def _proxy(self, h: BaseHTTPRequestHandler, role: str) -> None:
        """Hand the WebSocket handshake (without our cookie) to the role's server, its answer back,
        then the door's hello (web/door_hello.py), then every byte both ways."""
        h.close_connection = True
        try:
            upstream = self.guard.connect(self.backends[role])
        except OSError:
            return reply(h, 502, b"the relay is not running")
        try:
            for s in (upstream, h.connection):  # small frames both ways: no Nagle delay (40 ms with delayed ACKs)
                s.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
            head = ["GET / HTTP/1.1", *(f"{k}: {v}" for k, v in h.headers.items() if k.lower() != "cookie")]
            upstream.sendall(("\r\n".join(head) + "\r\n\r\n").encode("latin-1"))
            answer = b""
            while b"\r\n\r\n" not in answer and len(answer) < MAX_ANSWER_HEAD:
                data = upstream.recv(4096)
                if not data:
                    return
                answer += data
            h.connection.sendall(answer)  # (with any frames the server sent right after it)
            if not answer.startswith(b"HTTP/1.1 101"):
                return
            upstream.sendall(hello_frames(self.door_keys[role]))
            upstream.settimeout(None)
            h.connection.settimeout(None)  # (the request timeout was for the headers: a socket may stay quiet)
            self.on_socket(role, True)
            try:
                _pump(h.connection, upstream)
            finally:
                self.on_socket(role, False)
        except OSError:
            return
        finally:
            self.guard.release(upstream)
