"""`haven edit` in headless Chromium, driven with the mouse as a researcher would: four walls of a
6 x 4 m room clicked corner to corner, two rooms, the robot's and a person's start placed, the
loader's verdict shown live (a person put into a wall names the key), saved, and the saved
scenario run by `haven batch` to its normal end. The docs' picture of the editor comes from here."""

from __future__ import annotations

import csv
import os
import re
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest
from test_web_instruments import PAGE_TIMEOUT_MS, screenshot

pytestmark = [pytest.mark.browser, pytest.mark.integration]
HAVEN = [sys.executable, "-m", "haven_scenarios.tools.cli"]
CORNERS = [(0.0, 0.0), (6.0, 0.0), (6.0, 4.0), (0.0, 4.0)]


class Editor:
    """The page's mouse in metres (the page says where a point in metres is on the screen)."""

    def __init__(self, page) -> None:  # type: ignore[no-untyped-def]
        self.page = page

    def tool(self, name: str) -> None:
        self.page.click(f"#toolbox button[data-tool='{name}']")

    def click(self, x: float, y: float) -> None:
        px, py = self.page.evaluate(f"havenEditor.toPage({x}, {y})")
        self.page.mouse.click(px, py)

    def verdict_after(self, checks: int) -> dict:  # type: ignore[type-arg]
        """The loader's verdict on the world as it is now (a check newer than `checks`)."""
        self.page.wait_for_function(
            f"() => havenEditor.checks > {checks} && JSON.stringify(havenEditor.world()) === havenEditor.checkedWorld",
            timeout=PAGE_TIMEOUT_MS,
        )
        return self.page.evaluate("havenEditor.verdict")  # type: ignore[no-any-return]


def haven_edit(out: Path) -> tuple[subprocess.Popen, str]:  # type: ignore[type-arg]
    proc = subprocess.Popen(
        [*HAVEN, "edit", "--port", "0", "--out", str(out)], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True
    )
    lines: list[str] = []
    threading.Thread(target=lambda: lines.extend(iter(proc.stdout.readline, "")), daemon=True).start()  # type: ignore[union-attr]
    deadline = time.monotonic() + 60
    while not (found := re.findall(r"edit: the world editor \(saves into .*\): (\S+)", "".join(lines))):
        assert proc.poll() is None and time.monotonic() < deadline, "".join(lines)
        time.sleep(0.05)
    return proc, found[0]


def draw_room(editor: Editor) -> None:
    editor.page.fill("#name", "room6x4")
    editor.page.dispatch_event("#name", "change")
    editor.tool("wall")
    for i, corner in enumerate(CORNERS):
        editor.click(*corner)
        editor.click(*CORNERS[(i + 1) % 4])
    editor.tool("room")
    for name, x in (("west", 1.5), ("east", 4.5)):
        editor.page.fill("#label", name)
        editor.click(x, 2.0)
    editor.tool("robot")
    editor.click(1.0, 1.0)


def test_haven_edit_draws_a_room_that_haven_batch_runs(browser, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    proc, url = haven_edit(tmp_path / "worlds")
    try:
        page = browser.new_page(viewport={"width": 1280, "height": 760})
        assert page.goto(url.replace("token=", "token=x")).status == 403
        page.goto(url)
        page.wait_for_function("() => havenEditor.checks >= 1", timeout=PAGE_TIMEOUT_MS)
        editor = Editor(page)
        assert "needs at least one wall" in page.inner_text("#status")  # a new world: the loader says what is missing
        page.evaluate("havenEditor.fit(-1, -1, 7, 5)")
        draw_room(editor)
        editor.tool("person")
        page.fill("#heading", "180")
        checks = page.evaluate("havenEditor.checks")
        editor.click(6.0, 3.0)  # on the east wall: the loader names the person's start
        verdict = editor.verdict_after(checks)
        assert verdict["ok"] is False and verdict["key"] == "humans[0].start", verdict
        assert "humans[0].start" in page.inner_text("#status")
        checks = page.evaluate("havenEditor.checks")
        page.click("#undo")
        editor.click(5.0, 3.0)
        verdict = editor.verdict_after(checks)
        assert verdict["ok"] is True, verdict
        world = page.evaluate("havenEditor.world()")
        assert [w["segment"] for w in world["walls"]] == [
            [list(a), list(CORNERS[(i + 1) % 4])] for i, a in enumerate(CORNERS)
        ]
        assert [r["name"] for r in world["rooms"]] == ["west", "east"] and world["humans"] == [
            {"id": "h1", "start": [5, 3, 3.1416]}
        ]
        screenshot("editor_room.png", page.screenshot())
        page.select_option("#task", "visit_rooms")
        page.click("#save")
        page.wait_for_function("() => havenEditor.saved.length === 2", timeout=PAGE_TIMEOUT_MS)
        assert "Saved" in page.inner_text("#status")
    finally:
        proc.terminate()
        assert proc.wait(timeout=60) == 0
    scenario = tmp_path / "worlds" / "room6x4_scenario.yaml"
    out = tmp_path / "rows.csv"
    r = subprocess.run(
        [*HAVEN, "batch", str(scenario), "--seeds", "0", "--out", str(out)], capture_output=True, text=True, timeout=600
    )
    assert r.returncode == 0, r.stderr[-2000:]
    rows = list(csv.DictReader(out.open()))
    assert len(rows) == 1 and rows[0]["end_reason"] == "completed", rows
    assert os.path.exists(tmp_path / "worlds" / "room6x4.yaml")


def test_the_editors_other_tools_furniture_hallway_move_delete_and_a_map_image_under_the_plan_and_as_walls(  # type: ignore[no-untyped-def]
    browser, tmp_path: Path
) -> None:
    import io

    import numpy as np
    from PIL import Image

    from haven_scenarios.tools.commands.edit import NEW_WORLD
    from haven_scenarios.web.editor_server import EditorServer

    server = EditorServer("127.0.0.1", 0, NEW_WORLD, tmp_path)
    server.start()
    try:
        page = browser.new_page(viewport={"width": 1280, "height": 760})
        page.goto(server.url)
        page.wait_for_function("() => havenEditor.checks >= 1", timeout=PAGE_TIMEOUT_MS)
        page.evaluate("havenEditor.fit(-1, -1, 7, 5)")
        editor = Editor(page)
        pixels = np.full((80, 120), 255, dtype=np.uint8)  # 6 x 4 m at 0.05 m per pixel
        pixels[:2, :] = pixels[-2:, :] = pixels[:, :2] = pixels[:, -2:] = 0  # a dark border: the room's walls
        # a ROS map's own image, a PGM, which the browser cannot draw itself (the editor converts it)
        pgm = io.BytesIO()
        Image.fromarray(pixels).save(pgm, format="PPM")
        page.set_input_files(
            "#image", files=[{"name": "map.pgm", "mimeType": "image/x-portable-graymap", "buffer": pgm.getvalue()}]
        )
        page.click("#as-background")
        page.wait_for_function("() => havenEditor.background !== null", timeout=PAGE_TIMEOUT_MS)
        assert page.evaluate("havenEditor.background") == {
            "width": 120,
            "height": 80,
            "resolution": 0.05,
            "x": 0,
            "y": 0,
        }
        page.click("#as-walls")
        page.wait_for_function("() => havenEditor.world().walls.length === 4", timeout=PAGE_TIMEOUT_MS)
        assert all("polygon" in w for w in page.evaluate("havenEditor.world().walls"))
        editor.tool("obstacle")
        a, b = page.evaluate("havenEditor.toPage(2, 1)"), page.evaluate("havenEditor.toPage(3, 1.5)")
        page.mouse.move(*a)
        page.mouse.down()
        page.mouse.move(*b, steps=4)
        page.mouse.up()
        assert page.evaluate("havenEditor.world().obstacles") == [
            {"polygon": [[2, 1], [3, 1], [3, 1.5], [2, 1.5]], "height": 0.75}
        ]
        editor.tool("hallway")
        for x in (1.0, 3.0, 5.0):
            editor.click(x, 3.0)
        page.keyboard.press("Enter")
        assert page.evaluate("havenEditor.world().hallways") == [
            {"name": "hall1", "centreline": [[1, 3], [3, 3], [5, 3]], "width": 1.8}
        ]
        editor.tool("select")  # drag the furniture 1 m to the right, then delete the hallway
        a, b = page.evaluate("havenEditor.toPage(2.5, 1.25)"), page.evaluate("havenEditor.toPage(3.5, 1.25)")
        page.mouse.move(*a)
        page.mouse.down()
        page.mouse.move(*b, steps=4)
        page.mouse.up()
        assert page.evaluate("havenEditor.world().obstacles[0].polygon[0]") == [3, 1]
        editor.click(4.0, 3.0)
        page.click("#delete")
        assert page.evaluate("havenEditor.world().hallways") == []
        page.click("#undo")
        assert len(page.evaluate("havenEditor.world().hallways")) == 1
        checks = page.evaluate("havenEditor.checks")
        verdict = editor.verdict_after(checks - 1)
        assert verdict["ok"] is True, verdict  # the robot's start (1, 1) is clear of the image's walls
    finally:
        server.stop()
