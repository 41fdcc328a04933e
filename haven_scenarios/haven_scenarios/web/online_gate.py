"""Who may take a place in `haven serve`'s study (web/study_server.py), beside the book of places
(web/online_seats.py): one client cannot fill the study.

- A place is taken only by a POST from the landing page's form: opening the link (a GET, as a chat
  app's link preview or a crawler does) only shows the page.
- One place per browser: joining sets a cookie naming the place (its participant and key); a
  browser that has one is taken back to it, whatever id it sends.
- One network address takes at most `online.join_limit.places` new places (default 2) within
  `online.join_limit.minutes` (default 60); a returning id takes no new place and is never limited.
  An IPv6 address counts as its /64 network (what one home or device is given, RFC 6177).
- Signed links (`online.link_secret_file`): the panel appends `sig`, the HMAC-SHA256 of the id
  under the study's secret (hex; RFC 2104), and an id without the right one is refused.
- An allow-list (`online.allowed_ids`): only the ids in that file may join.
"""

from __future__ import annotations

import hashlib
import hmac
import ipaddress
from collections import deque
from dataclasses import dataclass

from aiohttp import web

from haven_scenarios.study.online import Online, read_ids, read_secret
from haven_scenarios.web.serving import secure

SIG_PARAM = "sig"  # the signed link's query key: /?participant=ID&sig=HEX
PLACE_COOKIE = "haven_place"  # a browser's place: "<participant>.<key>"
PLACE_COOKIE_DAYS = 30  # a participant may come back within this (a study's field time)
MAX_ADDRESSES = 100_000  # addresses remembered at once (the oldest forgotten first: memory stays bounded)


def address_key(address: str) -> str:
    """Whom the limit counts: an IPv4 address (also when written IPv4-mapped), or an IPv6 /64."""
    try:
        ip = ipaddress.ip_address(address)
    except ValueError:
        return address
    if isinstance(ip, ipaddress.IPv6Address):
        if ip.ipv4_mapped is not None:
            return str(ip.ipv4_mapped)
        return str(ipaddress.ip_network(f"{ip}/64", strict=False))
    return str(ip)


def link_signature(secret: bytes, panel_id: str) -> str:
    """What a signed link carries as `sig`: HMAC-SHA256 of the panel id (UTF-8) under the study's
    secret, in lowercase hex (as `printf %s ID | openssl dgst -sha256 -hmac SECRET` prints it)."""
    return hmac.new(secret, panel_id.encode(), hashlib.sha256).hexdigest()


@dataclass(frozen=True)
class Refusal:
    """Why an id may not join: the page's HTTP status, title and text."""

    code: int
    title: str
    text: str


NOT_SIGNED = Refusal(
    403,
    "This link is not valid",
    "Please open the study from the link your panel gave you (this one is incomplete or changed).",
)
NOT_LISTED = Refusal(
    403,
    "Not on this study's list",
    "Your participant id is not on this study's list: please check it, or contact the researcher.",
)
TOO_MANY = Refusal(
    429,
    "Too many new places from here",
    "This network address has taken as many new places as it may for now. If you have joined before, use the link or "
    "the browser you joined with; otherwise try again later or contact the researcher.",
)


class Gate:
    """The study's rules for joining (the module docstring); the files are read once, here
    (ValueError, one line, for one that went bad since the study was loaded)."""

    def __init__(self, online: Online) -> None:
        self.secret = read_secret(online.link_secret_file) if online.link_secret_file else None
        self.ids = read_ids(online.allowed_ids) if online.allowed_ids else None
        self.places, self.window_s = online.join_limit.places, online.join_limit.minutes * 60.0
        self.taken: dict[str, deque[float]] = {}  # address -> when it took new places (oldest first)

    def rules(self) -> str:
        """The rules in a few words, for the researcher's terminal."""
        limit = (
            f"{self.places} new places per address in {self.window_s / 60:g} min"
            if self.places
            else "no limit per address"
        )
        return "; ".join(
            [
                limit,
                *(["signed links only"] if self.secret else []),
                *([f"{len(self.ids)} listed ids only"] if self.ids else []),
            ]
        )

    def refusal(self, panel_id: str, sig: str) -> Refusal | None:
        """None if this id may join (a signed link checked, the allow-list), else why not."""
        if self.secret is not None and not hmac.compare_digest(
            sig.strip().lower().encode(), link_signature(self.secret, panel_id).encode()
        ):
            return NOT_SIGNED
        if self.ids is not None and panel_id not in self.ids:
            return NOT_LISTED
        return None

    def may_take(self, address: str, now: float) -> bool:
        """Whether `address` may take one more new place now."""
        if self.places == 0:
            return True
        times = self.taken.get(address_key(address))
        while times and now - times[0] >= self.window_s:
            times.popleft()
        return not times or len(times) < self.places

    def took(self, address: str, now: float) -> None:
        if self.places == 0:
            return
        self.taken.setdefault(address_key(address), deque()).append(now)
        if len(self.taken) > MAX_ADDRESSES:
            del self.taken[next(iter(self.taken))]


def set_place_cookie(response: web.Response, request: web.BaseRequest, participant: str, key: str) -> web.Response:
    """Keep a browser's place: not for scripts, sent on top-level visits from the panel's site too
    (Lax: the landing page says "welcome back"), over HTTPS never in clear."""
    response.set_cookie(
        PLACE_COOKIE,
        f"{participant}.{key}",
        path="/",
        max_age=PLACE_COOKIE_DAYS * 86400,
        httponly=True,
        samesite="Lax",
        secure=secure(request) or None,
    )
    return response


def cookie_place(request: web.BaseRequest) -> tuple[str, str]:
    """The (participant, key) a browser's place cookie names, ("", "") if none."""
    participant, _, key = request.cookies.get(PLACE_COOKIE, "").rpartition(".")
    return participant, key


def same_origin(request: web.BaseRequest) -> bool:
    """A POST from our own page: its Origin (which browsers send with every POST form) names the
    host it was sent to; a request without one is not from a page of ours, and takes no place."""
    origin = request.headers.get("Origin")
    return origin is not None and origin.split("://", 1)[-1].rstrip("/") == (request.headers.get("Host") or "")
