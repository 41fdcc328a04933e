"""A participant who drops out, in a real browser (`haven run --web --on-disconnect pause`): the
console lists them connected with what their page reports, their closed tab shows on the console
as away within 5 s and is a `participant_disconnected` event, simulated time (/clock) stands still
until they open their page again, then runs on; the log has the pause and the reconnection.
Skipped, with one line, where no Chromium can be had."""

import os
import time

import pytest
from test_web_browser import (
    PAGE_LOAD_MS,
    PAGE_TIMEOUT_MS,
    WebTrial,
    head_on_scenario,
    read_events,
    read_json,
    screenshot,
)

pytestmark = [pytest.mark.ros, pytest.mark.browser]

SHOWN_WITHIN_S = 5.0  # the limit for a closed tab to show on the console


def row(console, who):
    return console.evaluate(f"(p => p && p.participants['{who}'])(havenState.participants)")


def test_a_closed_tab_shows_on_the_console_is_recorded_and_the_pause_stands_the_trial_still(ros, browser, tmp_path):
    from rclpy.qos import QoSProfile
    from rosgraph_msgs.msg import Clock

    argv = [
        "run",
        str(head_on_scenario(tmp_path)),
        "--teleop",
        "h1",
        "--web",
        "--port",
        "0",
        "--sessions",
        str(tmp_path / "s"),
    ]
    trial = WebTrial(ros, [*argv, "--on-disconnect", "pause", "--reconnect-timeout", "600"])
    urls = trial.urls()
    console = browser.new_page(viewport={"width": 1100, "height": 600})
    console.goto(urls["researcher console"], timeout=PAGE_LOAD_MS)
    context = browser.new_context(viewport={"width": 480, "height": 270})
    page = context.new_page()
    page.goto(urls["participant h1"], timeout=PAGE_LOAD_MS)
    page.wait_for_function(
        "s => (s = window.havenState) && s.world > 0 && s.pose && s.trial && s.trial.state === 'held'",
        timeout=PAGE_TIMEOUT_MS,
    )
    page.click("#start")
    page.wait_for_function("() => havenState.trial.state === 'running'", timeout=PAGE_TIMEOUT_MS)
    page.keyboard.down("KeyW")  # an input the page reports
    page.wait_for_function("() => havenState.latencies.length > 0", timeout=PAGE_TIMEOUT_MS)
    page.keyboard.up("KeyW")
    console.wait_for_function(
        "() => (r => r && r.state === 'connected' && r.fps > 0 && r.latency_ms > 0 && r.input_age_s !== null)"
        "((havenState.participants || {participants: {}}).participants.h1)",
        timeout=PAGE_TIMEOUT_MS,
    )

    clock = ros.collect(Clock, "/clock", QoSProfile(depth=100))
    assert ros.spin_until(lambda: len(clock) > 2, timeout_s=60)
    context.close()  # the participant's tab closes
    closed_at = time.monotonic()
    console.wait_for_function("() => havenState.participants.participants.h1.state === 'away'", timeout=PAGE_TIMEOUT_MS)
    assert time.monotonic() - closed_at < SHOWN_WITHIN_S
    console.wait_for_function("() => havenState.participants.paused === true", timeout=PAGE_TIMEOUT_MS)
    assert "paused: waiting for h1" in console.inner_text("#participants")
    screenshot("web_console_dropout.png", console.screenshot())
    # Simulated time stands still: once the pause has taken hold, no /clock moves on for 2 s.
    ros.spin_for(1.0)
    frozen = len(clock), clock[-1].clock
    ros.spin_for(2.0)
    assert all(c.clock == frozen[1] for c in clock[frozen[0] :]), (
        "simulated time went on while the participant was away"
    )

    back = browser.new_context(viewport={"width": 480, "height": 270}).new_page()
    # the same address: back in the trial (on a slow machine's setting)
    back.goto(urls["participant h1"] + "&quality=low", timeout=PAGE_LOAD_MS)
    console.wait_for_function(
        "() => havenState.participants.participants.h1.state === 'connected'", timeout=PAGE_TIMEOUT_MS
    )
    seconds = frozen[1].sec + frozen[1].nanosec * 1e-9
    assert ros.spin_until(lambda: clock[-1].clock.sec + clock[-1].clock.nanosec * 1e-9 > seconds + 0.5, timeout_s=60), (
        "time did not run on"
    )
    back.wait_for_function("() => (t => t && t.state === 'running')(havenState.trial)", timeout=PAGE_TIMEOUT_MS)
    assert back.evaluate("havenState.quality") == "low"

    console.click("#stop")
    assert trial.ended() == 0, "".join(trial.lines)[-3000:]
    events = read_events(os.path.join(trial.session(), "events.jsonl"))
    order = [
        e["type"]
        for e in events
        if e["type"] in ("participant_disconnected", "trial_paused", "participant_reconnected", "trial_resumed")
    ]
    assert order == ["participant_disconnected", "trial_paused", "participant_reconnected", "trial_resumed"], order
    (left,) = [e for e in events if e["type"] == "participant_disconnected"]
    (returned,) = [e for e in events if e["type"] == "participant_reconnected"]
    assert left["by"] == returned["by"] == "h1" and left["policy"] == "pause" and returned["away_s"] >= 3.0
    metrics = read_json(os.path.join(trial.session(), "metrics.json"))
    assert metrics["end_reason"] == "stopped" and metrics["valid"], metrics["invalid_reasons"]  # paused: nothing missed
