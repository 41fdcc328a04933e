"""The instruments page (`haven study run --web`, before the first trial and after the last) in
headless Chromium: consent with the study's text, demographics, NARS in its mixed order with its
citation, the ranking refused until each rank is used once; the answers in instruments.json. No ROS:
the page talks to web/instrument_server.py alone."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest
import yaml

from haven_scenarios.record.participants import InstrumentBook
from haven_scenarios.study.instruments import NARS
from haven_scenarios.study.protocol import parse_study
from haven_scenarios.study.questionnaires import score
from haven_scenarios.web.instrument_server import InstrumentServer

pytestmark = [pytest.mark.browser]

PAGE_TIMEOUT_MS = 60_000  # a limit, not a wait (a loaded 2-core machine)
CONSENT = "You will walk past a robot in a virtual hallway.\n\nYou may stop at any time."
STUDY = {
    "name": "s", "scenarios": ["hallway"],
    "conditions": {"none": ["none"], "signals": ["turn_signals"], "all": ["all"]},
    "participants": 2, "consent": {"text": CONSENT},
    "before_study": ["demographics", {"name": "nars", "shuffle": True}], "after_study": ["preference"],
}  # fmt: skip


def screenshot(name: str, png: bytes) -> None:
    """The docs' pictures: written where HAVEN_SCREENSHOTS points (haven_scenarios/doc to update them)."""
    folder = os.environ.get("HAVEN_SCREENSHOTS")
    if folder:
        Path(folder, name).write_bytes(png)


def submit(page, name: str) -> None:  # type: ignore[no-untyped-def]
    page.click("#questionnaire button[type=submit]")
    page.wait_for_function(f"() => havenState.answered.includes('{name}')", timeout=PAGE_TIMEOUT_MS)


def test_the_page_asks_consent_demographics_and_nars_then_the_ranking_and_stores_them(browser, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    inst = parse_study(STUDY, "study.yaml").instruments()
    book = InstrumentBook(tmp_path, "p01")
    server = InstrumentServer("127.0.0.1", 0, book, inst.first, "s/p01/study", "Thank you. Please wait.")
    server.start()
    try:
        page = browser.new_page(viewport={"width": 1000, "height": 800})
        bad = page.goto(server.url.replace("token=", "token=x"))
        assert bad is not None and bad.status == 403  # another token: refused
        page.goto(server.url)
        page.wait_for_function("() => havenState.questionnaire === 'consent'", timeout=PAGE_TIMEOUT_MS)
        assert page.inner_text("#questionnaire .instructions") == CONSENT  # the study's text, paragraphs kept
        assert page.locator("#questionnaire input[name='consent.agree']").count() == 2
        assert (
            page.locator("fieldset[data-item='agree'] .options label").first.bounding_box()["width"] > 200
        )  # under the question, not squeezed beside it
        screenshot("web_consent.png", page.screenshot())
        page.click("#questionnaire button[type=submit]")  # nothing chosen: refused
        assert page.evaluate("havenForm.refused") == 1 and "Please answer every item" in page.inner_text(
            "#questionnaire .missing"
        )
        page.check("input[name='consent.agree'][value='1']")
        submit(page, "consent")

        page.wait_for_function("() => havenState.questionnaire === 'demographics'", timeout=PAGE_TIMEOUT_MS)
        assert "Prefer not to say" in page.inner_text("#questionnaire fieldset[data-item='gender']")
        for item, value in {"age": 2, "gender": 4, "robots": 1, "vr": 3, "games": 5}.items():
            page.check(f"input[name='demographics.{item}'][value='{value}']")
        page.fill("input[name='demographics.gender_self']", "agender")
        assert page.locator("input[name='demographics.gender_self']").bounding_box()["width"] > 150
        submit(page, "demographics")

        page.wait_for_function("() => havenState.questionnaire === 'nars'", timeout=PAGE_TIMEOUT_MS)
        assert "Nomura, Kanda, Suzuki & Kato (2006)" in page.inner_text("#questionnaire .source")
        shown = page.eval_on_selector_all("#questionnaire fieldset", "sets => sets.map(s => s.dataset.item)")
        assert sorted(shown) == sorted(i.id for i in NARS.items) and shown != [i.id for i in NARS.items]  # mixed
        answers = {i.id: 1 + k % 5 for k, i in enumerate(NARS.items)}
        for item, value in answers.items():
            page.check(f"input[name='nars.{item}'][value='{value}']")
        page.evaluate("document.getElementById('questionnaire').scrollTop = 0")
        screenshot("web_nars.png", page.screenshot())
        submit(page, "nars")
        page.wait_for_function("() => havenState.done", timeout=PAGE_TIMEOUT_MS)
        assert "Please wait" in page.inner_text("#prompt")
        assert server.finished.is_set()
    finally:
        server.stop()
    data = json.loads((tmp_path / "p01" / "instruments.json").read_text())
    assert data["consent"]["agreed"] is True and data["consent"]["answers"] == {"agree": 1}
    assert data["demographics"]["answers"] == {
        "age": 2,
        "gender": 4,
        "gender_self": "agender",
        "robots": 1,
        "vr": 3,
        "games": 5,
    }
    assert data["nars"]["answers"] == answers and data["nars"]["scores"] == score(NARS, answers)
    assert data["nars"]["order"] == shown  # the order shown is stored with the answers

    after = InstrumentServer("127.0.0.1", 0, book, inst.after, "s/p01/study", "Thank you for taking part.")
    after.start()
    try:
        page.goto(after.url)
        page.wait_for_function("() => havenState.questionnaire === 'preference'", timeout=PAGE_TIMEOUT_MS)
        for item, rank in {"none": 3, "signals": 3, "all": 1}.items():
            page.check(f"input[name='preference.{item}'][value='{rank}']")
        page.click("#questionnaire button[type=submit]")
        assert "each number from 1 to 3 once" in page.inner_text("#questionnaire .missing")
        assert "preference" not in json.loads(book.path.read_text())
        page.check("input[name='preference.signals'][value='2']")
        submit(page, "preference")
        page.wait_for_function("() => havenState.done", timeout=PAGE_TIMEOUT_MS)
    finally:
        after.stop()
    assert json.loads(book.path.read_text())["preference"]["scores"] == {
        "preference_none": 3.0,
        "preference_signals": 2.0,
        "preference_all": 1.0,
    }


@pytest.mark.integration
def test_haven_study_run_web_a_participant_who_declines_in_the_page_runs_no_trial(browser, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    path = tmp_path / "study.yaml"
    path.write_text(yaml.safe_dump(STUDY, sort_keys=False))
    argv = [
        sys.executable,
        "-m",
        "haven_scenarios",
        "study",
        "run",
        str(path),
        "--participant",
        "p02",
        "--web",
        "--port",
        "0",
        "--dir",
        str(tmp_path / "out"),
    ]
    proc = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, start_new_session=True)
    lines: list[str] = []
    threading.Thread(target=lambda: lines.extend(iter(proc.stdout.readline, "")), daemon=True).start()  # type: ignore[union-attr]
    try:
        deadline = time.monotonic() + 60
        while not (
            found := re.findall(
                r"web: participant p02 \(before the first trial: consent, demographics, nars\): (\S+)", "".join(lines)
            )
        ):
            assert proc.poll() is None and time.monotonic() < deadline, "".join(lines)
            time.sleep(0.05)
        page = browser.new_page()
        page.goto(found[0])
        page.wait_for_function("() => havenState.questionnaire === 'consent'", timeout=PAGE_TIMEOUT_MS)
        page.check("input[name='consent.agree'][value='2']")
        page.click("#questionnaire button[type=submit]")
        page.wait_for_function("() => havenState.done && havenState.declined", timeout=PAGE_TIMEOUT_MS)
        assert "You chose not to take part" in page.inner_text("#prompt")
        assert proc.wait(timeout=60) == 0
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, 15)
            proc.wait(timeout=10)
    assert "p02 did not agree to take part: no trial is run" in "".join(lines)
    assert json.loads((tmp_path / "out" / "p02" / "instruments.json").read_text())["consent"]["agreed"] is False
    assert not [p for p in (tmp_path / "out" / "p02").iterdir() if p.is_dir()]  # no trial folder
