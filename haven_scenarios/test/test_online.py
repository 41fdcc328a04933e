"""`haven serve`'s book of places and its pages, without a trial: panel ids take the design's
participants in order and keep them; two servers on one study folder share the book; the session
page's state says who waits in line; bad ids, wrong keys and the researcher's list without its
token are refused; one client cannot fill the study (a GET takes no place, one place per browser,
a few per address, signed links, an allow-list) and every answer carries the security headers.
(Trials in the browser: test_web_serve.py.)"""

from __future__ import annotations

import json
import stat
import urllib.error
import urllib.parse
import urllib.request
from pathlib import Path

import pytest

from haven_scenarios.record.progress import bind
from haven_scenarios.study.protocol import StudyError, load_study
from haven_scenarios.web.online_gate import link_signature
from haven_scenarios.web.online_seats import Full, Seats
from haven_scenarios.web.study_server import ServeOptions, StudyServer

pytestmark = pytest.mark.integration  # (HTTP servers on sockets)

STUDY = """name: online_pilot
scenarios: [hallway]
conditions: {none: [none], all: [all]}
participants: 2
counterbalancing: latin
online:
  welcome: "Walk past a robot <in a hallway> (10 minutes)."
  completion_code: C0DE42
consent: {text: "I agree to take part."}
"""


def study_file(tmp_path: Path, text: str = STUDY) -> Path:
    path = tmp_path / "study.yaml"
    path.write_text(text)
    return path


def test_panel_ids_take_the_designs_participants_in_order_and_keep_them(tmp_path):
    seats = Seats(tmp_path / "s", ["p01", "p02"])
    a, b = seats.join("PANEL_A"), seats.join("panel-b")
    assert (a.participant, b.participant) == ("p01", "p02") and a.key != b.key
    assert seats.join("PANEL_A") == a  # a return finds the same place and key
    assert Seats(tmp_path / "s", ["p01", "p02"]).join("panel-b") == b  # ... from another server on the folder
    with pytest.raises(Full, match="all 2 participants"):
        seats.join("third")
    for bad in ("", "../x", "a b", "x" * 65):
        with pytest.raises(ValueError, match="participant: must be"):
            seats.join(bad)
    assert json.loads((tmp_path / "s" / "online.json").read_text())["PANEL_A"]["participant"] == "p01"
    (tmp_path / "s" / "online.json").chmod(0o644)  # as an earlier version left it: made private again on opening
    Seats(tmp_path / "s", ["p01", "p02"])
    assert stat.S_IMODE((tmp_path / "s" / "online.json").stat().st_mode) == 0o600


def test_a_study_files_online_key_is_checked(tmp_path):
    assert load_study(study_file(tmp_path)).online.completion_code == "C0DE42"
    for key, value, says in (
        ("completion_code", "'has space'", "online.completion_code: must be 1..64 letters"),
        ("completion_url", "ftp://x", r"online.completion_url: must be an http\(s\)://"),
        ("code", "x", "online.code"),
    ):
        with pytest.raises(StudyError, match=says):
            load_study(study_file(tmp_path, STUDY.replace("  completion_code: C0DE42", f"  {key}: {value}")))


def server(tmp_path: Path, capacity: int = 2, text: str = STUDY) -> StudyServer:
    path = study_file(tmp_path, text)
    study = load_study(path)
    root = tmp_path / "studies" / study.name
    s = StudyServer(ServeOptions(str(path), root, port=0, capacity=capacity), study, bind(study, root))
    s.server.start()  # (the pages only: no runner is started here)
    return s


class NoRedirect(urllib.request.HTTPRedirectHandler):
    def redirect_request(self, *args, **kwargs):
        return None


def get(url: str, form: dict | None = None, headers: dict | None = None) -> tuple[int, str, dict]:
    """A request as a client that keeps no cookies (unless `headers` has them); a POST with `form`,
    with the Origin a browser sends (a header given as "" is left out)."""
    data = urllib.parse.urlencode(form).encode() if form is not None else None
    parts = urllib.parse.urlsplit(url)
    sent = {**({"Origin": f"{parts.scheme}://{parts.netloc}"} if form is not None else {}), **(headers or {})}
    request = urllib.request.Request(url, data=data, headers={k: v for k, v in sent.items() if v != ""})
    try:
        with urllib.request.build_opener(NoRedirect).open(request, timeout=10) as r:
            return r.status, r.read().decode(), dict(r.headers)
    except urllib.error.HTTPError as e:
        return e.code, e.read().decode(), dict(e.headers)


def join(base: str, panel_id: str, **more: str) -> tuple[int, str, dict]:
    """The landing page's button: a POST of the id (and any other field)."""
    return get(f"{base}/join", {"participant": panel_id, **more})


def test_two_servers_on_one_study_folder_share_the_places_and_refuse_strangers(tmp_path):
    one, two = server(tmp_path), server(tmp_path)
    try:
        code, page, _ = get(f"{one.base}/?participant=PANEL_A")
        assert code == 200 and "Walk past a robot &lt;in a hallway&gt;" in page and "I agree to take part." in page
        assert 'name="participant" value="PANEL_A"' in page
        code, _, head = join(one.base, "PANEL_A")
        assert code == 303 and head["Location"].startswith("/session/p01?key=")
        assert join(two.base, "PANEL_B")[2]["Location"].startswith("/session/p02?key=")
        assert join(two.base, "PANEL_A")[2]["Location"] == head["Location"]  # the same place on the other server
        # back on the landing page: the way back, not a new start
        code, page, _ = get(f"{two.base}/?participant=PANEL_A")
        assert code == 200 and "Welcome back" in page and "Continue where you left off" in page
        code, page, _ = join(two.base, "PANEL_C")
        assert code == 200 and "The study is full" in page
        code, page, _ = join(one.base, "../etc")
        assert code == 400 and "Your participant id must be" in page
        assert (
            get(f"{one.base}/session/p01?key=wrong")[0] == 403
            and get(f"{one.base}/session/p01/state?key=wrong")[0] == 403
        )
        assert get(f"{one.base}{head['Location']}")[0] == 200
        assert get(f"{one.base}/console/sessions.json")[0] == 403 and get(f"{one.base}/console?token=wrong")[0] == 403
        code, listing, _ = get(one.console_url.replace("/console?", "/console/sessions.json?"))
        assert code == 200 and [
            (r["panel_id"], r["participant"], r["state"]) for r in json.loads(listing)["sessions"]
        ] == [
            ("PANEL_A", "p01", "new"),
            ("PANEL_B", "p02", "new"),
        ]
    finally:
        for s in (one, two):
            s.server.stop()


class LiveRunner:
    """Stands in for a participant's `haven study run` that is still going."""

    code = None
    page = None
    trial = ""
    console = None

    def current_page(self):
        return None


def test_beyond_the_capacity_participants_wait_in_line_first_come_first_served(tmp_path):
    s = server(tmp_path, capacity=1)
    try:
        a, b = s.seats.join("A"), s.seats.join("B")
        s.runners["p01"] = LiveRunner()
        assert s.state(a, 0.0)["state"] == "preparing"  # theirs is running, no page open yet
        waiting = s.state(b, 0.0)
        assert waiting["state"] == "waiting" and "number 1 in line" in waiting["text"]
        assert [r["state"] for r in s.sessions()] == ["preparing", "waiting"]
        del s.runners["p01"]
        assert s.state(b, 1.0)["state"] == "preparing"  # a place is free: theirs starts next
        s.starts["p02"] = 99
        del s.waiting["p02"]
        assert s.state(b, 2.0)["state"] == "failed"
    finally:
        s.server.stop()


def test_a_runner_hands_out_the_page_it_opened_until_the_participant_has_finished_it(tmp_path):
    import os
    import sys
    import time

    from haven_scenarios.web.online_runner import LOG, Runner

    lines = [
        "web: participant p01 (before the first trial: consent): http://h:1/instruments/p01?token=AAA",
        "haven study: next: trial 1/1 t1: hallway, condition none (none), seed 0",
        "web: participant h1: http://h:2/participant/h1?token=BBB",
        "web: researcher console: http://h:2/console?token=CCC",
    ]
    script = f"import time\nfor line in {lines!r}:\n    print(line, flush=True)\ntime.sleep(60)\n"
    runner = Runner("p01", [sys.executable, "-c", script], os.environ, tmp_path / "p01")
    deadline = time.monotonic() + 20
    while runner.console is None and time.monotonic() < deadline:
        time.sleep(0.05)
    assert runner.current_page() == "http://h:2/participant/h1?token=BBB" and runner.console.endswith("token=CCC")
    assert runner.trial.startswith("trial 1/1 t1")
    runner.finished_page("BBB")  # they came back from it: never handed out again
    assert runner.current_page() is None
    runner.stop()
    assert runner.code is not None and "researcher console" in (tmp_path / "p01" / LOG).read_text()


def test_the_api_serves_a_study_as_the_command_does(tmp_path):
    from haven_scenarios import api

    with pytest.raises(ValueError, match="serve_study: unknown option 'capcity'"):
        api.serve_study(str(study_file(tmp_path)), capcity=2)
    server = api.serve_study(str(study_file(tmp_path)), dir=tmp_path / "s", port=0, capacity=1)
    try:
        code, page, _ = get(server.join_url.replace("=ID", "=API_1"))
        assert code == 200 and "Walk past a robot" in page and server.sessions() == []
    finally:
        server.stop()


HEADERS = ("Content-Security-Policy", "X-Content-Type-Options", "Referrer-Policy")


def test_a_burst_of_get_and_post_joins_from_one_client_without_cookies_takes_at_most_two_places(tmp_path):
    from haven_scenarios.conduct.online_study import open_server

    study = study_file(tmp_path, STUDY.replace("participants: 2", "participants: 10"))
    server = open_server(str(study), tmp_path / "s", host="127.0.0.1", port=0)  # `haven serve`'s own server
    server.start()
    try:
        answers = []
        for k in range(8):  # 24 joins with distinct ids: a link preview's GETs, and POSTs as the form sends
            answers.append(get(f"{server.base}/join?participant=bot{k}a"))
            answers.append(get(f"{server.base}/?participant=bot{k}b"))
            answers.append(join(server.base, f"bot{k}c"))
        book = tmp_path / "s" / "online.json"
        assert sorted(json.loads(book.read_text())) == ["bot0c", "bot1c"]  # the first two POSTs only
        assert stat.S_IMODE(book.stat().st_mode) == 0o600  # it holds every session's key
        assert [a[0] for a in answers[2::3]] == [303, 303] + [429] * 6
        # the page, no place
        assert all(a[0] == 200 and "Start the study" in a[1] for i, a in enumerate(answers) if i % 3 != 2)
        assert "Too many new places from here" in answers[-1][1]
        assert join(server.base, "bot0c")[0] == 303  # an id that has a place is not limited: it takes no new one
        assert get(f"{server.base}/session/p01/state?key={json.loads(book.read_text())['bot0c']['key']}")[0] == 200
        assert server.sessions() and len(server.sessions()) == 2
        # (the web framework's own answer)
        put = urllib.request.Request(f"{server.base}/", data=b"x", method="PUT")
        with pytest.raises(urllib.error.HTTPError) as unsupported:
            urllib.request.urlopen(put, timeout=10)
        assert unsupported.value.code == 405
        more = [
            get(f"{server.base}/nothing"),
            get(server.console_url),
            get(f"{server.base}/static/haven.css"),
            (405, "", unsupported.value.headers),
        ]
        for code, _, head in [*answers, *more]:
            assert all(h in head for h in HEADERS), (code, head)
        assert "frame-ancestors 'none'" in head["Content-Security-Policy"] and head["Referrer-Policy"] == "same-origin"
    finally:
        server.stop()


def gated(tmp_path: Path) -> StudyServer:
    (tmp_path / "ids.txt").write_text("# the panel's ids\nANNA\nBEN  # a comment\n\nCARL\n")
    (tmp_path / "secret.txt").write_text("s3cret-s3cret-s3cret-s3cret\n")
    (tmp_path / "secret.txt").chmod(0o600)
    online = "online:\n  allowed_ids: ids.txt\n  link_secret_file: secret.txt\n  join_limit: {places: 0}\n"
    return server(tmp_path, text=STUDY.replace("participants: 2", "participants: 4").replace("online:\n", online))


def test_one_place_per_browser_signed_links_and_an_allow_list(tmp_path):
    s = gated(tmp_path)
    sig = {k: link_signature(b"s3cret-s3cret-s3cret-s3cret", k) for k in ("ANNA", "BEN", "DORA")}
    try:
        for url in (f"{s.base}/?participant=ANNA", f"{s.base}/?participant=ANNA&sig={sig['BEN']}", f"{s.base}/"):
            code, page, _ = get(url)  # unsigned, another id's signature, no id at all: a clear page, no way in
            assert code == 403 and "This link is not valid" in page and "<form" not in page
        code, page, _ = get(f"{s.base}/?participant=ANNA&sig={sig['ANNA']}")
        assert code == 200 and f'name=sig value="{sig["ANNA"]}"' in page and "method=post" in page
        assert join(s.base, "ANNA")[0] == 403 and join(s.base, "ANNA", sig=sig["BEN"])[0] == 403
        code, page, _ = join(s.base, "DORA", sig=sig["DORA"])  # signed, but not on the list
        assert code == 403 and "Not on this study" in page
        code, _, head = join(s.base, "ANNA", sig=sig["ANNA"].upper())
        assert code == 303 and "HttpOnly" in head["Set-Cookie"] and "SameSite=Lax" in head["Set-Cookie"]
        cookie = {"Cookie": head["Set-Cookie"].split(";")[0]}
        again = get(f"{s.base}/join", {"participant": "BEN", "sig": sig["BEN"]}, cookie)  # the same browser, another id
        assert again[0] == 303 and again[2]["Location"] == head["Location"]  # back to its own place
        assert "Welcome back" in get(f"{s.base}/", headers=cookie)[1]
        assert [seat.panel_id for seat in s.seats.all()] == ["ANNA"]
        assert s.gate.rules() == "no limit per address; signed links only; 3 listed ids only"
        assert s.join_url.endswith("/?participant=ID&sig=SIG")
        assert (
            get(f"{s.base}/join", {"participant": "BEN", "sig": sig["BEN"]}, {"Origin": "http://elsewhere.example"})[0]
            == 403
        )
        assert get(f"{s.base}/join", {"participant": "BEN", "sig": sig["BEN"]}, {"Origin": "null"})[0] == 403
        # not from a browser's page
        assert get(f"{s.base}/join", {"participant": "BEN", "sig": sig["BEN"]}, {"Origin": ""})[0] == 403
        assert join(s.base, "BEN", sig=sig["BEN"])[2]["Location"].startswith("/session/p02?key=")
    finally:
        s.server.stop()


def test_the_online_keys_files_are_checked_when_the_study_is_loaded(tmp_path):
    (tmp_path / "short.txt").write_text("abc\n")
    (tmp_path / "short.txt").chmod(0o600)
    (tmp_path / "shared.txt").write_text("s3cret-s3cret-s3cret-s3cret\n")
    (tmp_path / "shared.txt").chmod(0o644)
    (tmp_path / "bad_ids.txt").write_text("ok_id\nnot an id\n")
    for online, says in (
        ("{allowed_ids: missing.txt}", r"online.allowed_ids: .*missing.txt is not a readable regular file"),
        ("{allowed_ids: bad_ids.txt}", r"online.allowed_ids: .*bad_ids.txt line 2: must be"),
        ("{link_secret_file: short.txt}", "online.link_secret_file: .*at least 16 characters"),
        ("{link_secret_file: shared.txt}", "online.link_secret_file: .*others can read this link secret: chmod 600"),
        ("{join_limit: {places: -1}}", r"online.join_limit.places: must be a whole number 0..999"),
    ):
        with pytest.raises(StudyError, match=says):
            load_study(study_file(tmp_path, STUDY.split("online:")[0] + f"online: {online}\nconsent: {{text: x}}\n"))


def test_the_limit_counts_an_address_in_a_window_and_an_ipv6_network_as_one():
    from haven_scenarios.study.online import JoinLimit, Online
    from haven_scenarios.web.online_gate import Gate

    gate = Gate(Online(join_limit=JoinLimit(places=2, minutes=1.0)))
    for now in (0.0, 10.0):
        assert gate.may_take("2001:db8:1:2::1", now)
        gate.took("2001:db8:1:2::1", now)
    assert not gate.may_take("2001:db8:1:2:ffff::9", 20.0)  # the same /64: the same household
    assert gate.may_take("2001:db8:1:3::1", 20.0) and gate.may_take("192.0.2.7", 20.0)
    assert gate.may_take("2001:db8:1:2::1", 60.0)  # the first has left the minute
    gate.took("::ffff:192.0.2.7", 0.0)
    gate.took("192.0.2.7", 0.0)
    assert not gate.may_take("192.0.2.7", 1.0)  # IPv4-mapped is the same address
    assert Gate(Online(join_limit=JoinLimit(places=0))).may_take("192.0.2.7", 0.0)
    assert (
        gate.rules() == "2 new places per address in 1 min"
        and Gate(Online(join_limit=JoinLimit(places=0))).rules() == "no limit per address"
    )
