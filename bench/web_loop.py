"""The participant's loop in the browser: key press -> velocity on the wire -> pose back -> frame drawn.

Runs `haven run shared_room --teleop h1 --web` at 1x real time, opens the participant page in
headless Chromium (Debian's, software WebGL through SwiftShader: no GPU), starts the trial, then
`--presses` times: presses W, and the page records the time from the key event to the first frame
drawn after its own pose on /humans has moved (its `havenState.latencies`), then releases and waits
for the avatar to stand still. Also the page's frame rate over `--seconds` of walking.

The page draws at `--quality` (low, standard, high: web/src/scenery.js), so each setting's cost
shows in its frame rate.

usage: python bench/web_loop.py [--presses 30] [--seconds 10] [--size 960x540] [--quality standard]
"""

from __future__ import annotations

import argparse
import os
import re
import signal
import statistics
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from common import OUT, save

HAVEN = [sys.executable, "-m", "haven_scenarios.tools.cli"]
ARGS = ["--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist"]


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--presses", type=int, default=30)
    ap.add_argument("--seconds", type=float, default=10.0)
    ap.add_argument("--size", default="960x540")
    ap.add_argument("--quality", default="standard", choices=["low", "standard", "high"])
    ap.add_argument("--params-file", default=None, help="parameters for the suite (e.g. another /humans rate)")
    a = ap.parse_args()
    width, height = (int(v) for v in a.size.split("x"))
    from playwright.sync_api import sync_playwright

    env = {**os.environ, "ROS_DOMAIN_ID": "91"}
    proc = subprocess.Popen(
        [
            *HAVEN,
            "run",
            "shared_room",
            "--teleop",
            "h1",
            "--web",
            "--port",
            "0",
            "--sessions",
            str(OUT / "web_sessions"),
            *(["--params-file", a.params_file] if a.params_file else []),
        ],
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        start_new_session=True,
    )
    try:
        url = None
        while url is None:
            m = re.search(r"web: participant h1: (\S+)", proc.stdout.readline())
            url = m.group(1) if m else None
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path="/usr/bin/chromium", args=ARGS)
            page = browser.new_page(viewport={"width": width, "height": height})
            page.goto(url + f"&quality={a.quality}")
            page.wait_for_function(
                "s => (s = window.havenState) && s.world > 0 && s.pose && s.trial && s.trial.state === 'held'",
                timeout=120_000,
            )
            page.click("#start")
            page.wait_for_function("havenState.trial.state === 'running'", timeout=60_000)
            for i in range(a.presses):
                key = "KeyA" if i % 2 else "KeyD"  # turning on the spot: the avatar stays clear of everything
                page.keyboard.down(key)
                page.wait_for_function(f"havenState.latencies.length > {i}", timeout=30_000)
                page.keyboard.up(key)
                time.sleep(0.6)  # stand still again before the next press
            latencies, wire = page.evaluate("havenState.latencies"), page.evaluate("havenState.wire")
            page.keyboard.down("KeyA")
            f0, t0 = page.evaluate("havenState.frames"), time.monotonic()
            time.sleep(a.seconds)
            fps = (page.evaluate("havenState.frames") - f0) / (time.monotonic() - t0)
            page.keyboard.up("KeyA")
            browser.close()
    finally:
        os.killpg(proc.pid, signal.SIGINT)
        proc.communicate(timeout=60)
    q = statistics.quantiles(latencies, n=20)
    w = statistics.quantiles(wire, n=20)
    row = {
        "size": a.size,
        "quality": a.quality,
        "presses": len(latencies),
        "median_ms": statistics.median(latencies),
        "p95_ms": q[18],
        "pose_back_median_ms": statistics.median(wire),
        "pose_back_p95_ms": w[18],
        "fps": fps,
    }
    print(
        f"key -> frame: median {row['median_ms']:.0f} ms, p95 {row['p95_ms']:.0f} ms over {len(latencies)} presses "
        f"(key -> moved pose back: median {row['pose_back_median_ms']:.0f} ms, p95 {row['pose_back_p95_ms']:.0f} ms); "
        f"{fps:.1f} frames/s at {a.size}, quality {a.quality}"
    )
    save({"summary": row, "latencies_ms": latencies, "pose_back_ms": wire}, OUT / f"web_loop_{a.size}_{a.quality}.json")


if __name__ == "__main__":
    main()
