"""`haven edit`'s server (web/editor_server.py) and the scenario template (study/scenario_template.py):
nothing without the token, sizes capped, the loader's own line for a world drawn wrong, saved files
that load, an existing file replaced only when the page says so, walls from a map image."""

from __future__ import annotations

import http.client
import io
import json
import struct
import urllib.error
import urllib.request
import zlib
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import yaml
from PIL import Image

from haven_scenarios.study.scenario import load_scenario, parse_scenario
from haven_scenarios.study.scenario_template import TemplateError, scenario_template
from haven_scenarios.tools.commands.edit import world_tree
from haven_scenarios.web.editor_server import MAX_WORLD_BYTES, EditorServer
from haven_sim.sim.map_image import MAX_CELLS, MAX_WALL_BOXES
from haven_sim.sim.world import WorldError
from haven_sim.sim.world_file import load_world

pytestmark = pytest.mark.integration  # (the editor's HTTP server on a socket)


def room_world(name: str = "lab") -> dict[str, Any]:
    """A 6 x 4 m room as the editor's walls draw it, two rooms, the robot and a person."""
    corners = [[0, 0], [6, 0], [6, 4], [0, 4]]
    walls = [{"segment": [corners[i], corners[(i + 1) % 4]], "thickness": 0.1} for i in range(4)]
    return {
        "name": name,
        "walls": walls,
        "rooms": [{"name": "west", "centre": [1.0, 2.0]}, {"name": "east", "centre": [5.0, 2.0]}],
        "robot": {"start": [1.0, 1.0, 0.0]},
        "humans": [{"id": "h1", "start": [5.0, 3.0, 3.1416]}],
        "gems": [{"id": "g1", "owner": "robot", "position": [3.0, 3.0]}],
    }


@pytest.fixture()
def server(tmp_path: Path) -> Iterator[EditorServer]:
    s = EditorServer("127.0.0.1", 0, room_world(), tmp_path / "out")
    s.start()
    yield s
    s.stop()


def post(
    server: EditorServer, action: str, body: bytes, token: bool = True, kind: str = "application/json"
) -> tuple[int, dict[str, Any]]:
    base = server.url.split("/edit?")[0]
    url = f"{base}/edit/{action}" + (f"{'&' if '?' in action else '?'}token={server.token}" if token else "")
    request = urllib.request.Request(url, data=body, headers={"Content-Type": kind}, method="POST")
    try:
        with urllib.request.urlopen(request, timeout=30) as r:
            return r.status, json.loads(r.read())
    except urllib.error.HTTPError as e:
        return e.code, json.loads(e.read() or b"{}")


def test_without_the_token_nothing_is_served_or_checked(server: EditorServer) -> None:
    with pytest.raises(urllib.error.HTTPError) as refused:
        urllib.request.urlopen(server.url.replace("token=", "token=x"), timeout=30)
    assert refused.value.code == 403
    with urllib.request.urlopen(server.url, timeout=30) as page:
        html = page.read().decode()
        assert '"name": "lab"' in html and "/static/editor.js" in html and "HttpOnly" in page.headers["Set-Cookie"]
    assert post(server, "check", json.dumps(room_world()).encode(), token=False)[0] == 403
    assert post(server, "save", json.dumps({"world": room_world(), "task": "none"}).encode(), token=False)[0] == 403
    assert not (server.out / "lab.yaml").exists()


def test_a_world_larger_than_a_world_file_may_be_is_refused_unread(server: EditorServer) -> None:
    port = server.server.port
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=30)
    conn.putrequest("POST", f"/edit/check?token={server.token}")
    conn.putheader("Content-Length", str(MAX_WORLD_BYTES + 1))  # (the body is never sent: the answer comes first)
    conn.endheaders()
    response = conn.getresponse()
    assert response.status == 400
    assert (
        json.loads(response.read())["error"] == f"the world of {MAX_WORLD_BYTES + 1} bytes (at most {MAX_WORLD_BYTES})"
    )
    conn.close()
    assert post(server, "check", b"{not json")[1]["error"] == "the page sent something that is not JSON"


def test_check_answers_with_the_loaders_own_line_and_the_key_it_names(server: EditorServer) -> None:
    assert post(server, "check", json.dumps(room_world()).encode()) == (
        200,
        {
            "ok": True,
            "summary": "world lab: 4 wall(s), 0 obstacle(s), 2 room(s), 0 hallway(s), 1 gem(s), 1 person start(s)",
        },
    )
    world = room_world()
    world["humans"][0]["start"] = [6.0, 2.0, 0.0]  # on the east wall
    code, answer = post(server, "check", json.dumps(world).encode())
    assert code == 200 and answer["ok"] is False and answer["key"] == "humans[0].start"
    assert answer["error"] == f"{server.out / 'lab.yaml'}: humans[0].start: (6, 2) lies inside a wall"
    code, answer = post(server, "check", json.dumps({**room_world(), "name": "my lab"}).encode())
    assert (
        answer["ok"] is False
        and answer["key"] == "name"
        and answer["error"].startswith("name: the world's name names its file")
    )


def test_save_writes_a_world_and_a_scenario_that_load_and_replaces_only_when_told(server: EditorServer) -> None:
    code, answer = post(server, "save", json.dumps({"world": room_world(), "task": "visit_rooms"}).encode())
    world_path, scenario_path = server.out / "lab.yaml", server.out / "lab_scenario.yaml"
    assert code == 200 and answer["saved"] == [str(world_path), str(scenario_path)]
    assert load_world(world_path).name == "lab"
    scenario = load_scenario(scenario_path)
    assert (
        scenario.kind == "hallway"
        and scenario.robot_route == ("east", "west")
        and scenario.humans[0].route == ("west", "east")
    )

    moved = room_world()
    moved["rooms"][0]["centre"] = [1.5, 2.0]
    code, answer = post(server, "save", json.dumps({"world": moved, "task": "visit_rooms"}).encode())
    assert code == 409 and answer["exists"] == [str(world_path), str(scenario_path)]
    assert load_world(world_path).rooms[0].centre == (1.0, 2.0)  # not replaced
    assert (
        post(server, "save", json.dumps({"world": moved, "task": "visit_rooms", "overwrite": True}).encode())[0] == 200
    )
    assert load_world(world_path).rooms[0].centre == (1.5, 2.0)


def test_save_refuses_an_invalid_world_with_the_loaders_line_and_writes_nothing(server: EditorServer) -> None:
    world = room_world()
    world["walls"][1]["thickness"] = 0
    code, answer = post(server, "save", json.dumps({"world": world, "task": "visit_rooms"}).encode())
    assert code == 400 and answer["error"] == f"{server.out / 'lab.yaml'}: walls[1].thickness: must be positive, got 0"
    world = room_world()
    world["name"] = "my lab/../x"
    assert (
        "name: the world's name names its file"
        in post(server, "save", json.dumps({"world": world, "task": "none"}).encode())[1]["error"]
    )
    world = room_world()
    world["rooms"] = world["rooms"][:1]
    assert post(server, "save", json.dumps({"world": world, "task": "visit_rooms"}).encode())[1]["error"] == (
        "task visit_rooms: needs at least 2 rooms in the world, it has 1"
    )
    assert not server.out.exists()


def test_a_map_images_dark_cells_become_wall_polygons(server: EditorServer) -> None:
    pixels = np.full((40, 60), 255, dtype=np.uint8)  # 3 x 2 m at 0.05 m per pixel, white = free
    pixels[:, :2] = 0  # a dark column on the left: one wall box 0.1 m wide
    data = io.BytesIO()
    Image.fromarray(pixels).save(data, format="PNG")
    code, answer = post(server, "walls?resolution=0.05&x=1&y=2", data.getvalue(), kind="image/png")
    assert code == 200 and len(answer["walls"]) == 1
    xs, ys = zip(*answer["walls"][0], strict=True)
    assert (min(xs), max(xs), min(ys), max(ys)) == pytest.approx((1.0, 1.1, 2.0, 4.0))
    code, answer = post(server, "walls?resolution=0", data.getvalue(), kind="image/png")
    assert code == 400 and "resolution" in answer["error"]
    assert (
        post(server, "walls", b"GIF89a", kind="image/gif")[1]["error"]
        == "the image must be a PNG, a JPEG or a PGM (a ROS map's image)"
    )
    # map_saver's own PGM (told by its first bytes, whatever type the browser gives it): the same walls,
    # and as a PNG the page can draw under the plan
    pgm = io.BytesIO()
    Image.fromarray(pixels).save(pgm, format="PPM")  # (Pillow writes a grey image as a binary PGM, "P5")
    assert pgm.getvalue().startswith(b"P5")
    code, answer = post(server, "walls?resolution=0.05&x=1&y=2", pgm.getvalue(), kind="application/octet-stream")
    assert code == 200 and len(answer["walls"]) == 1
    request = urllib.request.Request(server.url.replace("/edit?", "/edit/image?"), data=pgm.getvalue(), method="POST")
    with urllib.request.urlopen(request, timeout=30) as r:
        assert r.headers["Content-Type"] == "image/png"
        assert np.array_equal(np.asarray(Image.open(io.BytesIO(r.read()))), pixels)


def png_header_only(width: int, height: int) -> bytes:
    """A PNG that says it is `width` x `height` grey pixels, with one compressed row of data: what a
    decompression bomb shows before it is decoded (the size is judged from this header)."""

    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    ihdr = struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0)
    return (
        b"\x89PNG\r\n\x1a\n"
        + chunk(b"IHDR", ihdr)
        + chunk(b"IDAT", zlib.compress(bytes(width + 1)))
        + chunk(b"IEND", b"")
    )


@pytest.mark.parametrize("side", [12_000, 20_000])  # 144 megapixels (PIL warns), 400 (PIL refuses)
def test_an_image_too_large_to_be_a_map_is_refused_with_400_before_it_is_decoded(
    server: EditorServer, side: int
) -> None:
    bomb = png_header_only(side, side)
    for action in ("image", "walls?resolution=0.05"):
        code, answer = post(server, action, bomb, kind="image/png")
        assert code == 400 and "\n" not in answer["error"], answer
        assert answer["error"].startswith("the image") and f"at most {MAX_CELLS:,}" in answer["error"], answer
    assert post(server, "check", json.dumps(room_world()).encode())[1]["ok"] is True  # (and the server still answers)


def test_an_image_too_fragmented_for_walls_is_refused_with_400_in_one_line(server: EditorServer) -> None:
    rows, cols = np.indices((200, 200))
    data = io.BytesIO()
    # 20,000 one-pixel walls
    Image.fromarray(np.where((rows + cols) % 2 == 0, 0, 255).astype(np.uint8)).save(data, format="PNG")
    code, answer = post(server, "walls?resolution=0.05", data.getvalue(), kind="image/png")
    assert (
        code == 400
        and answer["error"].startswith("the image: ")
        and f"more than {MAX_WALL_BOXES:,} wall boxes" in answer["error"]
    ), answer


def test_the_template_makes_scenarios_that_load(tmp_path: Path) -> None:
    (tmp_path / "lab.yaml").write_text(yaml.safe_dump(room_world()))
    hallway = parse_scenario(scenario_template("s", "lab.yaml", room_world(), "visit_rooms"), str(tmp_path / "s.yaml"))
    assert hallway.robot_route == ("east", "west") and [h.model for h in hallway.humans] == ["walker"]
    gems = parse_scenario(scenario_template("s", "lab.yaml", room_world(), "collect_gems"), str(tmp_path / "s.yaml"))
    assert gems.kind == "retrieval" and gems.robot_order == "nearest"
    with pytest.raises(TemplateError, match="collect_gems: needs at least one gem for the robot"):
        scenario_template("s", "lab.yaml", {**room_world(), "gems": []}, "collect_gems")
    with pytest.raises(TemplateError, match="task: must be one of visit_rooms, collect_gems"):
        scenario_template("s", "lab.yaml", room_world(), "dance")


def test_haven_edit_starts_from_a_shipped_world_or_a_new_one_but_not_from_a_map(tmp_path: Path) -> None:
    assert world_tree("hallway")["name"] == "hallway"
    assert world_tree(None)["walls"] == []
    (tmp_path / "m.yaml").write_text("name: m\nmap: building.yaml\nrobot: {start: [1, 1]}\n")
    with pytest.raises(WorldError, match=r"m\.yaml: map: the editor draws walls itself"):
        world_tree(str(tmp_path / "m.yaml"))


def test_haven_edit_refuses_a_world_it_cannot_read_in_one_line(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    from haven_scenarios.tools.cli import main

    assert main(["edit", str(tmp_path / "nosuch.yaml")]) == 2
    err = capsys.readouterr().err
    assert err == f"haven: error: {tmp_path / 'nosuch.yaml'}: cannot read world file: No such file or directory\n"
