"""`haven serve` with real participants' browsers (headless Chromium, one context each, as on
three people's machines): two panel participants join at once, each agrees to the consent text,
plays their own trial in their own suite (pressing Start themselves), answers the questionnaire
after it and ends with the study's completion code; a third waits in line until a place frees;
a participant who opens the study's link again mid-trial is taken back to their running trial;
the researcher's list shows every session. Skipped, with one line, where no Chromium can be had."""

import json
import re
import signal
import subprocess
import sys
import threading
import time
import urllib.request

import pytest
from test_web_browser import PAGE_LOAD_MS, PAGE_TIMEOUT_MS, hallway_world, screenshot

pytestmark = [pytest.mark.ros, pytest.mark.browser]
HAVEN = [sys.executable, "-m", "haven_scenarios.tools.cli"]
CODE = "DONE2026"
STUDY = f"""name: online_browser
scenarios: [short_hallway.yaml]
conditions: {{signals: [turn_signals]}}
participants: 3
counterbalancing: none
consent: {{text: "You will walk past a robot in a virtual hallway."}}
questionnaires:
  - name: legibility
    title: About the robot
    points: 7
    anchors: [Strongly disagree, Strongly agree]
    items:
      - {{id: side, text: "I could tell which way the robot would pass me."}}
online: {{welcome: "A ten-second walk in a hallway with a robot.", completion_code: {CODE}, join_limit: {{places: 3}}}}
"""


class Serve:
    """`haven serve` in the background, its output collected."""

    def __init__(self, ros, argv):
        out = {"stdout": subprocess.PIPE, "stderr": subprocess.STDOUT, "text": True}
        self.proc = subprocess.Popen([*HAVEN, *argv], env=ros.env, start_new_session=True, **out)
        ros.procs.append(self.proc)
        self.lines: list[str] = []
        threading.Thread(target=lambda: self.lines.extend(self.proc.stdout), daemon=True).start()

    def printed(self, pattern, timeout_s=60):
        deadline = time.monotonic() + timeout_s
        while time.monotonic() < deadline:
            found = re.search(pattern, "".join(self.lines))
            if found:
                return found.group(1)
            assert self.proc.poll() is None, "".join(self.lines)[-3000:]
            time.sleep(0.1)
        raise AssertionError(f"not printed: {pattern}\n" + "".join(self.lines)[-3000:])


def sessions(console_url):
    with urllib.request.urlopen(console_url.replace("/console?", "/console/sessions.json?"), timeout=10) as r:
        return {s["panel_id"]: s for s in json.load(r)["sessions"]}


def wait_state(page, state):
    page.wait_for_url("**/session/**", timeout=PAGE_TIMEOUT_MS)
    page.wait_for_function(f"() => window.havenSession && havenSession.state === '{state}'", timeout=PAGE_TIMEOUT_MS)


def consent(page):
    """Their browser has gone on from the session page to the consent page."""
    page.wait_for_url("**/instruments/**", timeout=PAGE_TIMEOUT_MS)
    page.wait_for_function("() => window.havenState && havenState.questionnaire === 'consent'", timeout=PAGE_TIMEOUT_MS)


def test_two_panel_participants_at_once_each_end_with_the_completion_code(ros, browser, tmp_path):
    world = hallway_world(tmp_path, {"h1": (8.0, 2.0, 3.14159)})
    (tmp_path / "short_hallway.yaml").write_text(
        f"name: short_hallway\nworld: {world}\nkind: hallway\ntimeout_s: 10\nrobot: {{route: [B, A]}}\n"
        "humans: [{id: h1, model: walker, route: [A, B], speed_mps: 1.0}]\n"
    )
    (tmp_path / "study.yaml").write_text(STUDY)
    serve = Serve(
        ros, ["serve", str(tmp_path / "study.yaml"), "--dir", str(tmp_path / "s"), "--port", "0", "--capacity", "2"]
    )
    join = serve.printed(r"serve: participants join at (\S+)")
    console = serve.printed(r"serve: researcher's list: (\S+)")
    pages = [browser.new_context(viewport={"width": 480, "height": 320}).new_page() for _ in range(3)]
    refused = []  # what the pages' Content-Security-Policy blocked (Chromium says it on the console)
    for page in pages:
        page.on("console", lambda m: refused.append(m.text) if "Content Security Policy" in m.text else None)

    for k, page in enumerate(pages[:2]):  # the panel's link, with each one's id
        page.goto(join.replace("=ID", f"=PANEL{k}"), timeout=PAGE_LOAD_MS)
        assert "A ten-second walk" in page.inner_text("main") and "virtual hallway" in page.inner_text(".consent")
        page.click("#join")
    for page in pages[:2]:
        consent(page)
        page.check("input[name='consent.agree'][value='1']")
        page.click("#questionnaire button[type=submit]")

    pages[2].goto(join.replace("=ID", "=PANEL2"), timeout=PAGE_LOAD_MS)  # a third: every place is taken
    pages[2].click("#join")
    wait_state(pages[2], "waiting")
    assert "number 1 in line" in pages[2].inner_text("#message")
    screenshot("web_serve_waiting.png", pages[2].screenshot())

    for page in pages[:2]:  # each on their own trial page: they press Start themselves
        page.wait_for_url("**/participant/h1**", timeout=PAGE_TIMEOUT_MS)
        page.wait_for_function(
            "s => (s = window.havenState) && s.world > 0 && s.trial && s.trial.state === 'held'",
            timeout=PAGE_TIMEOUT_MS,
        )
        page.click("#start")
    for page in pages[:2]:
        page.wait_for_function(
            "() => havenState.trial.state === 'running' || havenState.trial.state === 'ended'", timeout=PAGE_TIMEOUT_MS
        )
    live = sessions(console)
    assert {live[f"PANEL{k}"]["participant"] for k in range(2)} == {"p01", "p02"}
    assert all(live[f"PANEL{k}"]["console"] for k in range(2)) and live["PANEL2"]["state"] == "waiting"
    assert len({urllib.request.urlparse(p.url).port for p in pages[:2]}) == 2  # each their own suite's pages

    trial_url = pages[0].url  # the first opens the study's link again: back to their trial, not a new place
    pages[0].goto(join.replace("=ID", "=PANEL0"), timeout=PAGE_LOAD_MS)
    pages[0].click("#join")
    pages[0].wait_for_url(trial_url, timeout=PAGE_TIMEOUT_MS)
    assert len(sessions(console)) == 3  # (their browser's cookie: no second place)

    for page in pages[:2]:  # the trial times out: the questionnaire, then the completion code
        page.wait_for_function("() => havenState.questionnaire === 'legibility'", timeout=PAGE_TIMEOUT_MS)
        page.check("input[name='legibility.side'][value='5']")
        page.click("#questionnaire button[type=submit]")
    for page in pages[:2]:
        wait_state(page, "done")
        assert page.inner_text("#code") == CODE and "finished the study" in page.inner_text("#message")
    screenshot("web_serve_done.png", pages[0].screenshot())

    # A place is free: the third goes on by themselves, to the consent page.
    consent(pages[2])
    done = sessions(console)
    assert [done[f"PANEL{k}"]["state"] for k in range(3)] == ["done", "done", "running"]
    for p in ("p01", "p02"):
        (info,) = [json.loads(f.read_text()) for f in (tmp_path / "s" / p).rglob("session.json")]
        assert info["outcome"] == "timeout" and info["study"]["condition"] == "signals"
        assert json.loads(next((tmp_path / "s" / p).rglob("questionnaires.json")).read_text())["h1"]["legibility"][
            "answers"
        ] == {"side": 5}
        assert json.loads((tmp_path / "s" / p / "instruments.json").read_text())["consent"]["agreed"] is True

    assert refused == []  # every page, its bundle and its WebSocket within the policy
    serve.proc.send_signal(signal.SIGINT)  # stops the third's runner too
    assert serve.proc.wait(60) == 0, "".join(serve.lines)[-3000:]
