"""The world editor's server (`haven edit`): the page, the real loader's verdict on what is drawn,
walls from a map image, and saving a world with a scenario from a template.

No ROS: a page server (web/serving.py), as the instruments page has (web/instrument_server.py).
`/edit` is the page (editor.html, the world being edited embedded as JSON), `/static/editor.js` its
bundle. The page POSTs, each with the token (in the printed address, then the cookie the page sets)
and size-capped:
- `/edit/check`: a world as its YAML tree in JSON; the answer is the loader's own verdict
  (`parse_world`): `{"ok": true, "summary": ...}` or `{"ok": false, "error": line, "key": key}`;
- `/edit/walls?resolution=R&x=X&y=Y&negate=0|1`: a PNG, JPEG or PGM (map_saver's own format; told
  apart by their first bytes); its dark cells as wall boxes (`map_image.read_image` and
  `wall_boxes`, as a world's `map:` is read), `{"walls": [polygon, ...]}`;
- `/edit/image`: such an image as a PNG, for a background the browser cannot decode itself (a PGM);
- `/edit/save`: `{"world": tree, "task": visit_rooms|collect_gems|none, "overwrite": bool}`; writes
  OUT/<name>.yaml and OUT/<name>_scenario.yaml (study/scenario_template.py), each written whole
  (common/atomic.py) and only after both load in a scratch folder; an existing file is replaced
  only when the page says so (`overwrite`, after asking), else the answer is `{"exists": [...]}`.
"""

from __future__ import annotations

import io
import json
import re
import ssl
import tempfile
import threading
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import yaml
from aiohttp import web

from haven_scenarios.study.scenario import ScenarioError, parse_scenario
from haven_scenarios.study.scenario_template import TASKS, TemplateError, scenario_template
from haven_scenarios.web.access import TOKEN_COOKIE, TOKEN_PARAM, new_token, role_token, token_of, token_ok
from haven_scenarios.web.front_door import STATIC, address_for_others
from haven_scenarios.web.serving import HTML, PageServer, Routes, read_body, reply, reply_json, set_token_cookie
from haven_sim.common import atomic
from haven_sim.common.yaml_file import MAX_FILE_BYTES, YamlFileError, file_label, one_line
from haven_sim.sim.map_image import open_image, read_image, wall_boxes
from haven_sim.sim.world import WorldError, summary
from haven_sim.sim.world_file import parse_world

PAGE = ROLE = "edit"
SERVED = ("editor.js", "haven.css")
MAX_WORLD_BYTES = MAX_FILE_BYTES  # a world the page sends is held to what a world file may be (1 MiB)
MAX_IMAGE_BYTES = 16 << 20  # a map image upload (a 4000 x 4000 grey PNG, map_image.MAX_CELLS, is well under)
IMAGE_MAGIC = {b"\x89PNG": ".png", b"\xff\xd8": ".jpg", b"P5": ".pgm", b"P2": ".pgm"}  # (the formats' signatures)
NO_TASK = "none"
_FILE_NAME = re.compile(r"^[A-Za-z0-9][A-Za-z0-9_-]{0,63}$")


class EditorServer:
    """Serves the editor for one world tree until stopped; saves into `out`."""

    def __init__(
        self, host: str, port: int, world: Mapping[str, Any], out: Path, tls: ssl.SSLContext | None = None
    ) -> None:
        self.world, self.out = dict(world), out
        self.token = role_token(new_token(), ROLE)
        self._lock = threading.Lock()
        routes = Routes(get={"/{path:.*}": self.get}, post={"/{path:.*}": self.post})
        self.server = PageServer("the editor", host, port, routes, tls)
        self.host = host

    @property
    def url(self) -> str:
        where = f"{self.server.scheme}://{address_for_others(self.host)}:{self.server.port}"
        return f"{where}/{PAGE}?{TOKEN_PARAM}={self.token}"

    def start(self) -> None:
        self.server.start()

    def stop(self) -> None:
        self.server.stop()

    def _allowed(self, request: web.BaseRequest) -> bool:
        return token_ok(token_of(request.query, request.cookies, ROLE), self.token)

    def get(self, request: web.Request) -> web.Response:
        parts = [p for p in request.path.split("/") if p]
        if parts == ["favicon.ico"]:
            return reply(request, 204, b"")
        if not self._allowed(request):
            return reply(request, 403, b"this page needs its token: open the address `haven edit` printed")
        if parts == [PAGE]:
            config = {"world": self.world, "tasks": list(TASKS), "out": str(self.out)}
            text = json.dumps(config).replace("<", "\\u003c")
            page = (STATIC / "editor.html").read_text().replace("{{CONFIG}}", text).encode()
            return set_token_cookie(reply(request, 200, page, HTML), request, TOKEN_COOKIE + ROLE, self.token)
        if len(parts) == 2 and parts[0] == "static" and parts[1] in SERVED:
            kind = "text/javascript" if parts[1].endswith(".js") else "text/css"
            return reply(request, 200, (STATIC / parts[1]).read_bytes(), kind)
        return reply(request, 404, b"no such page")

    def post(self, request: web.Request) -> web.Response:
        parts = [p for p in request.path.split("/") if p]
        actions = {"check": self.check, "save": self.save}
        if len(parts) != 2 or parts[0] != PAGE or parts[1] not in (*actions, "walls", "image"):
            return reply(request, 404, b"no such page")
        if not self._allowed(request):
            return reply_json(request, 403, {"error": "not the editor's page: open the address `haven edit` printed"})
        try:
            if parts[1] == "walls":
                image = read_body(request, MAX_IMAGE_BYTES, "the image")
                return reply_json(request, 200, image_walls(image, request.query))
            if parts[1] == "image":
                return reply(request, 200, as_png(read_body(request, MAX_IMAGE_BYTES, "the image")), "image/png")
            sent = read_body(request, MAX_WORLD_BYTES, "the world")
            try:
                message = json.loads(sent)
            except (json.JSONDecodeError, UnicodeDecodeError, RecursionError):
                raise ValueError("the page sent something that is not JSON") from None
            with self._lock:
                code, answer = actions[parts[1]](message)
        except ValueError as e:
            return reply_json(request, 400, {"ok": False, "error": str(e)})
        except OSError as e:  # (a full disk, a folder that cannot be written: the page can save again)
            return reply_json(request, 500, {"ok": False, "error": f"cannot write {e.filename}: {e.strerror or e}"})
        return reply_json(request, code, answer)

    def target(self, world: Any) -> Path:
        name = world.get("name") if isinstance(world, dict) else None
        if not isinstance(name, str) or not _FILE_NAME.match(name):
            raise ValueError(
                "name: the world's name names its file: letters, digits, "
                "'_' and '-' (up to 64), starting with a letter or digit"
            )
        return self.out / f"{name}.yaml"

    def check(self, world: Any) -> tuple[int, dict[str, Any]]:
        """The loader's verdict on a world tree (as if it were the file it would be saved as), and
        whether its name can name that file."""
        try:
            return 200, verdict(world, str(self.target(world)))
        except ValueError as e:
            answer = verdict(world, "world.yaml")
            return 200, answer if not answer["ok"] else {"ok": False, "error": str(e), "key": "name"}

    def save(self, message: Any) -> tuple[int, dict[str, Any]]:
        if not isinstance(message, dict) or not isinstance(message.get("world"), dict):
            raise ValueError("the page must send {world, task}")
        world, task = message["world"], message.get("task", NO_TASK)
        world_path = self.target(world)
        answer = verdict(world, str(world_path))
        if not answer["ok"]:
            return 400, answer
        files = {world_path: dump(world)}
        if task != NO_TASK:
            scenario_path = self.out / f"{world['name']}_scenario.yaml"
            try:
                scenario = scenario_template(f"{world['name']}_scenario", world_path.name, world, task)
            except TemplateError as e:
                return 400, {"ok": False, "error": str(e)}
            files[scenario_path] = dump(scenario)
            problem = _scenario_problem(world_path.name, files[world_path], scenario_path.name, files[scenario_path])
            if problem:
                return 400, {"ok": False, "error": problem}
        existing = [str(p) for p in files if p.exists()]
        if existing and message.get("overwrite") is not True:
            return 409, {
                "ok": False,
                "exists": existing,
                "error": f"{', '.join(existing)} exist(s): save again to replace",
            }
        self.out.mkdir(parents=True, exist_ok=True)
        for path, text in files.items():
            atomic.write_text(path, text)
        self.world = dict(world)
        return 200, {"ok": True, "saved": [str(p) for p in files], "summary": answer["summary"]}


def verdict(world: Any, source: str) -> dict[str, Any]:
    """`parse_world`'s answer: ok with a summary, or its one line and the key it names."""
    try:
        loaded = parse_world(world, source)
    except (WorldError, YamlFileError) as e:
        line = str(e)
        rest = line.removeprefix(f"{file_label(source)}: ")
        return {"ok": False, "error": line, "key": rest.split(": ", 1)[0] if ": " in rest else ""}
    return {"ok": True, "summary": f"world {loaded.name}: {summary(loaded)}"}


def dump(tree: Any) -> str:
    return yaml.safe_dump(tree, sort_keys=False, default_flow_style=None, allow_unicode=True)


def _scenario_problem(world_name: str, world_text: str, scenario_name: str, scenario_text: str) -> str:
    """The scenario loader's line on the pair written to a scratch folder ('' when it loads)."""
    with tempfile.TemporaryDirectory(prefix="haven_edit_") as scratch:
        Path(scratch, world_name).write_text(world_text)
        try:
            parse_scenario(yaml.safe_load(scenario_text), str(Path(scratch, scenario_name)))
        except ScenarioError as e:
            return str(e).replace(f"{scratch}/", "")
    return ""


def image_suffix(image: bytes) -> str:
    """The file suffix of a PNG, JPEG or PGM by its first bytes; ValueError for anything else."""
    for magic, suffix in IMAGE_MAGIC.items():
        if image.startswith(magic):
            return suffix
    raise ValueError("the image must be a PNG, a JPEG or a PGM (a ROS map's image)")


def as_png(image: bytes) -> bytes:
    """The image (PNG, JPEG or PGM) as a PNG the page can draw; held to what a world's map image
    may be (`map_image.open_image`: its size read from its header before it is decoded)."""
    image_suffix(image)
    out = io.BytesIO()
    try:
        with open_image(io.BytesIO(image), "the image", "") as picture:
            picture.save(out, "PNG")
    except WorldError as e:
        raise ValueError(str(e)) from None
    except (OSError, ValueError) as e:
        raise ValueError(f"the image: cannot be read as an image: {one_line(str(e))}") from None
    return out.getvalue()


def image_walls(image: bytes, query: Mapping[str, str]) -> dict[str, Any]:
    """A map image's occupied and unknown cells as wall polygons, read as a world's `map:` is."""
    suffix = image_suffix(image)

    def number(key: str, default: str) -> float:
        text = query.get(key, default)
        try:
            return float(text)
        except ValueError:
            raise ValueError(f"{key}: must be a number, got {text[:20]!r}") from None

    with tempfile.NamedTemporaryFile(prefix="haven_edit_", suffix=suffix) as f:
        f.write(image)
        f.flush()
        try:
            grid = read_image(
                f.name,
                number("resolution", "0.05"),
                (number("x", "0"), number("y", "0")),
                negate=query.get("negate", "0") == "1",
            )
            boxes = wall_boxes(grid)
        except WorldError as e:
            raise ValueError(str(e).replace(f.name, "the image")) from None
    return {"walls": [[[round(x, 4), round(y, 4)] for x, y in box] for box in boxes]}
