"""The study's one web address: pages, their code, and each page's WebSocket, behind the token.

A page server (web/serving.py): `/participant/<id>` and `/console` are the pages (their settings
embedded as JSON), `/static/*` the built bundles, `/robot/model.glb` the trial robot's glTF model if
its robot file names one, and `/ws/participant/<id>`, `/ws/console` are relayed, message for
message, to that role's Foxglove WebSocket server on 127.0.0.1 once the token is checked. So a lab
network sees one port, every request needs the token, and each role's server knows who its clients
are (a participant's can publish only their velocity).
"""

from __future__ import annotations

import asyncio
import contextlib
import json
import mimetypes
import socket
import ssl
from collections.abc import Callable, Mapping
from importlib import resources
from pathlib import Path
from typing import Any

import aiohttp
from aiohttp import web

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
from haven_scenarios.web.door_hello import BackendGuard, hello_messages
from haven_scenarios.web.serving import HTML, REQUEST_TIMEOUT_S, PageServer, Routes, reply, set_token_cookie

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
        self.on_socket = on_socket or (lambda role, opened: None)
        self.backends, self.config = dict(backends), config
        routes = Routes(get={"/{path:.*}": self.handle}, sockets={"/ws/{path:.*}": self._socket})
        self.server = PageServer("the study pages", host, port, routes, tls, request_timeout_s, self._sweep)

    @property
    def port(self) -> int:
        return self.server.port

    def base_url(self, host: str) -> str:
        """The address others open (`host` as bound: see address_for_others)."""
        return f"{self.server.scheme}://{address_for_others(host)}:{self.port}"

    def start(self) -> None:
        self.server.start()

    def stop(self) -> None:
        self.server.stop()

    async def _sweep(self) -> None:
        """Connections that skipped the door and never asked for anything are cut too, within a second."""
        while True:
            await asyncio.sleep(SWEEP_PERIOD_S)
            self.guard.sweep()

    def _allowed(self, request: web.BaseRequest, role: str) -> bool:
        if role:  # a page or a socket: that role's token
            return token_ok(token_of(request.query, request.cookies, role), self.tokens[role])
        given = token_of(request.query, {}, "")  # the pages' code: any role's token
        return any(
            token_ok(t, expected) for t in [given, *cookie_tokens(request.cookies)] for expected in self.tokens.values()
        )

    def _refusal(self, request: web.BaseRequest) -> web.Response | None:
        """The answer to a request that is not for one of this trial's pages or lacks its token."""
        req = route(request.path)
        if req.kind == "favicon":
            return reply(request, 204, b"")
        if not req.kind or (req.role and req.role not in self.backends):
            return reply(request, 404, b"no such page")
        if not self._allowed(request, req.role):
            return reply(request, 403, b"this page needs its token: open the address `haven run` printed for it")
        return None

    def handle(self, request: web.Request) -> web.Response:
        refused = self._refusal(request)
        if refused is not None:
            return refused
        req = route(request.path)
        if req.kind == "page":
            page = reply(request, 200, page_html(req.role, self.config(req.role)), HTML)
            return set_token_cookie(page, request, TOKEN_COOKIE + req.role, self.tokens[req.role])
        if req.kind == "robot_model":
            if self.robot_model is None or self.robot_model.suffix != f".{req.rest}" or not self.robot_model.is_file():
                return reply(request, 404, b"no such file")
            kind = "model/gltf-binary" if req.rest == "glb" else "model/gltf+json"
            return reply(request, 200, self.robot_model.read_bytes(), kind)
        if req.kind == "static":
            asset = STATIC / req.rest
            if not asset.is_file() or req.rest.endswith(".html"):
                return reply(request, 404, b"no such file")
            return reply(
                request, 200, asset.read_bytes(), mimetypes.guess_type(req.rest)[0] or "application/octet-stream"
            )
        return reply(request, 400, b"a WebSocket address")

    async def _socket(self, request: web.Request) -> web.StreamResponse:
        """A page's WebSocket: to its role's server, with the page's subprotocols and without our
        cookie; the door's hello first (web/door_hello.py), then every message both ways."""
        refused = self._refusal(request)
        if refused is not None:
            return refused
        role = route(request.path).role
        if request.headers.get("Upgrade", "").lower() != "websocket":
            return reply(request, 400, b"a WebSocket address")
        offered = [p.strip() for p in request.headers.get("Sec-WebSocket-Protocol", "").split(",") if p.strip()]
        connector = aiohttp.TCPConnector(socket_factory=self.guard.socket_for, force_close=True)
        async with aiohttp.ClientSession(connector=connector) as session:
            try:
                upstream = await session.ws_connect(
                    f"ws://127.0.0.1:{self.backends[role]}/",
                    protocols=offered,
                    compress=0,
                    max_msg_size=0,  # (our own server in this process: a map or a model may be large)
                    timeout=aiohttp.ClientWSTimeout(ws_close=2.0),
                    autoping=True,
                )
            except (aiohttp.ClientError, OSError, TimeoutError):
                return reply(request, 502, b"the relay is not running")
            try:
                for message in hello_messages(self.door_keys[role]):
                    await (upstream.send_str(message) if isinstance(message, str) else upstream.send_bytes(message))
                page = web.WebSocketResponse(
                    protocols=[upstream.protocol] if upstream.protocol else (),
                    compress=False,
                    max_msg_size=MAX_PAGE_MESSAGE,
                )
                await page.prepare(request)
                self.on_socket(role, True)
                try:
                    await _relay(page, upstream)
                finally:
                    self.on_socket(role, False)
            finally:
                await upstream.close()
                self.guard.release(upstream.get_extra_info("sockname"))
        return page


SWEEP_PERIOD_S = 1.0  # how often connections that skipped the door are looked for (and on their first request)
MAX_PAGE_MESSAGE = 1 << 20  # a page's own messages (velocities, parameters, Start, answers) are far smaller


async def _relay(page: web.WebSocketResponse, upstream: aiohttp.ClientWebSocketResponse) -> None:
    """Copy messages both ways until either side closes."""

    async def copy(source: Any, sink: Any) -> None:
        async for message in source:
            if message.type == aiohttp.WSMsgType.TEXT:
                await sink.send_str(message.data)
            elif message.type == aiohttp.WSMsgType.BINARY:
                await sink.send_bytes(message.data)
            else:
                break

    tasks = [asyncio.create_task(copy(page, upstream)), asyncio.create_task(copy(upstream, page))]
    try:
        await asyncio.wait(tasks, return_when=asyncio.FIRST_COMPLETED)
    finally:
        for task in tasks:
            task.cancel()
        with contextlib.suppress(Exception):
            await asyncio.gather(*tasks, return_exceptions=True)
        await page.close()
