"""Every robot as the participant page draws it, in headless Chromium: each registered robot (the
catalogue and any lab's), a lab's robot file with a polygon footprint and an aerial one, each drawn
from its description's look at real size, seen from 2.5 m (a drone hovering at its pad's 1.5 m).
One page load for them all (the page swaps robots); no ROS: the front door serves the page alone.

`HAVEN_ROBOT_PICTURES=docs/images/robots` writes the pictures the docs show (robot-pictures.md).
"""

from __future__ import annotations

import json
import os
import socket
import struct
from io import BytesIO
from pathlib import Path
from typing import Any

import pytest

from haven_scenarios.study.scenario import load_scenario
from haven_scenarios.web.access import roles, urls
from haven_scenarios.web.front_door import FrontDoor
from haven_scenarios.web.page_config import PageSettings, page_config, robot_view
from haven_sim.common import plugins
from haven_sim.common.bodies import EYE_HEIGHT_M
from haven_sim.robots.description import RobotDescription
from haven_sim.robots.robot_kind import resolve_robot

pytestmark = [pytest.mark.browser]
PAGE_TIMEOUT_MS = 90_000  # software rendering on a loaded 2-core machine is slow to start
VIEW = {"width": 640, "height": 480}
CROP = {"width": 320, "height": 240}  # the docs' pictures: the middle of the view, around the robot
DISTANCE_M = 2.5  # the participant's eye from the robot's centre
HOVER_M = 1.5  # the aerial robot is pictured hovering this high
# an empty scene
SPECK = {"shape": "sphere", "size": [0.001] * 3, "at": [0, 0, 0], "rpy": [0, 0, 0], "colour": "#dfe6ee", "spin": False}
ROBOT_AT = (6.0, 2.0)  # in the hallway, clear of its walls

POLYGON_ROBOT = """extends: turtlebot2
name: lab_cart
title: A lab's cart (a polygon footprint)
footprint: {polygon: [[0.35, 0.25], [-0.35, 0.25], [-0.35, -0.25], [0.35, -0.25]]}
height_m: 0.9
look:
  primitives:
    - {shape: box, size: [0.7, 0.5, 0.25], at: [0, 0, 0.2], colour: "#c0392b"}
    - {shape: box, size: [0.1, 0.4, 0.6], at: [-0.3, 0, 0.6], colour: "#7f8c8d"}
    - {shape: cylinder, size: [0.07, 0.07, 0.04], at: [0.25, 0.27, 0.07], rpy: [1.5708, 0, 0], \
colour: "#111111", spin: true}
    - {shape: cylinder, size: [0.07, 0.07, 0.04], at: [0.25, -0.27, 0.07], rpy: [1.5708, 0, 0], \
colour: "#111111", spin: true}
"""
AERIAL_ROBOT = """extends: turtlebot2
name: lab_drone
title: A lab's quadrotor
kinematics: aerial
footprint: {radius_m: 0.2}
height_m: 0.1
flight: {cruise_height_m: 1.5, climb_rate_mps: 0.5}
look:
  primitives:
    - {shape: box, size: [0.12, 0.12, 0.05], at: [0, 0, 0.05], colour: "#e67e22"}
    - {shape: box, size: [0.36, 0.02, 0.02], at: [0, 0, 0.06], rpy: [0, 0, 0.7854], colour: "#333333"}
    - {shape: box, size: [0.36, 0.02, 0.02], at: [0, 0, 0.06], rpy: [0, 0, -0.7854], colour: "#333333"}
    - {shape: torus, size: [0.07, 0.008, 0], at: [0.127, 0.127, 0.08], colour: "#222222", spin: true}
    - {shape: torus, size: [0.07, 0.008, 0], at: [-0.127, 0.127, 0.08], colour: "#222222", spin: true}
    - {shape: torus, size: [0.07, 0.008, 0], at: [-0.127, -0.127, 0.08], colour: "#222222", spin: true}
    - {shape: torus, size: [0.07, 0.008, 0], at: [0.127, -0.127, 0.08], colour: "#222222", spin: true}
"""


MODEL_ROBOT = """extends: turtlebot2
name: lab_model
title: A lab's robot drawn from a glTF model
look: {model: pyramid.glb}
"""


def pyramid_glb() -> bytes:
    """A glTF binary of one red pyramid (glTF axes: y up), 1 x 1 at the base and 2 high."""
    points = [(-0.5, 0, -0.5), (0.5, 0, -0.5), (0.5, 0, 0.5), (-0.5, 0, 0.5), (0, 2, 0)]
    faces = [(0, 2, 1), (0, 3, 2), (0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)]
    data = struct.pack(f"<{3 * len(points)}f", *[c for p in points for c in p]) + struct.pack(
        f"<{3 * len(faces)}H", *[i for f in faces for i in f]
    )
    n_points = 12 * len(points)
    gltf = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.1, 0.1, 1], "metallicFactor": 0}}],
        "buffers": [{"byteLength": len(data)}],
        "bufferViews": [
            {"buffer": 0, "byteLength": n_points},
            {"buffer": 0, "byteOffset": n_points, "byteLength": len(data) - n_points},
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(points), "type": "VEC3",
             "min": [-0.5, 0, -0.5], "max": [0.5, 2, 0.5]},
            {"bufferView": 1, "componentType": 5123, "count": 3 * len(faces), "type": "SCALAR"},
        ],
    }  # fmt: skip
    text = json.dumps(gltf).encode()
    text += b" " * (-len(text) % 4)
    data += b"\0" * (-len(data) % 4)
    chunks = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(data), 0x004E4942) + data
    return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks


def free_port() -> int:
    with socket.socket() as s:  # nothing listens there: the page's socket fails, the page stays
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def robots(tmp_path: Path) -> list[RobotDescription]:
    """Every registered robot, then a lab's two files."""
    found = [resolve_robot(name) for name in plugins.registry("robots").names()]
    for name, text in (("lab_cart", POLYGON_ROBOT), ("lab_drone", AERIAL_ROBOT)):
        (tmp_path / f"{name}.yaml").write_text(text)
        found.append(resolve_robot(str(tmp_path / f"{name}.yaml")))
    return found


def pose_for(desc: dict[str, Any], z: float) -> tuple[dict[str, float], dict[str, float], float]:
    """The robot's pose at height z, the eye's pose 2.5 m in front of it, and how far down to look
    to see its middle."""
    x, y = ROBOT_AT
    eye = {"x": x + DISTANCE_M, "y": y, "yaw": 3.14159265}
    robot = {"x": x, "y": y, "z": z, "yaw": 0.6}  # turned a little: its front and side both show
    pitch = max(0.0, (EYE_HEIGHT_M - (z + desc["height_m"] / 2)) / DISTANCE_M)  # (small angles: near enough)
    return robot, eye, pitch


def drawn(page, desc: dict[str, Any], z: float) -> tuple[int, bytes, bytes, bytes]:  # type: ignore[no-untyped-def]
    """The robot at height z: its mesh count, the view without it and with it, and the middle of
    the view around it (the docs' picture, at the size the participant sees it)."""
    at, eye, pitch = pose_for(desc, z)
    pictures = []
    for shown in ({**desc, "primitives": [SPECK], "model_url": None}, desc):
        meshes = page.evaluate(f"havenShowRobot({json.dumps(shown)}, {json.dumps(at)}, {json.dumps(eye)}, {pitch})")
        if shown.get("model_url"):  # its glTF model replaces the primitives once loaded
            page.wait_for_function("() => havenState.robotModel === true", timeout=PAGE_TIMEOUT_MS)
        frames = page.evaluate("havenState.frames")
        page.wait_for_function(f"() => havenState.frames > {frames + 1}", timeout=PAGE_TIMEOUT_MS)
        pictures.append(page.screenshot())
    spot = page.evaluate(f"havenProject({at['x']}, {at['y']}, {z + desc['height_m'] / 2})")
    left = min(max(0, int(spot["x"]) - CROP["width"] // 2), VIEW["width"] - CROP["width"])
    top = min(max(0, int(spot["y"]) - CROP["height"] // 2), VIEW["height"] - CROP["height"])
    return meshes, pictures[0], pictures[1], page.screenshot(clip={"x": left, "y": top, **CROP})


def changed_pixels(a: bytes, b: bytes) -> int:
    from PIL import Image, ImageChops

    diff = ImageChops.difference(Image.open(BytesIO(a)).convert("RGB"), Image.open(BytesIO(b)).convert("RGB")).convert(
        "L"
    )
    return sum(diff.point(lambda v: 255 if v > 24 else 0).histogram()[255:])


def test_every_robot_is_drawn_from_its_description_at_real_size(browser, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    scenario = load_scenario("hallway")
    role = roles(["h1"])["h1"]
    (tmp_path / "pyramid.glb").write_bytes(pyramid_glb())
    (tmp_path / "lab_model.yaml").write_text(MODEL_ROBOT)
    modelled = resolve_robot(str(tmp_path / "lab_model.yaml"))
    config = page_config(role, scenario, PageSettings())
    door = FrontDoor("127.0.0.1", 0, "secret", {"h1": free_port()}, lambda r: config, robot_model=modelled.look.model)
    door.start()
    try:
        page = browser.new_page(viewport=VIEW)
        page.goto(urls(f"http://127.0.0.1:{door.port}", "secret", ["h1"])["h1"], timeout=PAGE_TIMEOUT_MS)
        page.add_style_tag(content="#prompt, #inset, #hud, #lost { display: none !important; }")
        page.wait_for_function(
            "() => window.havenState && havenState.frames > 1 && typeof window.havenShowRobot === 'function'",
            timeout=PAGE_TIMEOUT_MS,
        )
        out = os.environ.get("HAVEN_ROBOT_PICTURES")
        shown = []
        for robot in robots(tmp_path):
            desc = robot_view(robot)
            # a drone: hovering, and on its pad
            heights = {"": 0.0} if not robot.aerial else {"": HOVER_M, "_landed": 0.0}
            for suffix, z in heights.items():
                meshes, empty, full, picture = drawn(page, desc, z)
                assert meshes == max(1, len(robot.look.primitives)), robot.name
                changed = changed_pixels(empty, full)
                # at 2.5 m the smallest robot (a 0.2 m drone) covers some hundreds
                assert changed > 300, (robot.name, z, changed)
                if out:
                    Path(out).mkdir(parents=True, exist_ok=True)
                    Path(out, f"{robot.name}{suffix}.png").write_bytes(picture)
            shown.append(robot.name)
        assert {"turtlebot2", "lab_cart", "lab_drone"} <= set(shown)
        # A robot file's glTF model (served by the front door) replaces its primitives.
        desc = robot_view(modelled)
        _, empty, primitives, _ = drawn(page, {**desc, "model_url": None}, 0.0)
        _, _, full, picture = drawn(page, desc, 0.0)
        assert changed_pixels(empty, full) > 300 and changed_pixels(primitives, full) > 300
        if out:
            Path(out, "lab_model.png").write_bytes(picture)
    finally:
        door.stop()
