"""`haven serve`'s book of places and its pages, without a trial: panel ids take the design's
participants in order and keep them; two servers on one study folder share the book; the session
page's state says who waits in line; bad ids, wrong keys and the researcher's list without its
token are refused. (Trials in the browser: test_web_serve.py.)"""

from __future__ import annotations

import json
import threading
import urllib.error
import urllib.request
from pathlib import Path

import pytest

from haven_scenarios.study.progress import bind
from haven_scenarios.study.protocol import StudyError, load_study
from haven_scenarios.web.online_seats import Full, Seats
from haven_scenarios.web.study_server import ServeOptions, StudyServer

pytestmark = pytest.mark.unit

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


def test_a_study_files_online_key_is_checked(tmp_path):
    assert load_study(study_file(tmp_path)).online.completion_code == "C0DE42"
    for key, value, says in (
        ("completion_code", "'has space'", "online.completion_code: must be 1..64 letters"),
        ("completion_url", "ftp://x", r"online.completion_url: must be an http\(s\)://"),
        ("code", "x", "online.code"),
    ):
        with pytest.raises(StudyError, match=says):
            load_study(study_file(tmp_path, STUDY.replace("  completion_code: C0DE42", f"  {key}: {value}")))


def server(tmp_path: Path, capacity: int = 2) -> StudyServer:
    study = load_study(study_file(tmp_path))
    root = tmp_path / "studies" / study.name
    s = StudyServer(ServeOptions(str(study_file(tmp_path)), root, port=0, capacity=capacity), study, bind(study, root))
    threading.Thread(target=s.httpd.serve_forever, daemon=True).start()  # (the pages only: no runner is started here)
    return s


class NoRedirect(urllib.request.HTTPRedirectHandler):
    def redirect_request(self, *args, **kwargs):
        return None


def get(url: str) -> tuple[int, str, dict]:
    try:
        with urllib.request.build_opener(NoRedirect).open(url, timeout=10) as r:
            return r.status, r.read().decode(), dict(r.headers)
    except urllib.error.HTTPError as e:
        return e.code, e.read().decode(), dict(e.headers)


def test_two_servers_on_one_study_folder_share_the_places_and_refuse_strangers(tmp_path):
    one, two = server(tmp_path), server(tmp_path)
    try:
        code, page, _ = get(f"{one.base}/?participant=PANEL_A")
        assert code == 200 and "Walk past a robot &lt;in a hallway&gt;" in page and "I agree to take part." in page
        assert 'name="participant" value="PANEL_A"' in page
        code, _, head = get(f"{one.base}/join?participant=PANEL_A")
        assert code == 303 and head["Location"].startswith("/session/p01?key=")
        assert get(f"{two.base}/join?participant=PANEL_B")[2]["Location"].startswith("/session/p02?key=")
        assert get(f"{two.base}/join?participant=PANEL_A")[2]["Location"] == head["Location"]  # the same place on the other server
        code, page, _ = get(f"{two.base}/?participant=PANEL_A")  # back on the landing page: the way back, not a new start
        assert code == 200 and "Welcome back" in page and "Continue where you left off" in page
        code, page, _ = get(f"{two.base}/join?participant=PANEL_C")
        assert code == 200 and "The study is full" in page
        code, page, _ = get(f"{one.base}/join?participant=..%2Fetc")
        assert code == 400 and "Your participant id must be" in page
        assert get(f"{one.base}/session/p01?key=wrong")[0] == 403 and get(f"{one.base}/session/p01/state?key=wrong")[0] == 403
        assert get(f"{one.base}{head['Location']}")[0] == 200
        assert get(f"{one.base}/console/sessions.json")[0] == 403 and get(f"{one.base}/console?token=wrong")[0] == 403
        code, listing, _ = get(one.console_url.replace("/console?", "/console/sessions.json?"))
        assert code == 200 and [(r["panel_id"], r["participant"], r["state"]) for r in json.loads(listing)["sessions"]] == [
            ("PANEL_A", "p01", "new"),
            ("PANEL_B", "p02", "new"),
        ]
    finally:
        for s in (one, two):
            s.httpd.shutdown()
            s.httpd.server_close()


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
        s.httpd.shutdown()
        s.httpd.server_close()


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
    script = "import time\nfor line in %r:\n    print(line, flush=True)\ntime.sleep(60)\n" % lines
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
